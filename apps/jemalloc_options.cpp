// jemalloc's options for the programs linked with it (RAMUS_USE_JEMALLOC: the ramus tool and
// ramus_bench). jemalloc reads this symbol at start-up; MALLOC_CONF in the environment still
// overrides it (MALLOC_CONF=thp:default,metadata_thp:disabled gives jemalloc's defaults back).
//
// Transparent huge pages for jemalloc's memory and its metadata: the meshers fill arrays of
// hundreds of megabytes once, and with 4 KiB pages every first touch was a page fault (76 000
// for `ramus lsystem tree_3d.lsys -n 8 --union`, a fifth of its time in the kernel on the 2-core
// VM, whose faults are dear). Where the system leaves huge pages to madvise (Debian's default)
// jemalloc asks for them; measured 2026-12-06 (docs/BENCHMARKS.md): that union 2.3 → 1.8 s,
// `-n 9 --weld` meshing 0.34–0.44 → 0.13–0.18 s, the same GLBs to the byte, 15 % more resident
// memory.
extern "C" {
// NOLINTNEXTLINE(readability-identifier-naming): the name jemalloc looks up
extern const char* malloc_conf;
const char* malloc_conf = "thp:always,metadata_thp:always";
}
