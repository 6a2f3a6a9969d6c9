#pragma once

#include "ompl_phys/base/PhysicsStateSpace.h"

#include <ompl/control/planners/syclop/GridDecomposition.h>

namespace ompl_phys
{
    /** OMPL's bounds of a region of the floor (x, y), as a grid decomposition over it needs. */
    ompl::base::RealVectorBounds floorBounds(const Eigen::AlignedBox2d &region);

    /** The workspace decomposition SyclopRRT and SyclopEST plan their leads over: a grid of
        cellsPerSide x cellsPerSide cells over the robot's region, locating a state by the robot's
        position. A full state for a grid point is a state-sampler sample with the robot moved there. */
    class RobotGridDecomposition : public ompl::control::GridDecomposition
    {
    public:
        /** Cells along each axis of the robot's region unless told otherwise. */
        static constexpr int DEFAULT_CELLS_PER_SIDE = 10;

        /** Shares the space whose robot position it reads, which it keeps alive. */
        explicit RobotGridDecomposition(std::shared_ptr<const PhysicsStateSpace> space,
                                        int cellsPerSide = DEFAULT_CELLS_PER_SIDE);

        /** OMPL's hook: coord is the robot centre's world x and y, m. */
        void project(const ompl::base::State *state, std::vector<double> &coord) const override;
        /** OMPL's hook: a uniform sample of sampler with the robot centre moved to coord (x, y). */
        void sampleFullState(const ompl::base::StateSamplerPtr &sampler, const std::vector<double> &coord,
                             ompl::base::State *state) const override;

    private:
        std::shared_ptr<const PhysicsStateSpace> space_;
    };
}  // namespace ompl_phys
