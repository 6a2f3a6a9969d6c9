#pragma once

#include "ompl_mm/robot/KinematicChain.h"

#include <ompl/util/RandomNumbers.h>

#include <Eigen/Geometry>

#include <cstdint>
#include <functional>
#include <memory>

namespace ompl_mm
{
    /** Which parts of a tool pose inverse kinematics must reach. */
    enum class IkTask
    {
        Pose6D,         ///< position and orientation
        Pose5DFreeYaw,  ///< position and orientation up to a rotation about the world's vertical
                        ///< (grasps of upright objects)
        Position3D,     ///< position only
    };

    /** Where inverse kinematics may look for a solution. */
    enum class IkScope
    {
        Anywhere,  ///< from the seed, then from random joint values (the solver's restarts)
        NearSeed,  ///< from the seed alone: for short moves, whose solution must stay close to it
    };

    /** Inverse kinematics of one kinematic chain, as the manipulation primitives and MOPL's
        sampling ask for it: joint values that put the chain's tool frame at a target. IkSolver is
        the built-in implementation; derive from this class to plug in another solver
        (PrimitiveFactory::setInverseKinematics). Every solve() is timed, so planners can report
        the time spent in inverse kinematics whatever the solver. One instance per thread. */
    class InverseKinematics
    {
    public:
        /** Subclasses are destroyed through this base. */
        virtual ~InverseKinematics() = default;

        /** Finds joint values that put the tool at target for task, starting from the chain's
            values in q (the whole robot's joint vector; other joints are left as they are).
            @returns true with q holding a solution within the joint limits and the solver's
            tolerance; false with q unchanged. rng draws any random restarts; scope NearSeed asks for
            none (a solution close to q or none). */
        bool solve(const Eigen::Isometry3d &target, IkTask task, double *q, ompl::RNG &rng,
                   IkScope scope = IkScope::Anywhere);

        /** The chain solved for. */
        virtual const KinematicChain &chain() const = 0;

        /** Seconds spent in solve() since construction or resetStatistics(). */
        double time() const { return time_; }
        /** Calls of solve() since construction or resetStatistics(). */
        std::uint64_t calls() const { return calls_; }
        /** Those calls that found a solution. */
        std::uint64_t solved() const { return solved_; }
        /** Sets the time and the counts to 0. */
        void resetStatistics() { time_ = 0.0, calls_ = solved_ = 0; }

    protected:
        /** The solver's work for solve(), untimed; the same contract. */
        virtual bool search(const Eigen::Isometry3d &target, IkTask task, double *q, ompl::RNG &rng,
                            IkScope scope) = 0;

    private:
        double time_{0.0};
        std::uint64_t calls_{0};
        std::uint64_t solved_{0};
    };

    /** Makes an inverse kinematics solver for a chain whose robot root sits at base (world frame). */
    using InverseKinematicsFactory = std::function<std::unique_ptr<InverseKinematics>(
        const KinematicChain &chain, const Eigen::Isometry3d &base)>;
}  // namespace ompl_mm
