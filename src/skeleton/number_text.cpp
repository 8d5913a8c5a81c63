#include "skeleton/number_text.hpp"

#include <charconv>
#include <cmath>
#include <system_error>

namespace ramus::detail {

void appendShortest(std::string& out, double value) {
    char buffer[64];
    if (std::abs(value) < 1e15 && value == std::trunc(value)) {
        const auto integral = static_cast<long long>(value);
        const auto result = std::to_chars(buffer, buffer + sizeof buffer, integral);
        out.append(buffer, result.ptr);
        return;
    }
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, result.ptr);
}

std::string shortest(double value) {
    std::string out;
    appendShortest(out, value);
    return out;
}

namespace {
bool isDigit(char c) { return c >= '0' && c <= '9'; }
}  // namespace

std::optional<double> parseNumber(std::string_view text, std::size_t& pos) {
    // Find the extent first: from_chars accepts neither '+' nor some forms SVG allows.
    std::size_t end = pos;
    bool negative = false;
    if (end < text.size() && (text[end] == '+' || text[end] == '-')) {
        negative = text[end] == '-';
        ++end;
    }
    const std::size_t mantissaStart = end;
    std::size_t digits = 0;
    while (end < text.size() && isDigit(text[end])) ++end, ++digits;
    if (end < text.size() && text[end] == '.') {
        ++end;
        while (end < text.size() && isDigit(text[end])) ++end, ++digits;
    }
    if (digits == 0) return std::nullopt;
    if (end < text.size() && (text[end] == 'e' || text[end] == 'E')) {
        std::size_t e = end + 1;
        if (e < text.size() && (text[e] == '+' || text[e] == '-')) ++e;
        if (e < text.size() && isDigit(text[e])) {
            while (e < text.size() && isDigit(text[e])) ++e;
            end = e;
        }
    }
    double value = 0.0;
    const char* first = text.data() + mantissaStart;
    const char* last = text.data() + end;
    const auto result = std::from_chars(first, last, value);
    if (result.ec != std::errc() || result.ptr != last || !std::isfinite(value)) {
        return std::nullopt;
    }
    pos = end;
    return negative ? -value : value;
}

}  // namespace ramus::detail
