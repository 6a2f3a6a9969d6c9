#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace ompl_phys
{
    /** One move of a control path: a constant force applied for a whole number of propagation steps. */
    struct RobotMove
    {
        /** force applied on average over the move, N, world frame: the control's force, unless the
            robot's drive held it back at the speed limit (simulatePath) */
        Eigen::Vector3d force{Eigen::Vector3d::Zero()};
        std::size_t steps{0};  ///< duration in propagation steps (>= 1)
    };

    /** The robot centre sampled every stepDuration seconds along a control path. */
    struct RobotTrajectory
    {
        double stepDuration{0.0};                ///< s between samples, > 0
        std::vector<Eigen::Vector3d> positions;  ///< world frame, m; [0] at t = 0; size = 1 + total steps
        std::vector<RobotMove> moves;            ///< in order; sum of steps = positions.size() - 1
    };

    /** Quality measures of a physics-based pushing solution: action, power and smoothness of the
        robot trajectory, as defined by the physics-based planning benchmark of Muhayyuddin, Akbari
        and Rosell (below) and computed by computeTrajectoryMetrics(), which gives the formulas.
        They follow the paper's equations 1–4 as printed, not its platform's code, so they compare
        with each other but not with the paper's tables. They are computed from the robot centre
        sampled at the propagation resolution and from the control path split into moves (constant
        force for a whole number of propagation steps). See docs/metrics.md.

        @par External documentation
        Muhayyuddin, A. Akbari, J. Rosell, "Physics-based Motion Planning: Evaluation Criteria and
        Benchmarking", ROBOT 2015: Second Iberian Robotics Conference, Advances in Intelligent
        Systems and Computing vol. 417, Springer, 2016, pp. 43–55, DOI 10.1007/978-3-319-27146-0_4. */
    struct TrajectoryMetrics
    {
        double action{0.0};      ///< effort weighted by covered distance, N·s·m; lower is better
        double power{0.0};       ///< sum of the moves' mean mechanical powers, W
        double smoothness{0.0};  ///< integrated squared jerk of the robot centre, m²/s⁵; lower is smoother
    };

    /** The paper's equations, implemented as written, on a trajectory with n steps of h seconds
        (samples p_0 … p_n, duration T = n·h). Move i spans samples [a_i, b_i] and lasts
        Δt_i = (b_i − a_i)·h.

        - Action A = Σ_i ‖f_i‖ · Δt_i · ε_i, where ε_i = Σ_{k=a_i}^{b_i−1} ‖p_{k+1} − p_k‖ is the
          distance the centre covered during the move (length of the sampled polyline). A depends
          on how the motion is split into moves: splitting a move lowers Δt_i per piece.
        - Power P = Σ_i f_i · (p_{b_i} − p_{a_i}) / Δt_i (a sum of per-move mean powers, as the paper
          writes it; negative when the force opposes the displacement).
        - Smoothness S = ∫ ‖j(t)‖² dt with the jerk from third differences of the samples,
          j_k = (p_{k+3} − 3 p_{k+2} + 3 p_{k+1} − p_k) / h³ for k = 0 … n−3 (exact for cubics).
          Rule: S = T · mean_k ‖j_k‖² = (n / (n − 2)) · Σ_k ‖j_k‖² · h, so the n − 2 differences
          stand for the whole duration and a constant jerk J gives exactly ‖J‖² T. With fewer than
          4 samples (n < 3) jerk is not measurable and S = 0. For smooth motion the differences,
          centred in [1.5h, T − 1.5h], make S first-order accurate in h.

        Limits of S: a piecewise-constant force makes the acceleration jump between moves, so the
        true jerk is a sum of Dirac impulses and ∫ ‖j‖² dt is infinite. The discrete S grows like
        1/h (a jump Δa of the acceleration at a sample adds about ‖Δa‖² / (2h)); it is only
        comparable between paths sampled at the same step. That is why the step is fixed: the
        propagation step, PlanningLimits::stepSize, 0.07 s by default.

        @throws std::invalid_argument, with a message naming the field and its value, when
            stepDuration is not finite or <= 0, positions is empty, a move has 0 steps, the steps
            of the moves do not add up to positions.size() - 1, or a position or force is not
            finite. */
    TrajectoryMetrics computeTrajectoryMetrics(const RobotTrajectory &trajectory);
}  // namespace ompl_phys
