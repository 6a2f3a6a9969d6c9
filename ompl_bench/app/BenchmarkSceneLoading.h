/* Telling the two kinds of scene apart, so one benchmark tool serves both libraries. */
#pragma once

#include "ompl_core/bench/BenchmarkScene.h"

#include <memory>
#include <vector>

namespace ompl_bench
{
    /** Loads problem's scene as an ompl_mm scene (root element <scene>; its solutions executed in
        physics too when simulate: ompl_mmphys) or a physics scene (<physics_scene>), after
        checking that every planner is registered for that kind.
        @throws ompl_core::InputError naming the cfg's scene line for a missing file or a file of
        neither kind, the planner's line for a planner of the other kind or of none, and the scene
        file's place for an error inside it. */
    std::unique_ptr<ompl_core::BenchmarkScene> loadBenchmarkScene(
        const ompl_core::BenchmarkProblem &problem, const std::vector<ompl_core::BenchmarkPlanner> &planners,
        bool simulate = false);
}  // namespace ompl_bench
