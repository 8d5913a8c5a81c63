#include "ramus/file_util.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <vector>

#include "ramus/error.hpp"

namespace ramus {

std::string readFile(const std::string& path, std::size_t maxBytes) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
        throw Error(path + ": cannot read file: it is a directory");
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path + ": cannot read file: " + std::strerror(errno));
    // Read in chunks rather than by the file's size: pipes and special files have none, and a
    // file may grow while it is read; the limit is checked on what actually arrives.
    std::string bytes;
    std::vector<char> chunk(std::size_t{1} << 20);
    while (in) {
        in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
        const auto got = static_cast<std::size_t>(in.gcount());
        if (bytes.size() + got > maxBytes) {
            throw Error(path + ": the file is larger than the input limit of " +
                        std::to_string(maxBytes) +
                        " bytes; expected a smaller file (ramus colonize raises the limit for "
                        "configs, point and mesh files with --max-file-size MIB)");
        }
        bytes.append(chunk.data(), got);
    }
    if (in.bad()) throw Error(path + ": cannot read file: read error");
    return bytes;
}

void writeFileAtomic(const std::string& path, std::string_view bytes) {
    // The temp name only needs to be unique, not reproducible, so a non-deterministic source is
    // fine here (it never influences the file's contents).
    std::random_device device;
    char suffix[32];
    std::snprintf(suffix, sizeof suffix, ".tmp-%08x", device());
    const std::string tempPath = path + suffix;

    std::FILE* file = std::fopen(tempPath.c_str(), "wb");
    if (!file) throw Error(path + ": cannot write file: " + std::strerror(errno));
    bool ok = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
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
