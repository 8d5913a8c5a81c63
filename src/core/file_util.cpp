#include "ramus/file_util.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "ramus/error.hpp"

namespace ramus {

std::string readFile(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
        throw Error(path + ": cannot read file: it is a directory");
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path + ": cannot read file: " + std::strerror(errno));
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if (in.bad()) throw Error(path + ": cannot read file: read error");
    return std::move(buffer).str();
}

void writeFileAtomic(const std::string& path, std::string_view bytes) {
    writeFileAtomic(path, std::span<const std::string_view>(&bytes, 1));
}

void writeFileAtomic(const std::string& path, std::span<const std::string_view> parts) {
    // The temp name only needs to be unique, not reproducible, so a non-deterministic source is
    // fine here (it never influences the file's contents).
    std::random_device device;
    char suffix[32];
    std::snprintf(suffix, sizeof suffix, ".tmp-%08x", device());
    const std::string tempPath = path + suffix;

    std::FILE* file = std::fopen(tempPath.c_str(), "wb");
    if (!file) throw Error(path + ": cannot write file: " + std::strerror(errno));
    bool ok = true;
    for (const std::string_view bytes : parts) {
        ok = ok && std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
    }
    ok = (std::fflush(file) == 0) && ok;
    ok = (std::fclose(file) == 0) && ok;
    if (!ok) {
        const int err = errno;
        std::remove(tempPath.c_str());
        throw Error(path + ": cannot write file: " + std::strerror(err));
    }
    std::error_code ec;
    std::filesystem::rename(tempPath, path, ec);
    if (ec) {
        std::remove(tempPath.c_str());
        throw Error(path + ": cannot write file: " + ec.message());
    }
}

}  // namespace ramus
