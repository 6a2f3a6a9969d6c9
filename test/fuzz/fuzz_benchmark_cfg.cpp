// Fuzz target: a benchmark configuration in OMPL's ompl_benchmark format, parsed as
// ompl_mm_benchmark parses it (sections, problem keys, planners and their parameters).
#include "FuzzInput.h"
#include "ompl_core/bench/BenchmarkConfig.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    fuzz::readOrReject([&] { ompl_core::parseBenchmarkConfig(fuzz::inputText(data, size), "fuzz.cfg"); });
    return 0;
}
