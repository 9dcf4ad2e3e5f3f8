// plastica_bench: the figures of the README's performance table. Run through `make bench`.
#include <benchmark/benchmark.h>

#include <malloc.h>

int main(int argc, char** argv) {
    // As in the plastica program: VTK's per-file buffers must not be handed back each time.
    mallopt(M_TRIM_THRESHOLD, 256 << 20);
    mallopt(M_TOP_PAD, 64 << 20);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
