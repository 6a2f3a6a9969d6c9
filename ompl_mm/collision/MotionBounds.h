#pragma once

#include "ompl_mm/model/ManipulationModel.h"

#include <Eigen/Geometry>

#include <vector>

namespace ompl_mm
{
    /** How far the points of a body move along a motion: between fractions t1 < t2 of the way,
        each point moves by (t2 - t1) * translation plus at most (t2 - t1) * spread in any direction.
        Two bodies' distance thus changes by at most (t2 - t1) * (|translation difference| + both
        spreads), which is what continuous collision checking steps by. */
    struct BodySweep
    {
        Eigen::Vector3d translation{Eigen::Vector3d::Zero()};  ///< shared by every point, metres
        double spread{0.0};                                    ///< the rest, metres
    };

    /** How a body moves at one instant of a motion, per unit of the motion's fraction: the velocity
        of its frame's origin and its angular velocity. */
    struct BodyVelocity
    {
        Eigen::Vector3d linear{Eigen::Vector3d::Zero()};   ///< metres per fraction
        Eigen::Vector3d angular{Eigen::Vector3d::Zero()};  ///< radians per fraction
    };

    /** Bounds on the motion of bodies when the robot's joints move linearly (as the state space
        interpolates them) and objects either slide (position linear, yaw the short way) or are
        carried with the tool. A prismatic joint with no turning joint above it translates its
        subtree exactly along a fixed world axis (mobile bases, so that a robot and the object it
        pushes share their translation); every other joint adds the displacement of its farthest
        point: the joint's travel, or its angle times a lever, an upper bound on the distance from
        the joint to the point whatever the joints between them do. Immutable; shares the model. */
    class MotionBounds
    {
    public:
        /** Precomputes the levers of every link. */
        explicit MotionBounds(ManipulationModelPtr model);

        /** Sweep of the points within `reach` of the origin of `link` when the joints move from q1
            to q2 (each of size dof()). */
        BodySweep linkSweep(int link, double reach, const double *q1, const double *q2) const;

        /** Bound on how much the distance between points within `reachA` of the origin of linkA
            and points within `reachB` of the origin of linkB changes when the joints move from q1
            to q2: only the joints between the two links count, since the joints above both move
            them together (so a wrist and a forearm far from the base stay close to each other
            however far the arm swings). */
        double relativeRate(int linkA, double reachA, int linkB, double reachB, const double *q1,
                            const double *q2) const;

        /** The velocity of link at the instant of the motion from q1 to q2 whose link frames
            (RobotModel::forwardKinematics) are `frames`. With relativeTo >= 0, only the joints above
            link that are not above link relativeTo count: its motion seen from their common
            ancestor, which moves both alike. */
        BodyVelocity linkVelocity(int link, const std::vector<Eigen::Isometry3d> &frames, const double *q1,
                                  const double *q2, int relativeTo = -1) const;

        /** Bound on the acceleration (metres per fraction squared) of the points within `reach` of
            the origin of `link` anywhere along the motion from q1 to q2, the joints moving linearly:
            a turning joint's axis turns with the joints above it and its lever changes with the joints
            below it. With relativeTo as for linkVelocity(). With the velocity at one instant it
            bounds the distance a point travels from there: |v| h + acceleration h^2 / 2. */
        double linkAcceleration(int link, double reach, const double *q1, const double *q2,
                                int relativeTo = -1) const;

        /** Sweep of an object of bounding radius `radius` (about its frame's z axis) that slides
            from one pose to another. */
        static BodySweep slideSweep(const ObjectPose &from, const ObjectPose &to, double radius);

        /** How an object carried with the tool moves in the tool link's frame: the reach of its
            points from the link's origin, and how far they move there. */
        struct CarriedGrasp
        {
            double reach{0.0};   ///< metres from the tool link's origin, all along the motion
            double change{0.0};  ///< bound on any point's motion in the tool link's frame, metres
            double centre{0.0};  ///< the object frame's origin from the tool link's origin, metres
            double shift{0.0};   ///< how far that origin moves in the tool link's frame, metres
        };
        /** The grasp of an object of bounding radius `radius` (about its frame, which the poses
            place) carried from one pose to another while the joints move from q1 to q2: the grasp
            (pose in the tool frame) moves linearly between the two ends', as
            ManipulationStateSpace interpolates it. */
        CarriedGrasp carriedGrasp(const ObjectPose &from, const ObjectPose &to, double radius,
                                  const double *q1, const double *q2) const;
        /** Sweep of an object carried with the tool (its grasp from carriedGrasp()). */
        BodySweep carriedSweep(const CarriedGrasp &grasp, const double *q1, const double *q2) const;
        /** Bound on how much the distance between points within `reach` of the origin of link and
            an object that turns freely (Shape::turnsFreely(): a body the same after any turn about
            its frame's vertical axis, its points within objectReach of the frame's origin) carried
            with the tool changes: the object stays upright whatever the tool does, so its frame's
            origin moves relative to the link as relativeRate() between the link and the tool link
            says, plus the grasp's shift, and the object turns relative to the link only as far as
            the joints above both tilt it (a wrist and the cylinder its gripper holds keep their
            distance when the grasp does and the arm only swings about a vertical axis). */
        double carriedRelativeRate(int link, double reach, const CarriedGrasp &grasp, double objectReach,
                                   const double *q1, const double *q2) const;

    private:
        /** A moving joint above a link, and how it moves the link's points. */
        struct Lever
        {
            int joint;             ///< the joint's index in RobotModel::joints()
            int child;             ///< the joint's child link (its frame is the joint's)
            int variable;          ///< the joint's variable (for a mimic joint, its leader's)
            double gain;           ///< the joint's change per change of its variable (a mimic's multiplier)
            bool translates;       ///< a prismatic joint with a fixed world axis
            Eigen::Vector3d axis;  ///< that axis, when it translates
            double length;         ///< for a turning joint: bound on its distance to the link's origin
            bool turns;            ///< revolute or continuous
            Eigen::Vector3d localAxis;  ///< the joint's axis in its child's frame
            /** For a turning joint, how far its turn tilts the vertical: |sin| of its axis to the
                vertical when no turning joint above it turns that axis, else 1; 0 for a sliding one */
            double tilt;
        };
        /** How many of link's levers (from the link up) are not above link relativeTo: the joints
            that move it relative to relativeTo; all of them when relativeTo < 0. */
        std::size_t ownLevers(int link, int relativeTo) const;
        /** How fast the lever's joint moves points within reach of the link's origin. */
        static double leverSpeed(const Lever &lever, double reach, const double *q1, const double *q2);

        ManipulationModelPtr model_;
        std::vector<std::vector<Lever>> levers_;  ///< per link, the moving joints above it
    };
}  // namespace ompl_mm
