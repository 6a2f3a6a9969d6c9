#include "ompl_mm/robot/IkSolver.h"

#include <Eigen/Cholesky>

#include <cmath>

namespace ompl_mm
{
    namespace
    {
        constexpr double PI = 3.14159265358979323846;
        /** Below this task error the step no longer pulls towards the middle of the joint ranges. */
        constexpr double POSTURE_ERROR = 1e-3;
        /** An attempt whose error is still this share of what it was stallIterations before is stuck. */
        constexpr double STALL_RATIO = 0.9;

        double wrapAngle(double angle)
        {
            return std::remainder(angle, 2.0 * PI);
        }

        /** Overwrites x with the solution y of m y = x, m symmetric, by Cholesky (m = L L^T);
            false when m is not positive definite (x then partly overwritten). Written out for the
            fixed size: Eigen's LLT factors through dynamic-size blocks, which took a sixth of the
            IK's time on the Meka-like arm. */
        bool choleskySolve(Eigen::Matrix<double, 6, 6> m, Eigen::Matrix<double, 6, 1> &x)
        {
            Eigen::Matrix<double, 6, 1> inverseDiagonal;  // of L: one division per row
            for (int j = 0; j < 6; ++j)
            {
                double pivot = m(j, j);
                for (int k = 0; k < j; ++k)
                    pivot -= m(j, k) * m(j, k);
                if (!(pivot > 0.0))
                    return false;
                inverseDiagonal[j] = 1.0 / std::sqrt(pivot);
                for (int i = j + 1; i < 6; ++i)
                {
                    double value = m(i, j);
                    for (int k = 0; k < j; ++k)
                        value -= m(i, k) * m(j, k);
                    m(i, j) = value * inverseDiagonal[j];
                }
            }
            for (int i = 0; i < 6; ++i)  // L y = x
            {
                for (int k = 0; k < i; ++k)
                    x[i] -= m(i, k) * x[k];
                x[i] *= inverseDiagonal[i];
            }
            for (int i = 5; i >= 0; --i)  // L^T x = y
            {
                for (int k = i + 1; k < 6; ++k)
                    x[i] -= m(k, i) * x[k];
                x[i] *= inverseDiagonal[i];
            }
            return true;
        }
    }  // namespace

    IkSolver::IkSolver(KinematicChain chain, const Eigen::Isometry3d &base)
        : chain_(std::move(chain)), base_(base)
    {
        unsigned int variables = 0;
        for (unsigned int i = 0; i < chain_.size(); ++i)
            variables = std::max(variables, chain_.variable(i) + 1);
        work_.assign(variables, 0.0);
        const auto n = static_cast<Eigen::Index>(chain_.size());
        jacobian_.resize(6, n);
        step_.resize(n);
        posture_.resize(n);
        params_.declareParam<double>(
            "ik_tolerance", [this](double v) { tolerance = v; }, [this] { return tolerance; });
        params_["ik_tolerance"].setRangeSuggestion("1e-9:1e-6:0.01");
        params_.declareParam<unsigned int>(
            "ik_iterations", [this](unsigned int v) { iterations = v; }, [this] { return iterations; });
        params_["ik_iterations"].setRangeSuggestion("1:1:10000");
        params_.declareParam<unsigned int>(
            "ik_restarts", [this](unsigned int v) { restarts = v; }, [this] { return restarts; });
        params_["ik_restarts"].setRangeSuggestion("0:1:100000");
        params_.declareParam<double>(
            "ik_damping", [this](double v) { damping = v; }, [this] { return damping; });
        params_["ik_damping"].setRangeSuggestion("0.:1e-4:1.");
        params_.declareParam<double>(
            "ik_time_limit", [this](double v) { timeLimit = v; }, [this] { return timeLimit; });
        params_["ik_time_limit"].setRangeSuggestion("0.:0.001:1e300");
        params_.declareParam<bool>(
            "ik_any_yaw", [this](bool v) { anyYaw = v; }, [this] { return anyYaw; });
        params_["ik_any_yaw"].setRangeSuggestion("0,1");
        params_.declareParam<unsigned int>(
            "ik_stall_iterations", [this](unsigned int v) { stallIterations = v; },
            [this] { return stallIterations; });
        params_["ik_stall_iterations"].setRangeSuggestion("0:1:10000");
    }

    IkSolver::Vector6d IkSolver::taskError(const Eigen::Isometry3d &target, const Eigen::Isometry3d &current,
                                           IkTask task) const
    {
        Vector6d error;
        error.head<3>() = target.translation() - current.translation();
        Eigen::Matrix3d difference = target.linear() * current.linear().transpose();
        if (task == IkTask::Pose5DFreeYaw && anyYaw)
        {
            // the target turned about the vertical to the yaw nearest to the current orientation
            // (the turn that maximises the trace of the difference): what is left no turn about the
            // vertical can remove, and it pulls nowhere about the vertical. The turn's cosine and
            // sine are those terms normalised: no atan2 and sincos per iteration
            const double cosine = difference(0, 0) + difference(1, 1);
            const double sine = difference(0, 1) - difference(1, 0);
            const double norm = std::sqrt(cosine * cosine + sine * sine);
            if (norm > 0.0)
            {
                const Eigen::RowVector3d row0 = difference.row(0);
                difference.row(0) = (cosine * row0 - sine * difference.row(1)) / norm;
                difference.row(1) = (sine * row0 + cosine * difference.row(1)) / norm;
            }
        }
        const Eigen::AngleAxisd rotation(difference);
        error.tail<3>() = rotation.angle() * rotation.axis();
        if (task == IkTask::Pose5DFreeYaw)
            error[5] = 0.0;  // a residual rotation about the vertical is allowed
        else if (task == IkTask::Position3D)
            error.tail<3>().setZero();
        return error;
    }

    double IkSolver::error(const Eigen::Isometry3d &target, IkTask task, const double *q) const
    {
        return taskError(target, chain_.toolPose(q, base_), task).norm();
    }

    bool IkSolver::attempt(const Eigen::Isometry3d &target, IkTask task,
                           const std::optional<std::chrono::steady_clock::time_point> &end)
    {
        const unsigned int n = chain_.size();
        for (unsigned int it = 0; it < iterations; ++it)
        {
            ++lastIterations_;
            const Eigen::Isometry3d pose = chain_.toolPoseAndJacobian(work_.data(), base_, jacobian_);
            const Vector6d error = taskError(target, pose, task);
            const double size = error.norm();
            if (size < tolerance)
                return true;
            // an attempt that is stuck gives up (the errors of its last stallIterations iterations,
            // oldest at it % stallIterations)
            if (stallIterations > 0)
            {
                double &before = recentErrors_[it % stallIterations];
                if (it >= stallIterations && size > STALL_RATIO * before)
                    return false;
                before = size;
            }
            if (end && std::chrono::steady_clock::now() > *end)
                return false;
            // the rows the task leaves free take no part in the step
            if (task == IkTask::Pose5DFreeYaw)
                jacobian_.row(5).setZero();
            else if (task == IkTask::Position3D)
                jacobian_.bottomRows<3>().setZero();
            // a coefficient-wise product: at this size faster than a general matrix product
            Eigen::Matrix<double, 6, 6> normal = jacobian_.lazyProduct(jacobian_.transpose());
            // less damping as the error shrinks: fast final convergence, steady far from the target
            const double lambda = damping * std::min(1.0, size);
            normal.diagonal().array() += lambda * lambda;
            // the damped step J^T (J J^T + lambda^2 I)^-1 e plus, far from the target, a step p
            // towards the middle of the joint ranges projected into the task's (damped) null space:
            // p + J^T (J J^T + lambda^2 I)^-1 (e - J p), one 6-vector solve; close to the target the
            // posture step would keep the error above what the damping leaks into the task
            Vector6d residual = error;
            if (size > POSTURE_ERROR)
            {
                for (unsigned int i = 0; i < n; ++i)
                    posture_[i] = chain_.continuous(i)
                                      ? 0.0
                                      : postureGain * (0.5 * (chain_.lower(i) + chain_.upper(i)) -
                                                       work_[chain_.variable(i)]);
                residual.noalias() -= jacobian_ * posture_;
                step_ = posture_;
            }
            else
                step_.setZero();
            // with damping the matrix is positive definite and Cholesky needs no pivoting; without,
            // it may be singular, which LDLT's pivoting copes with
            Vector6d weights = residual;
            if (!choleskySolve(normal, weights))
                weights = normal.ldlt().solve(residual);
            step_.noalias() += jacobian_.transpose() * weights;
            const double largest = step_.cwiseAbs().maxCoeff();
            if (largest > maxStep)
                step_ *= maxStep / largest;
            for (unsigned int i = 0; i < n; ++i)
            {
                double &value = work_[chain_.variable(i)];
                value += step_[i];
                value = chain_.continuous(i) ? wrapAngle(value)
                                             : std::clamp(value, chain_.lower(i), chain_.upper(i));
            }
        }
        return false;
    }

    bool IkSolver::search(const Eigen::Isometry3d &target, IkTask task, double *q, ompl::RNG &rng,
                          IkScope scope)
    {
        // no clock readings without a time limit
        std::optional<std::chrono::steady_clock::time_point> end;
        if (timeLimit < NO_TIME_LIMIT)
            end = std::chrono::steady_clock::now() +
                  std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                      std::chrono::duration<double>(timeLimit));
        lastIterations_ = 0;
        recentErrors_.resize(stallIterations);
        const unsigned int n = chain_.size();
        for (unsigned int i = 0; i < n; ++i)
            work_[chain_.variable(i)] = q[chain_.variable(i)];
        const unsigned int attempts = scope == IkScope::Anywhere ? restarts + 1 : 1;
        for (unsigned int a = 0; a < attempts; ++a)
        {
            if (a > 0)
                for (unsigned int i = 0; i < n; ++i)
                    work_[chain_.variable(i)] = rng.uniformReal(chain_.lower(i), chain_.upper(i));
            if (attempt(target, task, end))
            {
                for (unsigned int i = 0; i < n; ++i)
                    q[chain_.variable(i)] = work_[chain_.variable(i)];
                return true;
            }
            if (end && std::chrono::steady_clock::now() > *end)
                return false;
        }
        return false;
    }
}  // namespace ompl_mm
