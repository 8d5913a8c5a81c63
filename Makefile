# ramus — the two commands of the README (`make run`, `make test`) and the developer targets.
# Every target installs what it needs first (`make deps`), so a fresh Debian machine works.
JOBS      ?= $(shell nproc)
BUILD     ?= build/release
CHECK     ?= build/check
OUT       ?= out
CMAKE_GEN := -G Ninja
RAMUS     := $(BUILD)/ramus

.PHONY: all deps build run showcase serve test check-tests studio-e2e validate three-load blender-import format \
        format-check bench bench-peers fuzz fuzz-build fuzz-build-only fuzz-smoke fuzz-union \
        checks-and-fuzz-build fuzz-build-after-tests batch-check union-check random-union-check weld-rates \
        check-floats clean

all: build

deps:
	@scripts/install-deps.sh

build: deps
	@cmake -S . -B $(BUILD) $(CMAKE_GEN) -DCMAKE_BUILD_TYPE=Release >/dev/null
	@cmake --build $(BUILD) -j $(JOBS)

# Main job: build and generate the showcase into out/.
run: deps
	@cmake -S . -B $(BUILD) $(CMAKE_GEN) -DCMAKE_BUILD_TYPE=Release >/dev/null
	@cmake --build $(BUILD) -j $(JOBS) --target ramus
	@scripts/showcase.sh $(RAMUS) $(OUT)
	@echo "studio: run 'make serve' and open http://127.0.0.1:$(PORT)/"

showcase: run

# The studio (docs/studio.md): a local web page to generate, tweak and download.
PORT ?= 8080
serve: deps
	@cmake -S . -B $(BUILD) $(CMAKE_GEN) -DCMAKE_BUILD_TYPE=Release >/dev/null
	@cmake --build $(BUILD) -j $(JOBS) --target ramus
	$(RAMUS) serve --port $(PORT)

# Everything CI checks: formatting; every unit and end-to-end test in one ASan+UBSan build with
# internal assertions on; the Khronos glTF validator over every GLB those tests wrote, the
# same GLBs loaded and rendered by three.js and imported into Blender; a short run of each fuzzer; the studio page end to
# end in headless Chromium. (Benchmarks measure speed separately: `make bench`.)
test: deps format-check
	@$(MAKE) --no-print-directory -j 2 checks-and-fuzz-build
	@FUZZ_JOBS=$(JOBS) scripts/fuzz.sh $(FUZZ) $(FUZZ_SMOKE_SECS)
	@echo "make test: all checks passed"
	@node scripts/gtest-summary.mjs $(CHECK)/gtest-*.json

# After the sanitized build and its tests (both cores busy), the browser and Blender checks,
# which use about one core, run beside the fuzzers' build (a second, clang build of the
# libraries; its log is shown only when it fails). Started at the lowest priority from the
# beginning instead, the fuzz build got almost no time until the browser checks and slowed the
# tests (measured 2026-12-05, docs/BENCHMARKS.md).
FUZZ_BUILD_LOG := build/fuzz-build.log
checks-and-fuzz-build: studio-e2e validate three-load blender-import fuzz-build-after-tests
fuzz-build-after-tests: check-tests
	@mkdir -p build; $(MAKE) --no-print-directory fuzz-build-only >$(FUZZ_BUILD_LOG) 2>&1 || \
	  { cat $(FUZZ_BUILD_LOG); echo "make test: the fuzz build failed"; exit 1; }

# The heavy tests (tests/heavy-tests.txt) one per process, longest first, then the rest in twice
# as many shards as cores, all taken from one queue, keep both cores busy to the end
# (scripts/test-shards.sh); more shards would rebuild per-process caches (the default bone
# library, 13 s under ASan) once per shard for little gain.
TEST_SHARDS ?= $(shell echo $$(( $(JOBS) * 2 )))
CHECK_FLAGS := -DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_FLAGS="-O1 -g1" -DRAMUS_SANITIZE=ON \
               -DRAMUS_ENABLE_ASSERTS=ON -DRAMUS_BUILD_BENCH=OFF -DRAMUS_UNITY_BUILD=ON
check-tests: deps
	@cmake -S . -B $(CHECK) $(CMAKE_GEN) $(CHECK_FLAGS) >/dev/null
	@cmake --build $(CHECK) -j $(JOBS) --target ramus ramus_tests
	@rm -rf $(CHECK)/test-output $(CHECK)/gtest-*.json $(CHECK)/gtest-*.log && mkdir -p $(CHECK)/test-output
	@echo "ramus_tests: the heavy tests one by one, then $(TEST_SHARDS) shards, $(JOBS) at a time"
	@cd $(CHECK) && RAMUS_TEST_OUTPUT=$(CURDIR)/$(CHECK)/test-output RAMUS_BIN=$(CURDIR)/$(CHECK)/ramus \
	  $(CURDIR)/scripts/test-shards.sh ./ramus_tests . $(JOBS) $(TEST_SHARDS) $(CURDIR)/tests/heavy-tests.txt

studio-e2e: check-tests
	@node tests/studio/e2e.mjs $(CHECK)/ramus $(CHECK)/test-output

validate: check-tests studio-e2e
	@node tests/validator/validate.mjs $(CHECK)/test-output

# Issue 9: every GLB of the tests through three.js's GLTFLoader (the studio's three.js) in
# headless Chromium: parsed without warnings, skins, wind attributes, LODs, a non-blank render.
three-load: check-tests studio-e2e
	@node tests/studio/three-load.mjs $(CHECK)/test-output

# Every GLB of the test run imported into Debian's Blender with its glTF importer: objects,
# triangles, armature and bones, and posing a skeleton's bone moves its mesh alone.
blender-import: check-tests studio-e2e
	@blender -b --factory-startup --python tests/blender/import_check.py -- \
	  $(CHECK)/test-output/*.glb 2>&1 | grep -E '^(ok|FAIL|blender import|Traceback|Error)' \
	  | tee $(CHECK)/blender-import.log | grep -v '^ok'; \
	  grep -q '^blender import: .* 0 failures' $(CHECK)/blender-import.log

# Issue 8's scale check: 10 000 box skeletons and 1 000 small trees with `ramus batch --jobs 2`
# (Release build; make test runs small batches).
batch-check: build
	cd $(BUILD) && RAMUS_LARGE_TESTS=1 RAMUS_BIN=$(CURDIR)/$(RAMUS) ./ramus_tests_cli \
	  --gtest_filter='BatchCli.TenThousand*'

# Issue 9's union check on every shipped L-system and colonization tree (one clean 2-manifold
# each; Release build, a few minutes; make test runs ABOP 1.27 and two thin trees).
union-check: build
	cd $(BUILD) && RAMUS_LARGE_TESTS=1 ./ramus_tests_mesh \
	  --gtest_filter='SolidUnion.EveryExampleIsOneCleanSurface:SolidUnion.ShrunkJunctionsThatDoNotUniteCleanlyUniteAsHulls:SolidUnion.MovesAreTriedInOrderUntilOneIsClean:SolidUnion.MicroEdgeCollapsesMendWhatTheMovesCannot'

# The union on 400 random L-system plants (scripts/random-unions.py: each must end within 60 s as
# one clean surface, or be refused at once by the union's work limit, as seed 332 is; Release
# build, about a minute; docs/welded.md, Performance, "Session 44").
random-union-check: build
	python3 scripts/random-unions.py --ramus $(RAMUS) --from 1 --to 400 --timeout 60

# One-shot `ramus --weld` rate of every shipped example, best of 8 (scripts/mesh-rates.py; Release
# build, about a minute; issue 9 asks for 1 M welded triangles/s; docs/BENCHMARKS.md, session 46).
weld-rates: build
	python3 scripts/mesh-rates.py --ramus $(RAMUS) --mode=--weld --runs 8 --min-rate 1

FORMAT_FILES = $(shell git ls-files '*.cpp' '*.hpp')
format: deps
	@clang-format -i $(FORMAT_FILES)

format-check: deps
	@clang-format --dry-run --Werror $(FORMAT_FILES) && echo "clang-format: ok"

bench: build
	$(BUILD)/ramus_bench --benchmark_counters_tabular=true

# Every one of the 2^32 floats through the GLB's float text (apps/float_text_exhaustive): reads
# back exactly, at most 15 characters, the shortest digits. Minutes on all cores.
check-floats: deps
	@cmake -S . -B $(BUILD) $(CMAKE_GEN) -DCMAKE_BUILD_TYPE=Release >/dev/null
	@cmake --build $(BUILD) -j $(JOBS) --target float_text_exhaustive
	@$(BUILD)/float_text_exhaustive

bench-peers: build
	@cd bench/peers && npm ci --no-audit --no-fund --loglevel=error
	@bench/peers/run.sh $(BUILD)

# The fuzzers of make test reach no solid union, so their build leaves CGAL out
# (-DRAMUS_WITH_CGAL=OFF): a minute less to compile, and CI compiles that configuration too. The
# union's fuzzer (fuzz/fuzz_union.cpp) has its own build with CGAL: `make fuzz-union`, not in
# make test (0.1–2 s an input under ASan, up to 15 s where the exact predicates work hardest:
# an input is a finding after 60 s; docs/FUZZING.md).
FUZZ      ?= build/fuzz
FUZZ_SECS ?= 600
# The smoke run replays every seed corpus (a few files a target) and fuzzes on for the rest.
FUZZ_SMOKE_SECS ?= 10
fuzz-build: deps fuzz-build-only

# The fuzz build without `deps` (make test runs it beside the other checks, after `deps`).
fuzz-build-only:
	@CXX=clang++ cmake -S . -B $(FUZZ) $(CMAKE_GEN) -DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_FLAGS="-O1 -g1" \
	  -DRAMUS_BUILD_FUZZ=ON -DRAMUS_BUILD_TESTS=OFF -DRAMUS_BUILD_BENCH=OFF -DRAMUS_UNITY_BUILD=ON \
	  -DRAMUS_WITH_CGAL=OFF >/dev/null
	@cmake --build $(FUZZ) -j $(JOBS) --target fuzzers

fuzz: fuzz-build
	@FUZZ_JOBS=$(JOBS) scripts/fuzz.sh $(FUZZ) $(FUZZ_SECS)

fuzz-smoke: fuzz-build
	@FUZZ_JOBS=$(JOBS) scripts/fuzz.sh $(FUZZ) $(FUZZ_SMOKE_SECS)

FUZZ_UNION ?= build/fuzz-union
fuzz-union: deps
	@CXX=clang++ cmake -S . -B $(FUZZ_UNION) $(CMAKE_GEN) -DCMAKE_BUILD_TYPE=None \
	  -DCMAKE_CXX_FLAGS="-O1 -g1" -DRAMUS_BUILD_FUZZ=ON -DRAMUS_BUILD_TESTS=OFF \
	  -DRAMUS_BUILD_BENCH=OFF -DRAMUS_UNITY_BUILD=ON -DRAMUS_WITH_CGAL=ON >/dev/null
	@cmake --build $(FUZZ_UNION) -j $(JOBS) --target fuzz_union
	@FUZZ_TIMEOUT=60 scripts/fuzz.sh $(FUZZ_UNION) $(FUZZ_SECS) union

clean:
	rm -rf build $(OUT)
