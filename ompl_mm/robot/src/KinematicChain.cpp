#include "ompl_mm/robot/KinematicChain.h"

#include "ompl_mm/robot/AxisTurn.h"

#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>

namespace ompl_mm
{
    KinematicChain::KinematicChain(const RobotModel &robot, int tip, const Eigen::Isometry3d &tool)
    {
        if (tip < 0 || tip >= static_cast<int>(robot.links().size()))
            throw ompl::Exception("KinematicChain", "no link with index " + std::to_string(tip));
        std::vector<int> path;  // tip first
        for (int link = tip; robot.links()[link].parent >= 0; link = robot.links()[link].parent)
            path.push_back(link);
        std::reverse(path.begin(), path.end());
        Eigen::Isometry3d pending = Eigen::Isometry3d::Identity();
        for (const int link : path)
        {
            const Joint &joint = robot.joints()[robot.links()[link].joint];
            pending = pending * joint.origin;
            if (joint.type == Joint::Type::Fixed)
                continue;
            // inverse kinematics moves each chain joint's variable on its own
            if (joint.mimics >= 0)
                throw ompl::Exception("KinematicChain", "the chain to link '" + robot.links()[tip].name +
                                                            "' passes through joint '" + joint.name +
                                                            "', which follows another (<mimic>): inverse "
                                                            "kinematics cannot solve for it; fix the joint "
                                                            "(<fixed_joint>) or choose a tool link above it");
            ChainJoint chainJoint{pending,
                                  joint.axis,
                                  joint.type == Joint::Type::Prismatic,
                                  joint.type == Joint::Type::Continuous,
                                  static_cast<unsigned int>(joint.variable),
                                  joint.lower,
                                  joint.upper};
            chainJoint.alignedAxis = alignedAxisOf(joint.axis);
            chainJoint.turnsBefore = !pending.linear().isIdentity(0.0);
            joints_.push_back(chainJoint);
            pending.setIdentity();
        }
        after_ = pending * tool;
    }

    void KinematicChain::advance(Eigen::Isometry3d &frame, const ChainJoint &joint)
    {
        frame.translation() += frame.linear() * joint.before.translation();
        if (joint.turnsBefore)
            frame.linear() = frame.linear() * joint.before.linear();
    }

    void KinematicChain::move(Eigen::Isometry3d &frame, const ChainJoint &joint, double q)
    {
        if (joint.prismatic)
        {
            frame.translation() += frame.linear() * (q * joint.axis);
            return;
        }
        turnAbout(frame.linear(), joint.axis, joint.alignedAxis, q);
    }

    Eigen::Isometry3d KinematicChain::toolPose(const double *q, const Eigen::Isometry3d &base) const
    {
        Eigen::Isometry3d frame = base;
        for (const ChainJoint &joint : joints_)
        {
            advance(frame, joint);
            move(frame, joint, q[joint.variable]);
        }
        return frame * after_;
    }

    Eigen::Isometry3d KinematicChain::toolPoseAndJacobian(
        const double *q, const Eigen::Isometry3d &base,
        Eigen::Ref<Eigen::Matrix<double, 6, Eigen::Dynamic>> jacobian) const
    {
        // first pass: each joint's world origin (rows 0-2) and axis (rows 3-5), and the tool pose
        Eigen::Isometry3d frame = base;
        for (std::size_t i = 0; i < joints_.size(); ++i)
        {
            const ChainJoint &joint = joints_[i];
            advance(frame, joint);
            jacobian.col(static_cast<Eigen::Index>(i)).head<3>() = frame.translation();
            jacobian.col(static_cast<Eigen::Index>(i)).tail<3>() = frame.linear() * joint.axis;
            move(frame, joint, q[joint.variable]);
        }
        const Eigen::Isometry3d tool = frame * after_;
        // second pass: a turning joint moves the tool point by axis x (point - origin)
        for (std::size_t i = 0; i < joints_.size(); ++i)
        {
            auto column = jacobian.col(static_cast<Eigen::Index>(i));
            const Eigen::Vector3d axis = column.tail<3>();
            if (joints_[i].prismatic)
            {
                column.head<3>() = axis;
                column.tail<3>().setZero();
            }
            else
                column.head<3>() = axis.cross(tool.translation() - column.head<3>());
        }
        return tool;
    }
}  // namespace ompl_mm
