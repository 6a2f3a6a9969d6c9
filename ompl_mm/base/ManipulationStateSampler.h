#pragma once

#include "ompl_mm/base/ManipulationStateSpace.h"

#include <ompl/base/StateSampler.h>

namespace ompl_mm
{
    /** The default sampler of a ManipulationStateSpace. Uniform samples draw every coordinate
        (robot joints within their limits, objects within the space's bounds), as OMPL's compound
        sampler does. Samples near a state keep its objects and move only the robot: objects move
        only through primitives, so a state near another is one the robot alone gets to. This is
        what OMPL's PathGeometric::checkAndRepair (run by PathSimplifier::simplify) draws to repair
        a motion that fails a check: a repaired transit stays a transit, and a failed repair leaves
        the objects where they were. For planners that only move the robot (OMPL's own, see
        ManipulationSetup::plannerRegistry), uniform samples may keep every object at its start
        pose instead. */
    class ManipulationStateSampler : public ompl::base::StateSampler
    {
    public:
        /** A sampler for space; with objectsAtStart, uniform samples put every object where the
            scene starts it. @pre space outlives the sampler (OMPL's samplers keep their space). */
        explicit ManipulationStateSampler(const ManipulationStateSpace *space, bool objectsAtStart = false);

        /** OMPL's hook: every coordinate uniform (the objects at their start poses when so made). */
        void sampleUniform(ompl::base::State *state) override;
        /** OMPL's hook: near's objects; the robot's joints uniform within distance of near's. */
        void sampleUniformNear(ompl::base::State *state, const ompl::base::State *near,
                               double distance) override;
        /** OMPL's hook: mean's objects; the robot's joints Gaussian about mean's. */
        void sampleGaussian(ompl::base::State *state, const ompl::base::State *mean, double stdDev) override;

    private:
        ompl::base::StateSamplerPtr all_;
        ompl::base::StateSamplerPtr robot_;
        bool objectsAtStart_;
    };
}  // namespace ompl_mm
