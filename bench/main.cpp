// Entry point of ramus_bench: every bench/*.cpp registers its cases with Google Benchmark. The
// allocator policy is the one `ramus` itself runs with (apps/ramus/main.cpp), so the figures
// are what the command-line tool, batches and the studio get.
#include <benchmark/benchmark.h>

#include "ramus/memory_policy.hpp"

int main(int argc, char** argv) {
    ramus::keepFreedMemoryForReuse();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
