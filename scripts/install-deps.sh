#!/usr/bin/env bash
# Installs what ramus needs on a fresh Debian machine: Debian -dev packages (apt-get) and the
# npm packages of the test tools. Idempotent: does nothing when everything is present.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(build-essential cmake ninja-build pkg-config clang clang-format
          libeigen3-dev nlohmann-json3-dev libcli11-dev libcpp-httplib-dev libnanoflann-dev
          libstb-dev libtinygltf-dev libgtest-dev libgmock-dev libbenchmark-dev libjemalloc-dev libfmt-dev libcgal-dev
          chromium blender python3-numpy)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# Node.js may come from another source (e.g. NodeSource, which bundles npm): only the commands
# matter, so Debian's packages are installed only when they are missing.
command -v node >/dev/null 2>&1 || missing+=(nodejs)
command -v npm >/dev/null 2>&1 || missing+=(npm)
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# npm tools (lock files committed; `npm ci` installs exactly what they list)
for dir in tests/validator tests/studio web; do
  if [ -f "$dir/package-lock.json" ] && [ ! -d "$dir/node_modules" ]; then
    (cd "$dir" && npm ci --no-audit --no-fund --loglevel=error)
  fi
done
