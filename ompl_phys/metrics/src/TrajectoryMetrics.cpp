#include "ompl_phys/metrics/TrajectoryMetrics.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace ompl_phys
{
    namespace
    {
        std::string vectorText(const Eigen::Vector3d &v)
        {
            std::ostringstream out;
            out.precision(17);
            out << '(' << v.x() << ", " << v.y() << ", " << v.z() << ')';
            return out.str();
        }

        [[noreturn]] void reject(const std::string &what)
        {
            throw std::invalid_argument("computeTrajectoryMetrics: " + what);
        }

        /** Throws std::invalid_argument naming the first bad field of trajectory. */
        void validate(const RobotTrajectory &trajectory)
        {
            // the step
            const double h = trajectory.stepDuration;
            if (!std::isfinite(h) || h <= 0.0)
            {
                std::ostringstream out;
                out.precision(17);
                out << "trajectory.stepDuration is " << h << ", must be finite and > 0";
                reject(out.str());
            }

            // the samples
            const std::vector<Eigen::Vector3d> &positions = trajectory.positions;
            if (positions.empty())
                reject("trajectory.positions is empty, must hold at least the start");
            for (std::size_t k = 0; k < positions.size(); ++k)
                if (!positions[k].allFinite())
                    reject("trajectory.positions[" + std::to_string(k) + "] is " + vectorText(positions[k]) +
                           ", must be finite");

            // the moves cover the samples exactly
            const std::size_t totalSteps = positions.size() - 1;
            std::size_t covered = 0;
            for (std::size_t i = 0; i < trajectory.moves.size(); ++i)
            {
                const RobotMove &move = trajectory.moves[i];
                const std::string name = "trajectory.moves[" + std::to_string(i) + "]";
                if (!move.force.allFinite())
                    reject(name + ".force is " + vectorText(move.force) + ", must be finite");
                if (move.steps == 0)
                    reject(name + ".steps is 0, must be >= 1");
                if (move.steps > totalSteps - covered)
                    reject(name + ".steps is " + std::to_string(move.steps) + ": the moves' steps exceed " +
                           "positions.size() - 1 = " + std::to_string(totalSteps));
                covered += move.steps;
            }
            if (covered != totalSteps)
                reject("the moves' steps add up to " + std::to_string(covered) +
                       ", but positions.size() - 1 is " + std::to_string(totalSteps));
        }

        /** T · mean of the squared third-difference jerk; 0 with fewer than 4 samples. */
        double smoothness(const std::vector<Eigen::Vector3d> &p, double h)
        {
            if (p.size() < 4)
                return 0.0;
            const std::size_t n = p.size() - 1;  // steps
            const double h3 = h * h * h;
            double sum = 0.0;
            for (std::size_t k = 0; k + 3 < p.size(); ++k)
            {
                const Eigen::Vector3d jerk = (p[k + 3] - 3.0 * p[k + 2] + 3.0 * p[k + 1] - p[k]) / h3;
                sum += jerk.squaredNorm();
            }
            const double duration = static_cast<double>(n) * h;
            return duration * sum / static_cast<double>(n - 2);
        }
    }  // namespace

    TrajectoryMetrics computeTrajectoryMetrics(const RobotTrajectory &trajectory)
    {
        validate(trajectory);
        const double h = trajectory.stepDuration;
        const std::vector<Eigen::Vector3d> &p = trajectory.positions;

        TrajectoryMetrics metrics;
        std::size_t start = 0;  // first sample of the current move
        for (const RobotMove &move : trajectory.moves)
        {
            const std::size_t end = start + move.steps;
            const double duration = static_cast<double>(move.steps) * h;

            // covered distance: length of the sampled polyline over the move
            double covered = 0.0;
            for (std::size_t k = start; k < end; ++k)
                covered += (p[k + 1] - p[k]).norm();
            metrics.action += move.force.norm() * duration * covered;

            // mean power of the move: force times displacement over duration
            metrics.power += move.force.dot(p[end] - p[start]) / duration;
            start = end;
        }
        metrics.smoothness = smoothness(p, h);
        return metrics;
    }
}  // namespace ompl_phys
