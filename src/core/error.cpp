#include "ramus/error.hpp"

#include <cstdio>
#include <cstdlib>

namespace ramus {

std::string SourceLoc::str() const {
    std::string s = file;
    if (line > 0) {
        if (!s.empty()) s.push_back(':');
        s.append(std::to_string(line));
        if (column > 0) {
            s.push_back(':');
            s.append(std::to_string(column));
        }
    }
    return s;
}

namespace {
std::string withLocation(const SourceLoc& loc, const std::string& message) {
    std::string where = loc.str();
    return where.empty() ? message : where + ": " + message;
}
}  // namespace

Error::Error(const std::string& message) : std::runtime_error(message), message_(message) {}

Error::Error(SourceLoc loc, const std::string& message)
    : std::runtime_error(withLocation(loc, message)), loc_(std::move(loc)), message_(message) {}

namespace detail {
void assertFailed(const char* cond, const char* file, int line) {
    std::fprintf(stderr, "%s:%d: internal error: assertion failed: %s\n", file, line, cond);
    std::abort();
}
}  // namespace detail

}  // namespace ramus
