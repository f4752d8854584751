// Nanoseconds per 2-D pair of a sample stream: what a path tracer pays per decision for its random numbers.
#include <rtlab/core/sample_stream.hpp>

#include <benchmark/benchmark.h>

using namespace rtlab;

namespace {

void BM_StreamPairs(benchmark::State& state, SampleSequence sequence) {
    std::uint32_t sample = 0;
    for (auto _ : state) {
        // One camera sample and 16 pairs of it: the stream's set-up is paid once per sample, as in a render.
        const SampleStream stream(sequence, SampleKey{7, sample & 255u, sample >> 8, sample & 1023u, 0});
        Vec2 acc(0.0f);
        for (std::uint32_t p = 0; p < 16; ++p) acc += stream.get2d(p);
        benchmark::DoNotOptimize(acc);
        ++sample;
    }
    state.counters["pairs/s"] =
        benchmark::Counter(16.0 * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

}  // namespace

BENCHMARK_CAPTURE(BM_StreamPairs, sobol, SampleSequence::sobol);
BENCHMARK_CAPTURE(BM_StreamPairs, independent, SampleSequence::independent);
