#include "ompl_mm/model/ManipulationModel.h"

#include "ompl_core/io/InputError.h"

namespace ompl_mm
{
    ManipulationModel::ManipulationModel(Scene scene, RobotModel robot)
        : scene_(std::move(scene)), robot_(std::move(robot))
    {
        try
        {
            toolLink_ = robot_.linkIndex(scene_.robot.toolLink);
        }
        catch (const ompl::Exception &e)
        {
            throw ompl_core::InputError(scene_.robot.where, e.what());
        }
    }

    Eigen::Isometry3d ManipulationModel::toolFrame(const double *q) const
    {
        Eigen::Isometry3d frame = robot_.linkFrame(q, scene_.robot.basePose, toolLink_);
        frame.translation() = frame * scene_.robot.toolOffset;
        return frame;
    }
}  // namespace ompl_mm
