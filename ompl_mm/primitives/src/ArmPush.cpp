#include "ompl_mm/primitives/ArmPush.h"

#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>

namespace ompl_mm
{
    namespace
    {

        void requirePositive(double value, const std::string &what)
        {
            if (!(value > 0.0))
                throw ompl::Exception(what + " must be positive, got " + std::to_string(value));
        }
    }  // namespace

    ArmPush::ArmPush(const ManipulationStateSpace *space, std::string name, std::shared_ptr<Grasping> arm,
                     Settings settings)
        : Primitive(space, std::move(name), PrimitiveKind::Push), arm_(std::move(arm)), settings_(settings)
    {
        requirePositive(settings_.standoff, this->name() + " standoff");
        requirePositive(settings_.maxPushDistance, this->name() + " max_push_distance");
        requirePositive(settings_.maxPushJointDistance, this->name() + " max_push_joint_distance");
        if (!(settings_.approachDistance >= 0.0))
            throw ompl::Exception(this->name() + " approach_distance must be at least 0, got " +
                                  std::to_string(settings_.approachDistance));
    }

    Eigen::Isometry3d ArmPush::pushPose(unsigned int object, const ObjectPose &pose,
                                        const Eigen::Vector2d &direction) const
    {
        const double centre = 0.5 * space_->model()->scene().objects[object].shape.height();
        Eigen::Isometry3d tool = Eigen::Isometry3d::Identity();
        tool.translate(pose.position + Eigen::Vector3d(-settings_.standoff * direction.x(),
                                                       -settings_.standoff * direction.y(),
                                                       centre + settings_.heightOffset));
        tool.rotate(Eigen::AngleAxisd(std::atan2(direction.y(), direction.x()) + settings_.inwardTilt,
                                      Eigen::Vector3d::UnitZ()));
        // the approach axis (tool z) from the push direction (x) down by the downward tilt, the
        // fingers' axis (tool x) level across the push before the roll
        tool.rotate(Eigen::AngleAxisd(0.5 * M_PI + settings_.downwardTilt, Eigen::Vector3d::UnitY()));
        tool.rotate(Eigen::AngleAxisd(0.5 * M_PI + settings_.handRoll, Eigen::Vector3d::UnitZ()));
        return tool;
    }

    bool ArmPush::near(const double *q, const Eigen::Isometry3d &pose) const
    {
        const Eigen::Isometry3d tool = space_->model()->toolFrame(q);
        return (tool.translation() - pose.translation()).norm() <= LINE_TOLERANCE &&
               Eigen::AngleAxisd(tool.linear().transpose() * pose.linear()).angle() <= ANGLE_TOLERANCE;
    }

    bool ArmPush::keepsPushPose(const ompl::base::State *a, const ompl::base::State *b, unsigned int object,
                                const Eigen::Vector2d &direction) const
    {
        const unsigned int steps = std::max(1u, space_->validSegmentCount(a, b));
        ompl::base::State *between = space_->allocState();
        bool keeps = true;
        for (unsigned int i = 0; i <= steps && keeps; ++i)
        {
            space_->interpolate(a, b, static_cast<double>(i) / steps, between);
            keeps = near(space_->robotValues(between),
                         pushPose(object, space_->objectPose(between, object), direction));
        }
        space_->freeState(between);
        return keeps;
    }

    bool ArmPush::isUseful(const ompl::base::State *from, const ompl::base::State *to) const
    {
        return pushable(from, to);
    }

    bool ArmPush::appendPush(const ompl::base::State *end, unsigned int object,
                             const Eigen::Vector2d &direction, unsigned int splits,
                             Trajectory &trajectory) const
    {
        const ompl::base::State *start = trajectory.back();
        if (keepsPushPose(start, end, object, direction))
        {
            trajectory.append(end, {PrimitiveKind::Push, static_cast<int>(object)});
            return true;
        }
        if (splits == 0)
            return false;
        // halfway: the object halfway, the hand at its push pose near the joints' midpoint
        ompl::base::State *halfway = space_->allocState();
        space_->interpolate(start, end, 0.5, halfway);
        const bool split =
            arm_->solveToolPose(pushPose(object, space_->objectPose(halfway, object), direction),
                                space_->robotValues(halfway), IkScope::NearSeed) &&
            appendPush(halfway, object, direction, splits - 1, trajectory) &&
            appendPush(end, object, direction, splits - 1, trajectory);
        space_->freeState(halfway);
        return split;
    }

    bool ArmPush::solvePush(const ompl::base::State *from, unsigned int object, const ObjectPose &start,
                            const ObjectPose &end, const Eigen::Vector2d &direction,
                            ompl::base::State *scratch, Grasping::Solution &joints,
                            const ompl::base::PlannerTerminationCondition &ptc) const
    {
        const Eigen::Vector3d up(0.0, 0.0, settings_.approachDistance);
        const Eigen::Vector3d back(-settings_.approachDistance * direction.x(),
                                   -settings_.approachDistance * direction.y(), 0.0);
        const Eigen::Vector3d none = Eigen::Vector3d::Zero();
        // the state with the robot at q and the object at pose is acceptable
        const auto acceptableAt = [&](const std::vector<double> &q, const ObjectPose &pose)
        {
            std::copy(q.begin(), q.end(), space_->robotValues(scratch));
            space_->setObjectPose(scratch, object, pose);
            return acceptable(scratch);
        };
        return arm_->nearestSolution(
            space_->robotValues(from), 1, joints,
            [&](Grasping::Solution &s)
            {
                if (!arm_->solveToolPose(pushPose(object, start, direction), s[0].data()) ||
                    !acceptableAt(s[0], start) || ptc)
                    return false;
                s.resize(4, s[0]);
                if (!arm_->solveShortMove(up, none, s[1].data()) || !acceptableAt(s[1], start) ||
                    !arm_->solveToolPose(pushPose(object, end, direction), s[2].data(), IkScope::NearSeed) ||
                    arm_->jointDistance(s[0].data(), s[2].data()) > settings_.maxPushJointDistance ||
                    !acceptableAt(s[2], end))
                    return false;
                s[3] = s[2];
                return arm_->solveShortMove(back, none, s[3].data()) && acceptableAt(s[3], end);
            },
            ptc);
    }

    bool ArmPush::propagate(const ompl::base::State *from, const ompl::base::State *to,
                            Trajectory &trajectory) const
    {
        return propagate(from, to, trajectory, ompl::base::plannerNonTerminatingCondition());
    }

    bool ArmPush::propagate(const ompl::base::State *from, const ompl::base::State *to,
                            Trajectory &trajectory, const ompl::base::PlannerTerminationCondition &ptc) const
    {
        const int object = nearestSlidingObject(from, to);
        if (object < 0)
            return false;
        const ObjectPose start = space_->objectPose(from, object);
        const Eigen::Vector2d offset = (space_->objectPosition(to, object) - start.position).head<2>();
        const Eigen::Vector2d direction = offset.normalized();
        ObjectPose end = start;
        end.position.head<2>() += std::min(offset.norm(), settings_.maxPushDistance) * direction;
        ompl::base::State *waypoint = space_->cloneState(from);
        Grasping::Solution joints;
        if (!solvePush(from, object, start, end, direction, waypoint, joints, ptc))
        {
            space_->freeState(waypoint);
            return false;
        }

        Trajectory push(space_);
        space_->setObjectPose(waypoint, object, start);
        std::copy(joints[1].begin(), joints[1].end(), space_->robotValues(waypoint));
        push.reset(waypoint);
        std::copy(joints[0].begin(), joints[0].end(), space_->robotValues(waypoint));
        push.append(waypoint, {PrimitiveKind::Transit, -1});
        std::copy(joints[2].begin(), joints[2].end(), space_->robotValues(waypoint));
        space_->setObjectPose(waypoint, object, end);
        const bool straight = appendPush(waypoint, object, direction, MAX_SPLITS, push);
        if (straight)
        {
            std::copy(joints[3].begin(), joints[3].end(), space_->robotValues(waypoint));
            push.append(waypoint, {PrimitiveKind::Transit, -1});
            if (space_->robotMoves(from, push.state(0)))
                trajectory.append(push.state(0), {PrimitiveKind::Transit, -1});
            for (std::size_t i = 1; i < push.size(); ++i)
                trajectory.append(push.state(i), push.label(i - 1));
        }
        space_->freeState(waypoint);
        return straight;
    }

    std::optional<SegmentLabel> ArmPush::explain(const ompl::base::State *from,
                                                 const ompl::base::State *to) const
    {
        const int pushed = onlySlidingObject(from, to);
        if (pushed < 0)
            return std::nullopt;
        const Eigen::Vector2d direction =
            (space_->objectPosition(to, pushed) - space_->objectPosition(from, pushed))
                .head<2>()
                .normalized();
        if (!keepsPushPose(from, to, pushed, direction))
            return std::nullopt;
        return SegmentLabel{PrimitiveKind::Push, pushed};
    }
}  // namespace ompl_mm
