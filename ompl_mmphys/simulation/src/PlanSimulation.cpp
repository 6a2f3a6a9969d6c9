#include "ompl_mmphys/simulation/PlanSimulation.h"

#include "ompl_mm/base/ManipulationStateSpace.h"
#include "ompl_mmphys/simulation/SegmentTiming.h"

#include <ompl/util/Exception.h>

#include <cmath>

namespace ompl_mmphys
{
    namespace
    {
        /** The poses of every object in state. */
        std::vector<ompl_mm::ObjectPose> posesAt(const ompl_mm::ManipulationStateSpace &space,
                                                 const ompl::base::State *state)
        {
            std::vector<ompl_mm::ObjectPose> poses;
            for (unsigned int k = 0; k < space.objectCount(); ++k)
                poses.push_back(space.objectPose(state, k));
            return poses;
        }

        /** Runs a PlanWorld along the path, recording as it goes. */
        class PlanExecution
        {
        public:
            PlanExecution(const ompl_mm::ManipulationPath &path, const SimulationSettings &settings)
                : path_(path),
                  space_(*path.getSpaceInformation()->getStateSpace()->as<ompl_mm::ManipulationStateSpace>()),
                  settings_(settings),
                  world_(space_.model(), space_.robotValues(path.getState(0)),
                         posesAt(space_, path.getState(0)), settings.world),
                  dof_(space_.robotDimension())
            {
                const ompl_mm::RobotModel &robot = space_.model()->robot();
                for (unsigned int j = 0; j < dof_; ++j)
                {
                    const double limit = robot.variableJoint(j).velocity;
                    speeds_.push_back(limit > 0.0 ? std::min(limit, settings.jointSpeed)
                                                  : settings.jointSpeed);
                }
                plan_.tool.stepDuration = settings.timeStep;
                plan_.tool.positions.push_back(toolAt(space_.robotValues(path.getState(0))));
                plan_.statePoses.push_back(objectPoses());
            }

            SimulatedPlan run()
            {
                const std::vector<ompl_mm::SegmentLabel> &labels = path_.labels();
                for (std::size_t i = 0; i + 1 < path_.getStateCount(); ++i)
                {
                    const ompl_mm::SegmentLabel &label = labels[i];
                    const bool holding = label.kind == ompl_mm::PrimitiveKind::Pickup ||
                                         label.kind == ompl_mm::PrimitiveKind::Transfer;
                    const auto object = static_cast<unsigned int>(label.object);
                    if (holding && !world_.isHeld(object))
                        world_.hold(object);
                    drive(i, label.kind == ompl_mm::PrimitiveKind::Transit
                                 ? 1.0
                                 : settings_.manipulationSpeedFactor);
                    const bool runEnds = i + 2 == path_.getStateCount() || !(labels[i + 1] == label);
                    if (holding && runEnds && !holdsOn(labels, i + 1, object))
                    {
                        world_.release(object);
                        settle(space_.robotValues(path_.getState(i + 1)));
                        plan_.checkpoints.push_back(
                            {i + 1, object, ompl_mm::PrimitiveKind::Transfer, world_.objectPose(object)});
                    }
                    else if (label.kind == ompl_mm::PrimitiveKind::Push && runEnds)
                        plan_.checkpoints.push_back(
                            {i + 1, object, ompl_mm::PrimitiveKind::Push, world_.objectPose(object)});
                    plan_.statePoses.push_back(objectPoses());
                }
                settle(space_.robotValues(path_.getState(path_.getStateCount() - 1)));
                plan_.finalPoses = objectPoses();
                plan_.statePoses.back() = plan_.finalPoses;
                for (unsigned int k = 0; k < space_.objectCount(); ++k)
                    plan_.finalTilts.push_back(world_.objectTilt(k));
                plan_.simulatedSeconds =
                    static_cast<double>(plan_.tool.positions.size() - 1) * settings_.timeStep;
                return std::move(plan_);
            }

        private:
            /** Whether the segment from state i on goes on holding object (a pickup followed by
                its transfer). */
            bool holdsOn(const std::vector<ompl_mm::SegmentLabel> &labels, std::size_t i,
                         unsigned int object) const
            {
                return i < labels.size() && labels[i].object == static_cast<int>(object) &&
                       (labels[i].kind == ompl_mm::PrimitiveKind::Pickup ||
                        labels[i].kind == ompl_mm::PrimitiveKind::Transfer);
            }

            /** Drives the robot from state i to state i + 1 at speedFactor of its speeds. */
            void drive(std::size_t i, double speedFactor)
            {
                const double *from = space_.robotValues(path_.getState(i));
                const double *to = space_.robotValues(path_.getState(i + 1));
                std::vector<double> delta(dof_), speeds(dof_),
                    accelerations(dof_, settings_.jointAcceleration * speedFactor);
                for (unsigned int j = 0; j < dof_; ++j)
                {
                    delta[j] = to[j] - from[j];
                    speeds[j] = speeds_[j] * speedFactor;
                }
                const SegmentTiming timing(delta, speeds, accelerations);
                const auto steps =
                    static_cast<std::size_t>(std::ceil(timing.duration() / settings_.timeStep));
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
                    plan_.tool.positions.push_back(toolAt(next.data()));
                    now.swap(next);
                }
                addMove(move, steps);
            }

            /** Lets the world run for the settling time with the robot still at q. */
            void settle(const double *q)
            {
                const auto steps =
                    static_cast<std::size_t>(std::ceil(settings_.settleTime / settings_.timeStep));
                ompl_phys::RobotMove move;
                for (std::size_t k = 0; k < steps; ++k)
                {
                    world_.driveRobot(q, q, settings_.timeStep);
                    world_.step(settings_.timeStep);
                    move.force += world_.robotContactForce();
                    plan_.tool.positions.push_back(toolAt(q));
                }
                addMove(move, steps);
            }

            /** Records a move of steps steps whose forces add up to move.force. */
            void addMove(ompl_phys::RobotMove move, std::size_t steps)
            {
                if (steps == 0)
                    return;
                move.force /= static_cast<double>(steps);
                move.steps = steps;
                plan_.tool.moves.push_back(move);
            }

            Eigen::Vector3d toolAt(const double *q) const
            {
                return space_.model()->toolFrame(q).translation();
            }

            std::vector<ompl_mm::ObjectPose> objectPoses() const
            {
                std::vector<ompl_mm::ObjectPose> poses;
                for (unsigned int k = 0; k < space_.objectCount(); ++k)
                    poses.push_back(world_.objectPose(k));
                return poses;
            }

            const ompl_mm::ManipulationPath &path_;
            const ompl_mm::ManipulationStateSpace &space_;
            const SimulationSettings &settings_;
            PlanWorld world_;
            unsigned int dof_;
            std::vector<double> speeds_;  ///< per joint, before the speed factor
            SimulatedPlan plan_;
        };

        void requirePositive(double value, const char *name)
        {
            if (!(value > 0.0) || !std::isfinite(value))
                throw ompl::Exception("simulatePlan",
                                      std::string(name) + " must be positive, got " + std::to_string(value));
        }
    }  // namespace

    SimulatedPlan simulatePlan(const ompl_mm::ManipulationPath &path, const SimulationSettings &settings)
    {
        if (path.getStateCount() == 0)
            throw ompl::Exception("simulatePlan", "the path is empty");
        requirePositive(settings.timeStep, "timeStep");
        requirePositive(settings.jointSpeed, "jointSpeed");
        requirePositive(settings.jointAcceleration, "jointAcceleration");
        requirePositive(settings.manipulationSpeedFactor, "manipulationSpeedFactor");
        if (!(settings.settleTime >= 0.0) || !std::isfinite(settings.settleTime))
            throw ompl::Exception("simulatePlan", "settleTime must be 0 or more");
        return PlanExecution(path, settings).run();
    }
}  // namespace ompl_mmphys
