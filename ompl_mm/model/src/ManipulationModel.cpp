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

        mobileBase_ = robot_.dof() > 0;
        for (unsigned int i = 0; i < robot_.dof(); ++i)
            mobileBase_ = mobileBase_ && robot_.variableJoint(i).type == Joint::Type::Prismatic;

        // a planar base: prismatic joints along world x and y on the way to the tool
        std::vector<double> zero(robot_.dof(), 0.0);
        const auto &links = robot_.links();
        for (int link = toolLink_; link > 0; link = links[link].parent)
        {
            const Joint &joint = robot_.joints()[links[link].joint];
            if (joint.type != Joint::Type::Prismatic)
                continue;
            const Eigen::Isometry3d parent =
                robot_.linkFrame(zero.data(), scene_.robot.basePose, links[link].parent);
            const Eigen::Vector3d axis = parent.linear() * joint.origin.linear() * joint.axis;
            if (axis.isApprox(Eigen::Vector3d::UnitX(), 1e-9))
                baseJointX_ = joint.variable;
            else if (axis.isApprox(Eigen::Vector3d::UnitY(), 1e-9))
                baseJointY_ = joint.variable;
        }
        planarBase_ = baseJointX_ >= 0 && baseJointY_ >= 0;
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

    void ManipulationModel::baseJointsFor(const Eigen::Vector2d &toolXY, double *q) const
    {
        q[baseJointX_] = 0.0;
        q[baseJointY_] = 0.0;
        const Eigen::Vector3d atZero = toolFrame(q).translation();
        q[baseJointX_] = toolXY.x() - atZero.x();
        q[baseJointY_] = toolXY.y() - atZero.y();
    }
}  // namespace ompl_mm
