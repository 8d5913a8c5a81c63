// File helpers used by every writer and reader: whole-file reads with clear errors, and
// atomic writes (temp file in the same directory, then rename) so no partial file is left.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

namespace ramus {

/// Default size limit of every input file ramus reads (1 GiB): a file given by mistake (a
/// disk image, /dev/zero) fails at once instead of exhausting memory. Commands that read large
/// inputs (point and mesh files) have a flag to change it (docs/cli.md, "Limits").
inline constexpr std::size_t kMaxInputFileBytes = std::size_t{1} << 30;

/// The extension of `path`'s file name in lower case with its dot (".obj"), or "" without one.
std::string lowerExtension(const std::string& path);

/// Reads a whole file of at most `maxBytes` bytes. Throws Error("PATH: cannot read file:
/// <reason>") on failure and Error("PATH: the file is larger than the input limit of N bytes;
/// …") past the limit.
std::string readFile(const std::string& path, std::size_t maxBytes = kMaxInputFileBytes);

/// Writes `bytes` to `path` atomically: writes "<path>.tmp-<random>" next to it, flushes, then
/// renames over `path`. On any failure the temp file is removed and Error is thrown; an
/// existing file at `path` is then left untouched.
void writeFileAtomic(const std::string& path, std::string_view bytes);

/// writeFileAtomic of the concatenation of `parts`, without joining them in memory first.
void writeFileAtomic(const std::string& path, std::span<const std::string_view> parts);

}  // namespace ramus
