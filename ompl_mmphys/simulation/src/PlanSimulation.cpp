#include "ompl_mmphys/simulation/PlanSimulation.h"

#include "ompl_mm/base/ManipulationStateSpace.h"

#include <ompl/util/Exception.h>

#include <cmath>

namespace ompl_mmphys
{
    namespace
    {
        /** Runs a PlanWorld along the path, recording as it goes. */
        class PlanExecution : public ExecutionObserver
        {
        public:
            PlanExecution(const ompl_mm::ManipulationPath &path, const SimulationSettings &settings)
                : path_(path),
                  space_(*path.getSpaceInformation()->getStateSpace()->as<ompl_mm::ManipulationStateSpace>()),
                  world_(space_.model(), space_.robotValues(path.getState(0)),
                         ompl_mmphys::objectPoses(space_, path.getState(0)), settings.world),
                  execution_(world_, settings)
            {
                plan_.tool.stepDuration = settings.timeStep;
                plan_.tool.positions.push_back(toolAt(space_.robotValues(path.getState(0))));
                plan_.statePoses.push_back(worldPoses());
            }

            SimulatedPlan run()
            {
                std::vector<const double *> waypoints;
                for (std::size_t i = 0; i < path_.getStateCount(); ++i)
                    waypoints.push_back(space_.robotValues(path_.getState(i)));
                plan_.statePoses.resize(path_.getStateCount());
                execution_.execute(waypoints, path_.labels(), *this);
                execution_.settle(waypoints.back(), *this);
                plan_.finalPoses = worldPoses();
                plan_.statePoses.back() = plan_.finalPoses;
                for (unsigned int k = 0; k < space_.objectCount(); ++k)
                    plan_.finalTilts.push_back(world_.objectTilt(k));
                plan_.simulatedSeconds =
                    static_cast<double>(plan_.tool.positions.size() - 1) * plan_.tool.stepDuration;
                return std::move(plan_);
            }

            void stepped(const double *q) override { plan_.tool.positions.push_back(toolAt(q)); }
            void reached(std::size_t waypoint) override { plan_.statePoses[waypoint] = worldPoses(); }
            void settled(std::size_t waypoint, unsigned int object, ompl_mm::PrimitiveKind kind) override
            {
                plan_.checkpoints.push_back({waypoint, object, kind, world_.objectPose(object)});
            }
            void moved(const ompl_phys::RobotMove &move) override { plan_.tool.moves.push_back(move); }

        private:
            Eigen::Vector3d toolAt(const double *q) const
            {
                return space_.model()->toolFrame(q).translation();
            }

            std::vector<ompl_mm::ObjectPose> worldPoses() const
            {
                std::vector<ompl_mm::ObjectPose> poses;
                for (unsigned int k = 0; k < space_.objectCount(); ++k)
                    poses.push_back(world_.objectPose(k));
                return poses;
            }

            const ompl_mm::ManipulationPath &path_;
            const ompl_mm::ManipulationStateSpace &space_;
            PlanWorld world_;
            MotionExecution execution_;
            SimulatedPlan plan_;
        };
    }  // namespace

    SimulatedPlan simulatePlan(const ompl_mm::ManipulationPath &path, const SimulationSettings &settings)
    {
        if (path.getStateCount() == 0)
            throw ompl::Exception("simulatePlan", "the path is empty");
        checkSettings(settings, "simulatePlan");
        return PlanExecution(path, settings).run();
    }
}  // namespace ompl_mmphys
