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

        /** Sweep of an object of bounding radius `radius` (about its frame's z axis) that slides
            from one pose to another. */
        static BodySweep slideSweep(const ObjectPose &from, const ObjectPose &to, double radius);

        /** Sweep of an object carried with the tool from one pose to another while the joints move
            from q1 to q2: its grasp (pose in the tool frame) moves linearly between the two ends',
            as ManipulationStateSpace interpolates it. Objects are carried upright. */
        BodySweep carriedSweep(const ObjectPose &from, const ObjectPose &to, double radius, const double *q1,
                               const double *q2) const;

    private:
        /** A moving joint above a link, and how it moves the link's points. */
        struct Lever
        {
            int joint;             ///< the joint's index in RobotModel::joints()
            int variable;          ///< the joint's variable (for a mimic joint, its leader's)
            double gain;           ///< the joint's change per change of its variable (a mimic's multiplier)
            bool translates;       ///< a prismatic joint with a fixed world axis
            Eigen::Vector3d axis;  ///< that axis, when it translates
            double length;         ///< for a turning joint: bound on its distance to the link's origin
            bool turns;            ///< revolute or continuous
        };

        ManipulationModelPtr model_;
        std::vector<std::vector<Lever>> levers_;  ///< per link, the moving joints above it
    };
}  // namespace ompl_mm
