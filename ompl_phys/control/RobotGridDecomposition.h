/* The workspace decomposition SyclopRRT and SyclopEST plan their leads over: a grid of
   cellsPerSide x cellsPerSide cells over the robot's region, locating a state by the robot's
   position. A full state for a grid point is a state-sampler sample with the robot moved there. */
#pragma once

#include "ompl_phys/base/PhysicsStateSpace.h"

#include <ompl/control/planners/syclop/GridDecomposition.h>

namespace ompl_phys
{
    class RobotGridDecomposition : public ompl::control::GridDecomposition
    {
    public:
        static constexpr int DEFAULT_CELLS_PER_SIDE = 10;

        /** Shares the space whose robot position it reads. */
        explicit RobotGridDecomposition(std::shared_ptr<const PhysicsStateSpace> space,
                                        int cellsPerSide = DEFAULT_CELLS_PER_SIDE);

        void project(const ompl::base::State *state, std::vector<double> &coord) const override;
        void sampleFullState(const ompl::base::StateSamplerPtr &sampler, const std::vector<double> &coord,
                             ompl::base::State *state) const override;

    private:
        std::shared_ptr<const PhysicsStateSpace> space_;
    };
}  // namespace ompl_phys
