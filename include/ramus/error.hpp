// Errors thrown at the boundaries (parsers, configs, files, CLI): one type, with a location.
#pragma once

#include <stdexcept>
#include <string>

namespace ramus {

/// Where in an input text something was found. line and column are 1-based; 0 = unknown.
struct SourceLoc {
    std::string file;  ///< file name as the user gave it, or "<string>" for in-memory text
    int line = 0;
    int column = 0;

    /// "file:line:col" (parts that are unknown are left out).
    std::string str() const;
};

/// The one exception type of ramus. what() reads "file:line:col: message" when a location is
/// known, else just the message. Messages say what went wrong and what was expected.
class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message);
    Error(SourceLoc loc, const std::string& message);

    const SourceLoc& loc() const { return loc_; }
    /// The message without the location prefix.
    const std::string& message() const { return message_; }

private:
    SourceLoc loc_;
    std::string message_;
};

}  // namespace ramus

/// Internal invariant check: active in Debug builds and tests (RAMUS_ENABLE_ASSERTS), compiled
/// out in Release. Never used for validating user input (throw ramus::Error for that).
#if defined(RAMUS_ENABLE_ASSERTS)
#define RAMUS_ASSERT(cond)                                                     \
    do {                                                                       \
        if (!(cond)) ::ramus::detail::assertFailed(#cond, __FILE__, __LINE__); \
    } while (0)
namespace ramus::detail {
[[noreturn]] void assertFailed(const char* cond, const char* file, int line);
}
#else
#define RAMUS_ASSERT(cond) ((void)0)
#endif
