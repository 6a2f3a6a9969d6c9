#include "ompl_mm/robot/InverseKinematics.h"

#include <chrono>

namespace ompl_mm
{
    bool InverseKinematics::solve(const Eigen::Isometry3d &target, IkTask task, double *q, ompl::RNG &rng,
                                  IkScope scope)
    {
        const auto start = std::chrono::steady_clock::now();
        const bool found = search(target, task, q, rng, scope);
        time_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        ++calls_;
        solved_ += found ? 1 : 0;
        return found;
    }
}  // namespace ompl_mm
