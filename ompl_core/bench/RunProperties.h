/* A run record's values as run properties of OMPL's benchmark logs. */
#pragma once

#include "ompl_core/run/RunRecord.h"

#include <ompl/tools/benchmark/Benchmark.h>

namespace ompl_core
{
    /** Adds record's numbers (REAL), counts (INTEGER) and flags (BOOLEAN) to properties, named by
        their keys; a nested record's keys are prefixed with its key and '_', except those of
        "stats" ("stats.iterations" becomes "iterations INTEGER", "primitives.push" becomes
        "primitives_push INTEGER"). Texts are left out, and so are numbers that are not finite
        (the log has no value for them). A property already set stays: Benchmark's and the
        planner's own (MOPL's planner data names its statistics as the run record does). The names
        become the database's columns. */
    void addRunProperties(const RunRecord &record, ompl::tools::Benchmark::RunProperties &properties);
}  // namespace ompl_core
