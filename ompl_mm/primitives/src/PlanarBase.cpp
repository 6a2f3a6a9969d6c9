#include "ompl_mm/primitives/PlanarBase.h"

#include <algorithm>
#include <cassert>
#include <vector>

namespace ompl_mm
{
    PlanarBase::PlanarBase(const ManipulationModel &model) : model_(model)
    {
        const RobotModel &robot = model.robot();
        const std::vector<double> zero(robot.dof(), 0.0);
        const auto &links = robot.links();
        for (int link = model.toolLink(); link > 0; link = links[link].parent)
        {
            const Joint &joint = robot.joints()[links[link].joint];
            if (joint.type != Joint::Type::Prismatic)
                continue;
            const Eigen::Isometry3d parent =
                robot.linkFrame(zero.data(), model.scene().robot.basePose, links[link].parent);
            const Eigen::Vector3d axis = parent.linear() * joint.origin.linear() * joint.axis;
            if (axis.isApprox(Eigen::Vector3d::UnitX(), 1e-9))
                jointX_ = joint.variable;
            else if (axis.isApprox(Eigen::Vector3d::UnitY(), 1e-9))
                jointY_ = joint.variable;
        }
    }

    void PlanarBase::placeTool(const Eigen::Vector2d &toolXY, double *q) const
    {
        assert(exists());
        q[jointX_] = 0.0;
        q[jointY_] = 0.0;
        const Eigen::Vector3d atZero = model_.toolFrame(q).translation();
        q[jointX_] = toolXY.x() - atZero.x();
        q[jointY_] = toolXY.y() - atZero.y();
    }

    bool PlanarBase::onlyBaseMoves(const double *qa, const double *qb) const
    {
        assert(exists());
        for (int j = 0; j < static_cast<int>(model_.dof()); ++j)
            if (j != jointX_ && j != jointY_ && qa[j] != qb[j])
                return false;
        return true;
    }

    double PlanarBase::footprintRadius(const double *q) const
    {
        const RobotModel &robot = model_.robot();
        std::vector<Eigen::Isometry3d> frames;
        robot.forwardKinematics(q, model_.scene().robot.basePose, frames);
        const Eigen::Vector2d tool = model_.toolFrame(q).translation().head<2>();
        double radius = 0.0;
        for (std::size_t link = 0; link < robot.links().size(); ++link)
            for (const LinkShape &part : robot.links()[link].shapes)
            {
                const Eigen::Vector2d centre = (frames[link] * part.origin).translation().head<2>();
                radius = std::max(radius, (centre - tool).norm() + part.shape.boundingRadius());
            }
        return radius;
    }
}  // namespace ompl_mm
