// Runs the real `ramus` binary for end-to-end tests of the command-line tool.
#pragma once

#include <sys/wait.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "ramus/file_util.hpp"

namespace ramus::testing {

/// Writes `text` to `dir`/`name` (atomically) and returns that path.
inline std::filesystem::path writeInput(const std::filesystem::path& dir, const std::string& name,
                                        const std::string& text) {
    const std::filesystem::path path = dir / name;
    writeFileAtomic(path.string(), text);
    return path;
}

struct CommandResult {
    int exitCode = -1;
    std::string out;
    std::string err;
};

/// The binary under test: $RAMUS_BIN, else the one next to the tests.
inline std::string ramusBinary() {
    const char* env = std::getenv("RAMUS_BIN");
    return env && *env ? env : RAMUS_BINARY_DIR "/ramus";
}

/// A fresh, empty scratch directory for one test.
inline std::filesystem::path scratchDirectory(const std::string& name) {
    auto dir = std::filesystem::temp_directory_path() / ("ramus_cli_" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

/// Runs `ramus ARGS` (ARGS already shell-quoted) with stdout/stderr captured through files.
inline CommandResult runRamus(const std::string& args, const std::filesystem::path& dir) {
    const std::string outPath = (dir / "stdout.txt").string();
    const std::string errPath = (dir / "stderr.txt").string();
    const std::string command =
        "'" + ramusBinary() + "' " + args + " >'" + outPath + "' 2>'" + errPath + "'";
    const int status = std::system(command.c_str());
    CommandResult result;
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = readFile(outPath);
    result.err = readFile(errPath);
    return result;
}

/// Copies a test output into $RAMUS_TEST_OUTPUT (for the glTF validator) when it is set.
inline void keepForValidation(const std::filesystem::path& file, const std::string& name) {
    const char* dir = std::getenv("RAMUS_TEST_OUTPUT");
    if (!dir || !*dir) return;
    std::filesystem::copy_file(file, std::filesystem::path(dir) / name,
                               std::filesystem::copy_options::overwrite_existing);
}

/// The JSON chunk of a GLB file's bytes (the chunk's length at byte 12, its data from 20).
inline nlohmann::json glbJson(const std::string& bytes) {
    std::uint32_t length = 0;
    std::memcpy(&length, bytes.data() + 12, 4);
    return nlohmann::json::parse(bytes.substr(20, length));
}

}  // namespace ramus::testing
