// Float text for the GLB JSON (src/core/float_text.hpp): detail::writeShortFloat (Dragonbox
// digits, own layout) against std::to_chars, both giving the shortest text that reads back as
// the same float, over 4096 random floats of the magnitudes a skeleton's JSON holds (node
// translations, quaternions, extents in metres: [-2, 2]). Items: floats per second.
#include <benchmark/benchmark.h>

#include <charconv>
#include <vector>

#include "core/float_text.hpp"
#include "ramus/rng.hpp"

namespace {

const std::vector<float>& sampleFloats() {
    static const std::vector<float> values = [] {
        std::vector<float> v(4096);
        ramus::Rng rng(3);
        for (float& f : v) f = static_cast<float>(rng.uniform(-2.0, 2.0));
        return v;
    }();
    return values;
}

template <typename Write>
void formatAll(benchmark::State& state, Write write) {
    const std::vector<float>& values = sampleFloats();
    char buffer[32];
    for (auto _ : state) {
        for (const float f : values) {
            benchmark::DoNotOptimize(write(buffer, f));
            benchmark::ClobberMemory();
        }
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(values.size()));
}

void BM_WriteShortFloat(benchmark::State& state) {
    formatAll(state, [](char* p, float f) { return ramus::detail::writeShortFloat(p, f); });
}
BENCHMARK(BM_WriteShortFloat);

void BM_ToCharsFloat(benchmark::State& state) {
    formatAll(state, [](char* p, float f) { return std::to_chars(p, p + 32, f).ptr; });
}
BENCHMARK(BM_ToCharsFloat);

}  // namespace
