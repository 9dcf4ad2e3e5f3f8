// plastica_bench: the figures of docs/performance.md's table. Run through `make bench`.
#include <benchmark/benchmark.h>

#include <malloc.h>

int main(int argc, char** argv) {
    // As in the plastica program: buffers freed and allocated again each step or iteration
    // (VTK's per-file buffers, Eigen's factorisation workspace) stay in the heap.
    mallopt(M_MMAP_THRESHOLD, 256 << 20);
    mallopt(M_TRIM_THRESHOLD, 512 << 20);
    mallopt(M_TOP_PAD, 64 << 20);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
