#include "ompl_phys/control/RobotGridDecomposition.h"

namespace ompl_phys
{
    ompl::base::RealVectorBounds floorBounds(const Eigen::AlignedBox2d &region)
    {
        ompl::base::RealVectorBounds bounds(2);
        bounds.setLow(0, region.min().x());
        bounds.setHigh(0, region.max().x());
        bounds.setLow(1, region.min().y());
        bounds.setHigh(1, region.max().y());
        return bounds;
    }

    RobotGridDecomposition::RobotGridDecomposition(std::shared_ptr<const PhysicsStateSpace> space,
                                                   int cellsPerSide)
        : ompl::control::GridDecomposition(cellsPerSide, 2, floorBounds(space->scene().limits.robotRegion)),
          space_(std::move(space))
    {
    }

    void RobotGridDecomposition::project(const ompl::base::State *state, std::vector<double> &coord) const
    {
        const Eigen::Vector2d robot = space_->robotPosition(state);
        coord = {robot.x(), robot.y()};
    }

    void RobotGridDecomposition::sampleFullState(const ompl::base::StateSamplerPtr &sampler,
                                                 const std::vector<double> &coord,
                                                 ompl::base::State *state) const
    {
        sampler->sampleUniform(state);
        BodyStates states;
        space_->readState(state, states);
        states[0].position.head<2>() = Eigen::Vector2d(coord[0], coord[1]);
        space_->writeState(states, state);
    }
}  // namespace ompl_phys
