#include "ompl_mm/collision/MotionBounds.h"

#include <algorithm>
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
                    chain.push_back({index, link, joint.variable, joint.multiplier, false,
                                     frames[link].linear() * joint.axis, length, turns, joint.axis,
                                     turns ? 1.0 : 0.0});
                }
                length += joint.origin.translation().norm() + travelReach(robot, joint);
            }
            // a prismatic joint translates exactly when nothing above it turns
            bool turnsAbove = false;
            for (auto it = chain.rbegin(); it != chain.rend(); ++it)
            {
                it->translates = !it->turns && !turnsAbove;
                if (it->turns && !turnsAbove)  // its axis keeps its direction in the world
                    it->tilt = it->axis.normalized().cross(Eigen::Vector3d::UnitZ()).norm();
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
                sweep.spread += leverSpeed(lever, reach, q1, q2);
        }
        return sweep;
    }

    double MotionBounds::relativeRate(int linkA, double reachA, int linkB, double reachB, const double *q1,
                                      const double *q2) const
    {
        const auto below = [&](int link, double reach, int other)
        {
            double rate = 0.0;
            for (std::size_t j = 0; j < ownLevers(link, other); ++j)
                rate += leverSpeed(levers_[link][j], reach, q1, q2);
            return rate;
        };
        return below(linkA, reachA, linkB) + below(linkB, reachB, linkA);
    }

    std::size_t MotionBounds::ownLevers(int link, int relativeTo) const
    {
        const std::vector<Lever> &levers = levers_[link];
        if (relativeTo < 0)
            return levers.size();
        // the joints above both are the last of the link's levers
        const auto shared = [&](const Lever &lever)
        {
            return std::any_of(levers_[relativeTo].begin(), levers_[relativeTo].end(),
                               [&lever](const Lever &above) { return above.joint == lever.joint; });
        };
        return static_cast<std::size_t>(std::find_if(levers.begin(), levers.end(), shared) - levers.begin());
    }

    double MotionBounds::leverSpeed(const Lever &lever, double reach, const double *q1, const double *q2)
    {
        return std::abs(lever.gain * (q2[lever.variable] - q1[lever.variable])) *
               (lever.turns ? lever.length + reach : 1.0);
    }

    BodyVelocity MotionBounds::linkVelocity(int link, const std::vector<Eigen::Isometry3d> &frames,
                                            const double *q1, const double *q2, int relativeTo) const
    {
        BodyVelocity velocity;
        const Eigen::Vector3d &origin = frames[link].translation();
        const std::size_t moving = ownLevers(link, relativeTo);
        for (std::size_t j = 0; j < moving; ++j)
        {
            const Lever &lever = levers_[link][j];
            const double rate = lever.gain * (q2[lever.variable] - q1[lever.variable]);
            const Eigen::Isometry3d &joint = frames[lever.child];
            const Eigen::Vector3d axis = joint.linear() * lever.localAxis;
            if (lever.turns)
            {
                velocity.angular += rate * axis;
                velocity.linear += rate * axis.cross(origin - joint.translation());
            }
            else
                velocity.linear += rate * axis;
        }
        return velocity;
    }

    double MotionBounds::linkAcceleration(int link, double reach, const double *q1, const double *q2,
                                          int relativeTo) const
    {
        // levers_ runs up from the link: lever j's axis turns with the turning joints after it (their
        // rates summed in turnAbove), and the link's points move relative to its origin by the
        // joints up to it (their speeds summed in below)
        const std::vector<Lever> &levers = levers_[link];
        const std::size_t count = ownLevers(link, relativeTo);
        double below = 0.0;
        for (std::size_t j = 0; j < count; ++j)
            below += leverSpeed(levers[j], reach, q1, q2);
        double acceleration = 0.0;
        double turnAbove = 0.0;
        for (std::size_t j = count; j-- > 0;)
        {
            const Lever &lever = levers[j];
            const double rate = std::abs(lever.gain * (q2[lever.variable] - q1[lever.variable]));
            // a turning joint: its axis turns (turnAbove * lever) and the point's offset from it
            // changes (turnAbove * lever + below); a sliding joint: its axis turns
            acceleration +=
                lever.turns ? rate * (2.0 * turnAbove * (lever.length + reach) + below) : rate * turnAbove;
            below -= leverSpeed(lever, reach, q1, q2);
            if (lever.turns)
                turnAbove += rate;
        }
        return acceleration;
    }

    BodySweep MotionBounds::slideSweep(const ObjectPose &from, const ObjectPose &to, double radius)
    {
        return {to.position - from.position, yawTurn(from.yaw, to.yaw) * radius};
    }

    MotionBounds::CarriedGrasp MotionBounds::carriedGrasp(const ObjectPose &from, const ObjectPose &to,
                                                          double radius, const double *q1,
                                                          const double *q2) const
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
        CarriedGrasp grasp;
        grasp.centre = std::max(grasp1.translation().norm(), grasp2.translation().norm());
        grasp.shift = (grasp2.translation() - grasp1.translation()).norm();
        grasp.reach = grasp.centre + radius;
        // the grasp itself moves: its translation, and its turn about the object's centre
        const double graspTurn = Eigen::AngleAxisd(grasp1.linear().transpose() * grasp2.linear()).angle();
        grasp.change = grasp.shift + graspTurn * grasp.reach;
        return grasp;
    }

    BodySweep MotionBounds::carriedSweep(const CarriedGrasp &grasp, const double *q1, const double *q2) const
    {
        BodySweep sweep = linkSweep(model_->toolLink(), grasp.reach, q1, q2);
        sweep.spread += grasp.change;
        return sweep;
    }

    double MotionBounds::carriedRelativeRate(int link, double reach, const CarriedGrasp &grasp,
                                             double objectReach, const double *q1, const double *q2) const
    {
        const int toolLink = model_->toolLink();
        double tilt = 0.0;  // of the joints above both
        const std::vector<Lever> &levers = levers_[link];
        for (std::size_t j = ownLevers(link, toolLink); j < levers.size(); ++j)
            tilt +=
                std::abs(levers[j].gain * (q2[levers[j].variable] - q1[levers[j].variable])) * levers[j].tilt;
        return relativeRate(link, reach, toolLink, grasp.centre, q1, q2) + grasp.shift + tilt * objectReach;
    }
}  // namespace ompl_mm
