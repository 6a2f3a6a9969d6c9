#pragma once

#include "ompl_phys/base/PhysicsStateSpace.h"

#include <ompl/base/ProjectionEvaluator.h>

namespace ompl_phys
{
    /** Projects a physics state on the robot's position on the floor (world x, y, m): the
        low-dimensional view that KPIECE1, EST and PDST grid their exploration in. Default cells
        split the robot's region into CELLS_PER_SIDE along each axis. */
    class RobotProjection : public ompl::base::ProjectionEvaluator
    {
    public:
        /** Default cells along each axis of the robot's region. */
        static constexpr unsigned int CELLS_PER_SIDE = 20;

        /** Projects states of space, which must outlive the projection (PhysicsSetup registers it
            as the space's default projection, so the space owns it). */
        explicit RobotProjection(const PhysicsStateSpace *space);

        /** OMPL's hook: two dimensions, x and y. */
        unsigned int getDimension() const override { return 2; }
        /** OMPL's hook: CELLS_PER_SIDE cells along each axis, bounded by the robot's region. */
        void defaultCellSizes() override;
        /** OMPL's hook: the robot centre's x and y, m. */
        void project(const ompl::base::State *state, Eigen::Ref<Eigen::VectorXd> projection) const override;

    private:
        const PhysicsStateSpace &physics_;
    };
}  // namespace ompl_phys
