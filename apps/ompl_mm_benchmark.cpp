// ompl_mm_benchmark: runs a benchmark config (OMPL.app's ompl_benchmark format) on ompl_mm and physics
// scenes and writes OMPL benchmark logs. Exit codes: 0 done, 1 an output could not be written, 2 bad input.
#include "ompl_bench/app/BenchmarkApp.h"

int main(int argc, char **argv)
{
    return ompl_bench::benchmarkMain(argc, argv);
}
