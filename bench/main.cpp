// Entry point of ramus_bench: every bench/*.cpp registers its cases with Google Benchmark.
#include <benchmark/benchmark.h>

BENCHMARK_MAIN();
