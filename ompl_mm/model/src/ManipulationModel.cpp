#include "ompl_mm/model/ManipulationModel.h"

#include "ompl_core/io/InputError.h"

#include <cmath>

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

    int ManipulationModel::restingSurface(const Eigen::Vector3d &position) const
    {
        for (std::size_t i = 0; i < scene_.surfaces.size(); ++i)
        {
            const SupportSurface &s = scene_.surfaces[i];
            if (std::abs(position.z() - s.height) < REST_TOLERANCE && s.contains(position.x(), position.y()))
                return static_cast<int>(i);
        }
        return -1;
    }
}  // namespace ompl_mm
