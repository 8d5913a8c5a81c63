// File helpers used by every writer and reader: whole-file reads with clear errors, and
// atomic writes (temp file in the same directory, then rename) so no partial file is left.
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace ramus {

/// Reads a whole file. Throws Error("PATH: cannot read file: <reason>") on failure.
std::string readFile(const std::string& path);

/// Writes `bytes` to `path` atomically: writes "<path>.tmp-<random>" next to it, flushes, then
/// renames over `path`. On any failure the temp file is removed and Error is thrown; an
/// existing file at `path` is then left untouched.
void writeFileAtomic(const std::string& path, std::string_view bytes);

/// writeFileAtomic of the concatenation of `parts`, without joining them in memory first.
void writeFileAtomic(const std::string& path, std::span<const std::string_view> parts);

}  // namespace ramus
