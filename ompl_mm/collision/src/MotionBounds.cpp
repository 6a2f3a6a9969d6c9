#include "ompl_mm/collision/MotionBounds.h"

#include <cmath>

namespace ompl_mm
{
    namespace
    {
        /** The joint's farthest reach along its own motion: a prismatic joint's largest travel (a
            mimic joint's over its leader's limits). */
        double travelReach(const RobotModel &robot, const Joint &joint)
        {
            if (joint.type != Joint::Type::Prismatic)
                return 0.0;
            const Joint &limits = joint.mimics >= 0 ? robot.joints()[joint.mimics] : joint;
            return std::max(std::abs(joint.multiplier * limits.lower + joint.offset),
                            std::abs(joint.multiplier * limits.upper + joint.offset));
        }

        /** The shorter turn from one yaw to another, radians in [0, pi]. */
        double yawTurn(double from, double to)
        {
            return std::abs(std::remainder(to - from, 2.0 * M_PI));
        }
    }  // namespace

    MotionBounds::MotionBounds(ManipulationModelPtr model) : model_(std::move(model))
    {
        const RobotModel &robot = model_->robot();
        std::vector<double> zero(robot.dof(), 0.0);
        std::vector<Eigen::Isometry3d> frames;
        robot.forwardKinematics(zero.data(), model_->scene().robot.basePose, frames);

        levers_.resize(robot.links().size());
        for (std::size_t l = 0; l < robot.links().size(); ++l)
        {
            // up from the link: what lies between each joint and the link's origin
            double length = 0.0;
            std::vector<Lever> chain;
            for (int link = static_cast<int>(l); robot.links()[link].parent >= 0;
                 link = robot.links()[link].parent)
            {
                const int index = robot.links()[link].joint;
                const Joint &joint = robot.joints()[index];
                if (joint.variable >= 0)
                {
                    const bool turns = joint.type != Joint::Type::Prismatic;
                    chain.push_back({index, joint.variable, joint.multiplier, false,
                                     frames[link].linear() * joint.axis, length, turns});
                }
                length += joint.origin.translation().norm() + travelReach(robot, joint);
            }
            // a prismatic joint translates exactly when nothing above it turns
            bool turnsAbove = false;
            for (auto it = chain.rbegin(); it != chain.rend(); ++it)
            {
                it->translates = !it->turns && !turnsAbove;
                turnsAbove = turnsAbove || it->turns;
            }
            levers_[l] = std::move(chain);
        }
    }

    BodySweep MotionBounds::linkSweep(int link, double reach, const double *q1, const double *q2) const
    {
        BodySweep sweep;
        for (const Lever &lever : levers_[link])
        {
            const double change = lever.gain * (q2[lever.variable] - q1[lever.variable]);
            if (lever.translates)
                sweep.translation += change * lever.axis;
            else
                sweep.spread += std::abs(change) * (lever.turns ? lever.length + reach : 1.0);
        }
        return sweep;
    }

    double MotionBounds::relativeRate(int linkA, double reachA, int linkB, double reachB, const double *q1,
                                      const double *q2) const
    {
        const auto below = [&](int link, double reach, int other)
        {
            double rate = 0.0;
            for (const Lever &lever : levers_[link])
            {
                bool shared = false;
                for (const Lever &above : levers_[other])
                    shared = shared || above.joint == lever.joint;
                if (!shared)
                    rate += std::abs(lever.gain * (q2[lever.variable] - q1[lever.variable])) *
                            (lever.turns ? lever.length + reach : 1.0);
            }
            return rate;
        };
        return below(linkA, reachA, linkB) + below(linkB, reachB, linkA);
    }

    BodySweep MotionBounds::slideSweep(const ObjectPose &from, const ObjectPose &to, double radius)
    {
        return {to.position - from.position, yawTurn(from.yaw, to.yaw) * radius};
    }

    BodySweep MotionBounds::carriedSweep(const ObjectPose &from, const ObjectPose &to, double radius,
                                         const double *q1, const double *q2) const
    {
        // the object's points lie within `grasp reach` of the tool link's origin at both ends and,
        // the grasp moving linearly, everywhere between them
        const int toolLink = model_->toolLink();
        const Eigen::Isometry3d tool1 =
            model_->robot().linkFrame(q1, model_->scene().robot.basePose, toolLink);
        const Eigen::Isometry3d tool2 =
            model_->robot().linkFrame(q2, model_->scene().robot.basePose, toolLink);
        const Eigen::Isometry3d grasp1 = tool1.inverse() * from.frame();
        const Eigen::Isometry3d grasp2 = tool2.inverse() * to.frame();
        const double graspReach = std::max(grasp1.translation().norm(), grasp2.translation().norm()) + radius;
        BodySweep sweep = linkSweep(toolLink, graspReach, q1, q2);
        // and the grasp itself moves: its translation, and its turn about the object's centre
        const double graspTurn = Eigen::AngleAxisd(grasp1.linear().transpose() * grasp2.linear()).angle();
        sweep.spread += (grasp2.translation() - grasp1.translation()).norm() + graspTurn * graspReach;
        return sweep;
    }
}  // namespace ompl_mm
