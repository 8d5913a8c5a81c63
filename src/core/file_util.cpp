#include "ramus/file_util.hpp"

#include <fcntl.h>
#include <sys/uio.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

#include "ramus/error.hpp"

namespace ramus {

std::string lowerExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

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
    writeFileAtomic(path, std::span<const std::string_view>(&bytes, 1));
}

namespace {

// A temp name suffix ".tmp-xxxxxxxx". It only needs to be unique, not reproducible (it never
// influences a file's contents): the clock, the process and the thread mixed by SplitMix64's
// finalizer; O_EXCL below settles the rare collision by trying the next attempt. (A
// std::random_device per file cost more than writing a small file.)
std::string tempSuffix(unsigned attempt) {
    std::uint64_t x =
        static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count()) ^
        (static_cast<std::uint64_t>(::getpid()) << 32) ^
        std::hash<std::thread::id>{}(std::this_thread::get_id()) ^ (std::uint64_t{attempt} << 56);
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    x ^= x >> 31;
    std::string suffix = ".tmp-00000000";  // 8 hex digits of x (snprintf cost more here)
    for (int i = 0; i < 8; ++i) suffix[5 + i] = "0123456789abcdef"[(x >> (28 - 4 * i)) & 15];
    return suffix;
}

// Writes all of `parts` to `fd` in order with writev(2), IOV_MAX pieces at a time (a GLB is a
// dozen pieces: one system call instead of joining them in memory or writing each); writev may
// write less than asked, or be interrupted.
bool writeAll(int fd, std::span<const std::string_view> parts) {
    constexpr std::size_t kBatch = 64;  // ≤ IOV_MAX (1024 on Linux)
    std::array<iovec, kBatch> iov;
    std::size_t next = 0, skip = 0;  // the first part not fully written, and its written bytes
    while (next < parts.size()) {
        std::size_t count = 0;
        for (std::size_t i = next; i < parts.size() && count < kBatch; ++i) {
            const std::string_view part = i == next ? parts[i].substr(skip) : parts[i];
            if (part.empty()) continue;
            iov[count++] = {const_cast<char*>(part.data()), part.size()};
        }
        if (count == 0) return true;
        const ssize_t written = ::writev(fd, iov.data(), static_cast<int>(count));
        if (written < 0 && errno == EINTR) continue;
        if (written <= 0) return false;
        // Advance past what was written.
        auto left = static_cast<std::size_t>(written);
        while (next < parts.size() && left >= parts[next].size() - skip) {
            left -= parts[next].size() - skip;
            ++next;
            skip = 0;
        }
        skip += left;
    }
    return true;
}

}  // namespace

void writeFileAtomic(const std::string& path, std::span<const std::string_view> parts) {
    std::string tempPath;
    int fd = -1;
    for (unsigned attempt = 0; fd < 0 && attempt < 16; ++attempt) {
        tempPath = path + tempSuffix(attempt);
        fd = ::open(tempPath.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd < 0 && errno != EEXIST) break;
    }
    if (fd < 0) throw Error(path + ": cannot write file: " + std::strerror(errno));
    bool ok = writeAll(fd, parts);
    int err = ok ? 0 : errno;
    if (::close(fd) != 0 && ok) {
        ok = false;
        err = errno;
    }
    if (!ok) {
        std::remove(tempPath.c_str());
        throw Error(path + ": cannot write file: " + std::strerror(err));
    }
    if (std::rename(tempPath.c_str(), path.c_str()) != 0) {
        err = errno;
        std::remove(tempPath.c_str());
        throw Error(path + ": cannot write file: " + std::strerror(err));
    }
}

}  // namespace ramus
