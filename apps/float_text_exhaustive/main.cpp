// Exhaustive check of detail::writeShortFloat (src/core/float_text.hpp) over all 2^32 bit
// patterns: every finite float's text reads back bit-exactly with strtof (correctly rounded),
// fits the 15 characters the callers' 16-byte room allows, and has exactly the significant
// digits of scientific std::to_chars (the shortest, nearest to the value). A heavy check of
// its own (`make check-floats`, minutes on all cores); the unit test samples the same
// properties. Prints a progress line per 1/16 of the range and the counts; exit status 1 on
// any mismatch.
#include <atomic>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <thread>
#include <vector>

#include "core/float_text.hpp"

namespace {

// The significant digits of a decimal text: no sign, point, leading or trailing zeros, exponent.
std::string_view significantDigits(const char* first, const char* last, char* out) {
    char* o = out;
    for (const char* p = first; p < last && *p != 'e'; ++p) {
        if (*p >= '0' && *p <= '9' && !(o == out && *p == '0')) *o++ = *p;
    }
    while (o > out && o[-1] == '0') --o;
    return {out, static_cast<std::size_t>(o - out)};
}

struct Counts {
    std::atomic<std::uint64_t> finite{0}, roundTrip{0}, tooLong{0}, digits{0};
};

void checkRange(std::uint64_t begin, std::uint64_t end, Counts& counts) {
    std::uint64_t finite = 0, roundTrip = 0, tooLong = 0, digits = 0;
    for (std::uint64_t u = begin; u < end; ++u) {
        const auto bits = static_cast<std::uint32_t>(u);
        const float f = std::bit_cast<float>(bits);
        if (!std::isfinite(f)) continue;
        ++finite;
        char text[32];
        char* const textEnd = ramus::detail::writeShortFloat(text, f);
        *textEnd = '\0';
        const float back = std::strtof(text, nullptr);
        const bool same = std::bit_cast<std::uint32_t>(back) == bits || f == 0.0f;  // "0" for -0
        char reference[32], a[32], b[32];
        const char* referenceEnd =
            std::to_chars(reference, reference + sizeof reference, f, std::chars_format::scientific)
                .ptr;
        const bool digitsMatch =
            significantDigits(text, textEnd, a) == significantDigits(reference, referenceEnd, b);
        roundTrip += !same;
        tooLong += textEnd - text > 15;
        digits += !digitsMatch;
        if ((!same || textEnd - text > 15 || !digitsMatch) && roundTrip + tooLong + digits <= 10) {
            std::printf("bits %08x: %s (std::to_chars: %.*s)\n", bits, text,
                        static_cast<int>(referenceEnd - reference), reference);
        }
    }
    counts.finite += finite;
    counts.roundTrip += roundTrip;
    counts.tooLong += tooLong;
    counts.digits += digits;
}

}  // namespace

int main() {
    const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    constexpr std::uint64_t kTotal = std::uint64_t{1} << 32;
    constexpr std::uint64_t kChunks = 16;
    Counts counts;
    std::atomic<std::uint64_t> next{0};
    std::vector<std::thread> workers;
    for (unsigned t = 0; t < threads; ++t) {
        workers.emplace_back([&] {
            for (std::uint64_t c = next++; c < kChunks; c = next++) {
                checkRange(c * (kTotal / kChunks), (c + 1) * (kTotal / kChunks), counts);
                std::printf("chunk %llu of %llu done\n", static_cast<unsigned long long>(c + 1),
                            static_cast<unsigned long long>(kChunks));
                std::fflush(stdout);
            }
        });
    }
    for (std::thread& w : workers) w.join();
    std::printf(
        "checked %llu finite floats: %llu do not read back, %llu longer than 15 characters, "
        "%llu with other digits than std::to_chars\n",
        static_cast<unsigned long long>(counts.finite.load()),
        static_cast<unsigned long long>(counts.roundTrip.load()),
        static_cast<unsigned long long>(counts.tooLong.load()),
        static_cast<unsigned long long>(counts.digits.load()));
    return counts.roundTrip + counts.tooLong + counts.digits == 0 ? 0 : 1;
}
