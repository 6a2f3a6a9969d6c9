#pragma once

#include "ompl_mm/robot/InverseKinematics.h"

#include <ompl/base/GenericParam.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <chrono>
#include <optional>
#include <vector>

namespace ompl_mm
{
    /** Inverse kinematics of a kinematic chain by damped least squares: each iteration steps the
        chain's joints by J^T (J J^T + lambda^2 I)^-1 e towards the target (e: the task's position
        and rotation error, world frame; lambda = damping * min(1, |e|)), plus, far from the target,
        a null-space step towards the middle of the joint ranges, capped at maxStep per joint and
        clamped to the limits (continuous joints wrap).
        When an attempt has not converged after `iterations`, it restarts from random joint values
        within the limits, at most `restarts` times and within `timeLimit`; an attempt also gives up
        once it is stuck (its error still at least 90 % of what it was `stallIterations` iterations
        before: held at a joint limit, or circling). Deterministic for a given random generator
        state. Holds its own work space, so the hot path allocates nothing; use one solver per
        thread. Its parameters are declared (params()): ik_tolerance, ik_iterations, ik_restarts,
        ik_damping, ik_time_limit, ik_any_yaw, ik_stall_iterations. */
    class IkSolver : public InverseKinematics
    {
    public:
        /** Solves for chain's tool frame, the robot's root at base. */
        IkSolver(KinematicChain chain, const Eigen::Isometry3d &base);

        /** The task error of the chain's values in q: position and rotation error vector (world
            frame; radians about each axis), for Pose5DFreeYaw without the rotation about the
            world vertical (and, with anyYaw, measured against the target turned about the vertical
            to the chain's nearest yaw), for Position3D without the rotation. */
        double error(const Eigen::Isometry3d &target, IkTask task, const double *q) const;

        /** InverseKinematics' hook: the chain solved for. */
        const KinematicChain &chain() const override { return chain_; }

        /** Largest error that counts as reached (metres and radians together); 1e-5 by default. */
        double tolerance{1e-5};
        /** Iterations of one attempt; 20 by default: an attempt that has not converged by then
            seldom does, and a restart is cheaper (benchmarks/bench_ik). */
        unsigned int iterations{20};
        /** Attempts from random joint values after the first; 100 by default. */
        unsigned int restarts{100};
        /** Iterations over which the error of an attempt must fall by a tenth, else the attempt
            gives up (0: never); 8 by default: on targets out of reach such attempts then cost a few
            iterations instead of all of them, and few that would have converged are given up
            (benchmarks/bench_ik, --stall). The attempt from the seed too: of the seed attempts cut
            short this way while planning the arm scenes, 97 % (MEKA CLEAN-UP) to over 99 % (KUKA
            TABLE, KUKA CABINET) would not have converged in all their iterations either. */
        unsigned int stallIterations{8};
        /** Damping of the least-squares step while the error is 1 or more; it shrinks with the error
            (damping times the error), so steps are steady far from the target and converge fast
            close to it. 0.1 by default (benchmarks/bench_ik). */
        double damping{0.1};
        /** Largest change of a joint in one iteration, radians or metres; 30 deg by default. */
        double maxStep{0.5235987755982988};
        /** Gain of the step towards the middle of the joint ranges within the null space. */
        double postureGain{0.05};
        /** Seconds a solve may take; infinite by default. */
        double timeLimit{1e300};
        /** Time limits from this many seconds on are none: the solver then reads no clock. */
        static constexpr double NO_TIME_LIMIT = 1e9;
        /** How Pose5DFreeYaw treats the free yaw. False (the default): the error keeps the
            target's yaw, whose pull on the other axes favours solutions near it but makes an
            attempt diverge that starts more than about a quarter turn away; restarts then find a
            solution near the target's yaw. True: the error is measured against the target turned
            to the yaw nearest to the chain's, so an attempt converges to whatever yaw is nearest
            to where it starts (arms that must reach round, or grasp from any side). */
        bool anyYaw{false};

        /** The declared parameters (OMPL's ParamSet): ik_tolerance, ik_iterations, ik_restarts,
            ik_damping, ik_time_limit, ik_any_yaw, ik_stall_iterations, with their ranges. */
        ompl::base::ParamSet &params() { return params_; }

        /** Iterations the last solve() took, over all attempts. */
        unsigned int lastIterations() const { return lastIterations_; }

    protected:
        /** InverseKinematics' hook: damped least squares from q's values, then, for scope Anywhere,
            from random values (`restarts` times, within timeLimit); a solution is within tolerance. */
        bool search(const Eigen::Isometry3d &target, IkTask task, double *q, ompl::RNG &rng,
                    IkScope scope) override;

    private:
        using Vector6d = Eigen::Matrix<double, 6, 1>;

        /** The 6-vector error (position, rotation) of tool pose current, masked for task. */
        Vector6d taskError(const Eigen::Isometry3d &target, const Eigen::Isometry3d &current,
                           IkTask task) const;

        /** One attempt from the chain's values in work_ (the seed's, or random ones after a restart),
            until end if any; true when it converged. */
        bool attempt(const Eigen::Isometry3d &target, IkTask task,
                     const std::optional<std::chrono::steady_clock::time_point> &end);

        KinematicChain chain_;
        Eigen::Isometry3d base_;
        ompl::base::ParamSet params_;
        unsigned int lastIterations_{0};
        // work space, sized once
        std::vector<double> work_;  ///< the whole robot's joint vector being solved
        Eigen::Matrix<double, 6, Eigen::Dynamic> jacobian_;
        Eigen::VectorXd step_, posture_;
        std::vector<double> recentErrors_;  ///< the last stallIterations errors of an attempt
    };
}  // namespace ompl_mm
