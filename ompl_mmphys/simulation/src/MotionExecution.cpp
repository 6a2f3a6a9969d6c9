#include "ompl_mmphys/simulation/MotionExecution.h"

#include "ompl_mmphys/simulation/SegmentTiming.h"

#include <ompl/util/Exception.h>
#include <Eigen/Core>

#include <cmath>

namespace ompl_mmphys
{
    namespace
    {
        /** Segments whose directions differ by less than this (1 - cosine) continue one run: pieces
            of one straight motion differ only by rounding. */
        constexpr double SAME_DIRECTION = 1e-9;

        /** Settling ends early once every free object has moved slower than REST_SPEED (m/s) and
            turned slower than REST_SPIN (rad/s) for REST_STEPS steps in a row: friction stops a
            pushed or placed object within a few steps, and the rest of settleTime would change
            nothing but the time spent. */
        constexpr double REST_SPEED = 1e-3;
        constexpr double REST_SPIN = 1e-2;
        constexpr std::size_t REST_STEPS = 10;

        bool holds(const ompl_mm::SegmentLabel &label)
        {
            return label.kind == ompl_mm::PrimitiveKind::Pickup ||
                   label.kind == ompl_mm::PrimitiveKind::Transfer;
        }

        Eigen::VectorXd motion(const double *from, const double *to, unsigned int dof)
        {
            return Eigen::Map<const Eigen::VectorXd>(to, dof) - Eigen::Map<const Eigen::VectorXd>(from, dof);
        }

        /** Reports a motion or settling of steps steps whose forces add up to move.force. */
        void report(ompl_phys::RobotMove move, std::size_t steps, ExecutionObserver &observer)
        {
            if (steps == 0)
                return;
            move.force /= static_cast<double>(steps);
            move.steps = steps;
            observer.moved(move);
        }
    }  // namespace

    void checkSettings(const SimulationSettings &settings, const char *who)
    {
        const std::pair<double, const char *> positive[] = {
            {settings.timeStep, "timeStep"},
            {settings.jointSpeed, "jointSpeed"},
            {settings.jointAcceleration, "jointAcceleration"},
            {settings.manipulationSpeedFactor, "manipulationSpeedFactor"}};
        for (const auto &[value, name] : positive)
            if (!(value > 0.0) || !std::isfinite(value))
                throw ompl::Exception(who,
                                      std::string(name) + " must be positive, got " + std::to_string(value));
        if (!(settings.settleTime >= 0.0) || !std::isfinite(settings.settleTime))
            throw ompl::Exception(who, "settleTime must be 0 or more");
    }

    std::vector<ompl_mm::ObjectPose> objectPoses(const ompl_mm::ManipulationStateSpace &space,
                                                 const ompl::base::State *state)
    {
        std::vector<ompl_mm::ObjectPose> poses;
        for (unsigned int k = 0; k < space.objectCount(); ++k)
            poses.push_back(space.objectPose(state, k));
        return poses;
    }

    MotionExecution::MotionExecution(PlanWorld &world, const SimulationSettings &settings)
        : world_(world), settings_(settings), dof_(world.model().robot().dof())
    {
        for (unsigned int j = 0; j < dof_; ++j)
        {
            const double limit = world.model().robot().variableJoint(j).velocity;
            speeds_.push_back(limit > 0.0 ? std::min(limit, settings.jointSpeed) : settings.jointSpeed);
        }
    }

    void MotionExecution::execute(const std::vector<const double *> &waypoints,
                                  const std::vector<ompl_mm::SegmentLabel> &labels,
                                  ExecutionObserver &observer)
    {
        for (std::size_t first = 0; first < labels.size();)
        {
            const std::size_t last = runEnd(waypoints, labels, first);
            const ompl_mm::SegmentLabel &label = labels[first];
            const auto object = static_cast<unsigned int>(label.object);
            if (holds(label) && !world_.isHeld(object))
                world_.hold(object);
            const bool pushStarts =
                label.kind == ompl_mm::PrimitiveKind::Push && (first == 0 || !(labels[first - 1] == label));
            if (pushStarts)
                world_.isolate(object);
            drive(waypoints, first, last,
                  label.kind == ompl_mm::PrimitiveKind::Transit ? 1.0 : settings_.manipulationSpeedFactor,
                  observer);
            const bool labelEnds = last == labels.size() || !(labels[last] == label);
            // a pickup followed by its transfer holds on
            const bool holdsOn =
                last < labels.size() && holds(labels[last]) && labels[last].object == label.object;
            if (holds(label) && labelEnds && !holdsOn)
            {
                world_.release(object);
                settle(waypoints[last], observer);
                observer.settled(last, object, ompl_mm::PrimitiveKind::Transfer);
            }
            else if (label.kind == ompl_mm::PrimitiveKind::Push && labelEnds)
            {
                settle(waypoints[last], observer);
                world_.thaw();
                observer.settled(last, object, ompl_mm::PrimitiveKind::Push);
            }
            observer.reached(last);
            first = last;
        }
    }

    std::size_t MotionExecution::runEnd(const std::vector<const double *> &waypoints,
                                        const std::vector<ompl_mm::SegmentLabel> &labels,
                                        std::size_t first) const
    {
        const Eigen::VectorXd direction = motion(waypoints[first], waypoints[first + 1], dof_);
        std::size_t last = first + 1;
        if (direction.norm() == 0.0)
            return last;
        while (last < labels.size() && labels[last] == labels[first])
        {
            const Eigen::VectorXd next = motion(waypoints[last], waypoints[last + 1], dof_);
            if (next.norm() == 0.0 ||
                1.0 - direction.dot(next) / (direction.norm() * next.norm()) > SAME_DIRECTION)
                break;
            ++last;
        }
        return last;
    }

    void MotionExecution::drive(const std::vector<const double *> &waypoints, std::size_t first,
                                std::size_t last, double speedFactor, ExecutionObserver &observer)
    {
        const double *from = waypoints[first];
        std::vector<double> delta(dof_), speeds(dof_),
            accelerations(dof_, settings_.jointAcceleration * speedFactor);
        for (unsigned int j = 0; j < dof_; ++j)
        {
            delta[j] = waypoints[last][j] - from[j];
            speeds[j] = speeds_[j] * speedFactor;
        }
        // where along the run each waypoint in it lies
        const double length = Eigen::Map<const Eigen::VectorXd>(delta.data(), dof_).norm();
        std::vector<double> passes;
        for (std::size_t i = first + 1; i < last; ++i)
            passes.push_back(motion(from, waypoints[i], dof_).norm() / length);
        std::size_t passed = 0;

        const SegmentTiming timing(delta, speeds, accelerations);
        const auto steps = static_cast<std::size_t>(std::ceil(timing.duration() / settings_.timeStep));
        std::vector<double> now(from, from + dof_), next(dof_);
        ompl_phys::RobotMove move;
        for (std::size_t k = 1; k <= steps; ++k)
        {
            const double s = timing.fraction(static_cast<double>(k) * settings_.timeStep);
            for (unsigned int j = 0; j < dof_; ++j)
                next[j] = from[j] + s * delta[j];
            world_.driveRobot(now.data(), next.data(), settings_.timeStep);
            world_.step(settings_.timeStep);
            move.force += world_.robotContactForce();
            observer.stepped(next.data());
            for (; passed < passes.size() && passes[passed] <= s; ++passed)
                observer.reached(first + 1 + passed);
            now.swap(next);
        }
        for (; passed < passes.size(); ++passed)
            observer.reached(first + 1 + passed);
        report(move, steps, observer);
    }

    void MotionExecution::settle(const double *q, ExecutionObserver &observer)
    {
        const auto steps = static_cast<std::size_t>(std::ceil(settings_.settleTime / settings_.timeStep));
        ompl_phys::RobotMove move;
        std::size_t k = 0;
        for (std::size_t resting = 0; k < steps && resting < REST_STEPS; ++k)
        {
            world_.driveRobot(q, q, settings_.timeStep);
            world_.step(settings_.timeStep);
            move.force += world_.robotContactForce();
            observer.stepped(q);
            resting = world_.atRest(REST_SPEED, REST_SPIN) ? resting + 1 : 0;
        }
        report(move, k, observer);
    }
}  // namespace ompl_mmphys
