/* The benchmark tool's command line, as a function: ompl_mm_benchmark is this alone, and a user's own
   program can register planners first and then call it. */
#pragma once

namespace ompl_bench
{
    /** Runs `NAME CONFIG.cfg [--shard K/N] [--output DIR] [--quiet]`: reads the cfg (OMPL.app's
       ompl_benchmark format, see docs/benchmarks.md), runs the benchmark with planners from the registries of
        ompl_mm::ManipulationSetup and ompl_phys::PhysicsSetup (a planner a program adds there
        before this call can be named in the cfg), and writes OMPL benchmark logs.
        @returns the exit status: 0 when every run was made and the logs written, 1 when a log or
        path could not be written, 2 for bad input (a cfg or scene error, named by file and
        line, or a bad option). */
    int benchmarkMain(int argc, const char *const *argv);
}  // namespace ompl_bench
