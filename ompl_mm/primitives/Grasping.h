#pragma once

#include "ompl_mm/base/ManipulationStateSpace.h"
#include "ompl_mm/robot/InverseKinematics.h"

#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/util/RandomNumbers.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ompl_mm
{
    /** How an arm grasps upright objects, shared by the primitives that pick up and carry them:
        the tool point at the object's centre, the tool's approach axis (its z, from the wrist
        towards the finger tips) pointing down and tilted by `tilt` about the tool's x axis (the
        axis between the fingers), the rotation about the world vertical left free. It solves the
        inverse kinematics of these poses, and of short moves along them (approach, lift, retreat),
        with one InverseKinematics solver for the chain of the scene's tool point or of a named
        tool frame (whose pose the solver targets; objects are held relative to the tool point).
        Not thread-safe (one solver). */
    class Grasping
    {
    public:
        /** What a grasp is held to. */
        struct Settings
        {
            std::string tool;  ///< tool frame of the scene to solve for; empty: the tool point
            double tilt{0.0};  ///< approach axis from the downward vertical, radians
            double approachDistance{
                0.05};  ///< length of the approach before a grasp and the retreat after a placement, metres
            /** How far below the object's top the tool point grasps, metres (>= 0; deeper than the
                object's height is its base); unset: at the object's centre, or higher when the hand
                comes down over the object (its first shape, handReach() back along the tilted
                approach axis, lies above the object's footprint) and would reach its top: then as
                deep as leaves the hand HAND_MARGIN above the top. */
            std::optional<double> depth;
        };

        /** How far the hand stays clear of what its grasp holds from above: the automatic grasp
            keeps the hand's first shape this far above the object's top, metres. */
        static constexpr double HAND_MARGIN = 0.005;

        /** Grasps in space with settings, solving with a solver made by factory (IkSolver when it
            is empty) for the scene's robot base. @pre space outlives it.
            @throws ompl::Exception when settings.tool names no tool frame of the scene or the
            approach distance is negative. */
        Grasping(const ManipulationStateSpace *space, Settings settings,
                 const InverseKinematicsFactory &factory);

        /** The settings in force. */
        const Settings &settings() const { return settings_; }

        /** How far behind the tool point, back along its approach axis (tool -z), the hand's first
            collision shape begins, metres (the palm of a parallel gripper between its open
            fingers): the deepest an object's top can reach into the hand. The hand is the tool link
            and the links fixed to it (fixed joints, and joints the scene holds); meshes count as
            their convex hulls. Infinity when no shape lies on that line within MAX_HAND_REACH. */
        double handReach() const;
        /** How far handReach() looks, metres. */
        static constexpr double MAX_HAND_REACH = 0.5;
        /** The height above the object's base at which the tool point grasps it, metres (see
            Settings::depth). */
        double graspHeight(unsigned int object) const;
        /** The solver (its statistics tell the time spent). */
        const InverseKinematics &inverseKinematics() const { return *ik_; }

        /** Sets q (the robot's joints, also the seed) so that the tool grasps the object at pose:
            IK of the grasp pose with the yaw free. False, q unchanged, when no solution is found. */
        bool solveGrasp(unsigned int object, const ObjectPose &pose, double *q);
        /** Sets the solver chain's joints in q to random values within their limits (a seed for
            another solution). */
        void randomizeChain(double *q);
        /** Sets q (also the seed) so that the solver's frame ends at its pose for q moved by
            `offset` (world frame, applied after) and `local` (its own frame, applied before): full 6-D
            IK of a short move. False, q unchanged, when no solution is found or when it is not
            short: some joint would turn more than MAX_SHORT_MOVE (so that the straight joint motion
            stays close to the straight tool motion). */
        bool solveShortMove(const Eigen::Vector3d &offset, const Eigen::Vector3d &local, double *q);
        /** Sets q (also the seed) so that the tool point reaches `tool` (world frame), position and
            orientation: full 6-D IK, looking as far as `scope` allows. False, q unchanged, when no
            solution is found. */
        bool solveToolPose(const Eigen::Isometry3d &tool, double *q, IkScope scope = IkScope::Anywhere);
        /** Sets q (also the seed) so that an object held in the tool by `grasp` (its frame in the
            tool point's frame) comes to `target` (its yaw free). False, q unchanged, when no
            solution is found. */
        bool solveCarry(const Eigen::Isometry3d &grasp, const ObjectPose &target, double *q);

        /** Solutions tried by the primitives (the first seeded from the robot's joints, the others
            from random joints) until one lets the short moves around it (approach, lift, retreat)
            be short. */
        static constexpr unsigned int ATTEMPTS = 5;
        /** Solutions with short moves compared (of ATTEMPTS): the one nearest to the robot's joints
            is kept, so that the arm does not swing far round to reach what is close. */
        static constexpr unsigned int CANDIDATES = 2;
        /** Euclidean distance between two joint vectors of the robot, radians or metres. */
        double jointDistance(const double *a, const double *b) const;

        /** The joint vectors of one solution of a primitive (e.g. grasp, approach, lift). */
        using Solution = std::vector<std::vector<double>>;
        /** Solves from the robot's joints `start`, then from random joints, ATTEMPTS times at most,
            until CANDIDATES attempts succeed or ptc is true, and keeps in best the success whose
            joint vector number `compared` is nearest to start. solve gets a solution whose vector 0
            holds the seed, fills it in and says whether it succeeded. False, best unchanged, when
            none did. */
        bool nearestSolution(const double *start, std::size_t compared, Solution &best,
                             const std::function<bool(Solution &)> &solve,
                             const ompl::base::PlannerTerminationCondition &ptc =
                                 ompl::base::plannerNonTerminatingCondition());
        /** The most a joint may turn in a short move, radians or metres. */
        static constexpr double MAX_SHORT_MOVE = 0.5;

        /** The pose of an object held in the tool: its frame relative to the tool, `grasp`, moved
            with the tool to toolFrame; the yaw kept from `yaw` when the object turns freely. */
        ObjectPose heldPose(unsigned int object, const Eigen::Isometry3d &toolFrame,
                            const Eigen::Isometry3d &grasp, double yaw) const;
        /** True when the object is held the same way in a and b: its base centre (and, unless it
            turns freely, its yaw) the same in the tool frame, within GRASP_TOLERANCE. */
        static bool sameGrasp(const ManipulationStateSpace &space, const ompl::base::State *a,
                              const ompl::base::State *b, unsigned int object);
        /** Largest difference between two grasps that counts as the same, metres or radians: the
            inverse kinematics' tolerance and some rounding. */
        static constexpr double GRASP_TOLERANCE = 1e-4;

    private:
        /** Measures handReach(). */
        double measureHandReach() const;
        /** The solver's frame relative to the tool point at joints q. */
        Eigen::Isometry3d solvedInTool(const double *q) const;
        /** Solves for the solver's frame at target from seed q, into q when found. */
        bool solve(const Eigen::Isometry3d &target, IkTask task, double *q,
                   IkScope scope = IkScope::Anywhere);

        const ManipulationStateSpace *space_;
        Settings settings_;
        /** handReach(), measured on its first use: only a pickup's grasps need it. */
        mutable std::optional<double> handReach_;
        std::unique_ptr<InverseKinematics> ik_;
        std::vector<double> work_;
        ompl::RNG rng_;
    };
}  // namespace ompl_mm
