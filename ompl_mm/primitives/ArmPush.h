#pragma once

#include "ompl_mm/primitives/Grasping.h"
#include "ompl_mm/primitives/Primitive.h"

#include <memory>
#include <string>

namespace ompl_mm
{
    /** An arm pushes one object in a straight line across its support surface (MOPL paper,
        section IV-C: Push-Interior, Push-Exterior and Push-Frontal are this primitive with
        different hand poses). While pushing, the tool point keeps its push pose: `standoff` behind
        the object's axis against the push direction, `heightOffset` above the object's centre,
        its approach axis (tool z) along the push direction tilted down by `downwardTilt`, turned by
        `handRoll` about that axis from where the axis between the fingers (tool x) lies level
        across the push (fingers side by side, the hand's face, tool y, towards the object; a half
        turn pushes with the back of the hand), and the whole hand turned by `inwardTilt` about the
        world vertical. Each push moves the object at
        most `maxPushDistance`; full 6-D inverse kinematics places the hand at the push's start
        and end, and the joint-space motion between them, split where needed, keeps the tool
        within LINE_TOLERANCE of the straight push line at every step of the connect resolution,
        so the object moves with the tool. The hand comes down to the push start from
        `approachDistance` above it and backs away by as much after the push. */
    class ArmPush : public Primitive
    {
    public:
        /** The hand's pose and the limits of one push. */
        struct Settings
        {
            double standoff{0.14};  ///< horizontal distance from the object's axis to the tool point, metres
            double heightOffset{0.0};             ///< tool point height above the object's centre, metres
            double inwardTilt{0.0};               ///< turn of the hand about the world vertical, radians
            double downwardTilt{0.0};             ///< approach axis below the horizontal, radians
            double handRoll{0.0};                 ///< turn of the hand about its approach axis, radians
            double maxPushDistance{0.1};          ///< longest push, metres
            double maxPushJointDistance{0.5236};  ///< longest joint-space motion of a push, radians
            double approachDistance{0.05};  ///< height of the approach and length of the retreat, metres
        };

        /** Largest distance of the tool point from its push pose along a push, metres. */
        static constexpr double LINE_TOLERANCE = 0.005;
        /** Largest angle between the hand and its push pose along a push, radians. */
        static constexpr double ANGLE_TOLERANCE = 0.05;
        /** Most times a push is halved to keep the tool on its line. */
        static constexpr unsigned int MAX_SPLITS = 3;

        /** A push primitive called name in space, solving its inverse kinematics with `arm`
            (whose grasp settings it does not use). @pre space outlives the primitive.
            @throws ompl::Exception when a distance is not positive (the standoff, the push
            distances) or the approach distance is negative. */
        ArmPush(const ManipulationStateSpace *space, std::string name, std::shared_ptr<Grasping> arm,
                Settings settings);

        /** Primitive's hook: useful when every object rests in both states and some object moves
            in the plane at constant height. */
        bool isUseful(const ompl::base::State *from, const ompl::base::State *to) const override;
        /** Primitive's hook: pushes the sliding object nearest to the tool towards its target x, y,
            at most maxPushDistance: a transit above the push start (left out when the robot is
            there), a transit down to it, push segments, and a transit backing away. False when none
            of Grasping::ATTEMPTS solutions reaches both ends of the push within
            maxPushJointDistance and keeps the tool on the line. */
        bool propagate(const ompl::base::State *from, const ompl::base::State *to,
                       Trajectory &trajectory) const override;
        /** Primitive's hook: as above, but stops searching soon after ptc becomes true (between
            inverse kinematics solves): then false, nothing appended, unless a solution was found. */
        bool propagate(const ompl::base::State *from, const ompl::base::State *to, Trajectory &trajectory,
                       const ompl::base::PlannerTerminationCondition &ptc) const override;
        /** Primitive's hook: a push segment when every object rests at both ends, exactly one
            slides (x, y only, its yaw kept), and the tool keeps this primitive's push pose for it
            (within LINE_TOLERANCE and ANGLE_TOLERANCE) at both ends and at every step of the
            connect resolution in between. */
        std::optional<SegmentLabel> explain(const ompl::base::State *from,
                                            const ompl::base::State *to) const override;
        /** Primitive's hook: the time of the push's inverse kinematics. */
        double inverseKinematicsTime() const override { return arm_->inverseKinematics().time(); }

        /** The tool point's frame (world) that pushes the object, at pose, in direction (a unit
            vector in the plane). */
        Eigen::Isometry3d pushPose(unsigned int object, const ObjectPose &pose,
                                   const Eigen::Vector2d &direction) const;

        /** The settings in force. */
        const Settings &settings() const { return settings_; }

    private:
        /** True when the tool keeps its push pose for the object along the motion from a to b
            (which pushes it in direction), checked at both ends and every step of the connect
            resolution. */
        bool keepsPushPose(const ompl::base::State *a, const ompl::base::State *b, unsigned int object,
                           const Eigen::Vector2d &direction) const;
        /** True when the tool point's frame at joints q is within the tolerances of pose. */
        bool near(const double *q, const Eigen::Isometry3d &pose) const;
        /** Finds, with the push's inverse kinematics, the joints of the push from `start` to `end`
            (the object pushed in direction; the rest of the world as in `from`): joints[0] at the
            push start, [1] approachDistance above it, [2] at the push end, [3] backed away from
            it, the approach nearest to from's joints, every state acceptable. scratch is a state
            to work in. False when none of Grasping::ATTEMPTS solutions has them all, or when ptc
            became true before one had. */
        bool solvePush(const ompl::base::State *from, unsigned int object, const ObjectPose &start,
                       const ObjectPose &end, const Eigen::Vector2d &direction, ompl::base::State *scratch,
                       Grasping::Solution &joints, const ompl::base::PlannerTerminationCondition &ptc) const;
        /** Appends push segments from trajectory.back() to `end` (the object pushed there in
            direction): one when the tool keeps its push pose, else two halves through the push
            pose halfway, found by inverse kinematics near the joints' midpoint, each again split at
            most `splits` times. False when no split keeps the pose; the trajectory may then hold
            some of the halves, so it should be a scratch one. */
        bool appendPush(const ompl::base::State *end, unsigned int object, const Eigen::Vector2d &direction,
                        unsigned int splits, Trajectory &trajectory) const;

        std::shared_ptr<Grasping> arm_;
        Settings settings_;
    };
}  // namespace ompl_mm
