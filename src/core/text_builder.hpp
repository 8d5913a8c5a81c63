// A short text built in a caller's stack buffer: the JSON of objects written by the hundred (a
// skeleton's accessors, nodes and bone extras), where appending to a std::string piece by piece
// cost more than the pieces themselves.
#pragma once

#include <charconv>
#include <cstdint>
#include <cstring>
#include <string_view>

#include "core/float_text.hpp"
#include "ramus/error.hpp"

namespace ramus::detail {

class TextBuilder {
public:
    /// Writes into [first, last); the caller sizes the buffer for the longest text it builds
    /// (checked in builds with RAMUS_ENABLE_ASSERTS).
    TextBuilder(char* first, char* last) : begin_(first), end_(last), p_(first) {}

    template <std::size_t N>
    TextBuilder& text(const char (&literal)[N]) {
        return text(std::string_view(literal, N - 1));
    }
    TextBuilder& text(std::string_view s) {
        RAMUS_ASSERT(s.size() <= static_cast<std::size_t>(end_ - p_));
        std::memcpy(p_, s.data(), s.size());
        p_ += s.size();
        return *this;
    }
    TextBuilder& number(std::uint64_t n) {
        RAMUS_ASSERT(end_ - p_ >= 20);
        p_ = std::to_chars(p_, p_ + 20, n).ptr;
        return *this;
    }
    /// A float (through the cache: shortest round-trip text, −0 as "0").
    TextBuilder& number(float value, FloatTextCache& cache) {
        RAMUS_ASSERT(end_ - p_ >= 16);
        p_ = cache.write(p_, p_ + 16, value);
        return *this;
    }
    /// A JSON array of `count` numbers written as floats.
    template <typename T>
    TextBuilder& floats(const T* values, int count, FloatTextCache& cache) {
        text("[");
        for (int i = 0; i < count; ++i) {
            if (i > 0) text(",");
            number(static_cast<float>(values[i]), cache);
        }
        return text("]");
    }
    std::string_view view() const { return {begin_, static_cast<std::size_t>(p_ - begin_)}; }

private:
    char* begin_;
    char* end_;
    char* p_;
};

}  // namespace ramus::detail
