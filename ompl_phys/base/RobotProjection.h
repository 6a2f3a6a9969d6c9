/* Projects a physics state on the robot's position on the floor (x, y): the low-dimensional view
   that KPIECE1, EST and PDST grid their exploration in. Default cells split the robot's region
   into CELLS_PER_SIDE along each axis. */
#pragma once

#include "ompl_phys/base/PhysicsStateSpace.h"

#include <ompl/base/ProjectionEvaluator.h>

namespace ompl_phys
{
    class RobotProjection : public ompl::base::ProjectionEvaluator
    {
    public:
        static constexpr unsigned int CELLS_PER_SIDE = 20;

        explicit RobotProjection(const PhysicsStateSpace *space);

        unsigned int getDimension() const override { return 2; }
        void defaultCellSizes() override;
        void project(const ompl::base::State *state, Eigen::Ref<Eigen::VectorXd> projection) const override;

    private:
        const PhysicsStateSpace &physics_;
    };
}  // namespace ompl_phys
