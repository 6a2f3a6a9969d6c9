#include "ompl_phys/base/RobotProjection.h"

namespace ompl_phys
{
    RobotProjection::RobotProjection(const PhysicsStateSpace *space)
        : ompl::base::ProjectionEvaluator(space), physics_(*space)
    {
    }

    void RobotProjection::defaultCellSizes()
    {
        const Eigen::AlignedBox2d &region = physics_.scene().limits.robotRegion;
        cellSizes_ = {region.sizes().x() / CELLS_PER_SIDE, region.sizes().y() / CELLS_PER_SIDE};
        bounds_.resize(2);
        bounds_.setLow(0, region.min().x());
        bounds_.setHigh(0, region.max().x());
        bounds_.setLow(1, region.min().y());
        bounds_.setHigh(1, region.max().y());
    }

    void RobotProjection::project(const ompl::base::State *state,
                                  Eigen::Ref<Eigen::VectorXd> projection) const
    {
        projection = physics_.robotPosition(state);
    }
}  // namespace ompl_phys
