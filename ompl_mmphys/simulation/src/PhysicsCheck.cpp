#include "ompl_mmphys/simulation/PhysicsCheck.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace ompl_mmphys
{
    double yawDifference(double a, double b)
    {
        return std::abs(std::remainder(a - b, 360.0 * DEGREE));
    }

    PhysicsCheck checkPlan(const ompl_mm::ManipulationSetup &setup, const ompl_mm::ManipulationPath &path,
                           const SimulationSettings &settings, const CheckTolerances &tolerances)
    {
        const auto start = std::chrono::steady_clock::now();
        PhysicsCheck check;
        check.simulation = simulatePlan(path, settings);
        const ompl_mm::ManipulationStateSpace &space = *setup.manipulationSpace();
        const ompl_mm::Scene &scene = space.model()->scene();
        const ompl::base::State *planned = path.getState(path.getStateCount() - 1);
        ompl::base::State *simulatedEnd = space.allocState();
        space.copyState(simulatedEnd, planned);
        bool withinTolerances = true;
        for (unsigned int k = 0; k < space.objectCount(); ++k)
        {
            const ompl_mm::MovableObject &object = scene.objects[k];
            const bool yawMatters = !object.shape.turnsFreely();
            auto errors = [&](const ompl_mm::ObjectPose &simulated, const ompl_mm::ObjectPose &plannedPose)
            {
                return std::make_pair((simulated.position - plannedPose.position).norm(),
                                      yawMatters ? yawDifference(simulated.yaw, plannedPose.yaw) : 0.0);
            };
            ObjectCheck result;
            result.name = object.name;
            ompl_mm::ObjectPose end = check.simulation.finalPoses[k];
            std::tie(result.positionError, result.yawError) = errors(end, space.objectPose(planned, k));
            result.tipped = check.simulation.finalTilts[k] > tolerances.tilt;
            const int surface = surfaceUnder(scene, end.position);
            if (surface >= 0)
                end.position.z() = scene.surfaces[static_cast<std::size_t>(surface)].height;
            result.offSurface = surface < 0 && space.restingSurface(planned, k) >= 0;
            for (const Checkpoint &checkpoint : check.simulation.checkpoints)
            {
                if (checkpoint.object != k)
                    continue;
                const auto [position, yaw] =
                    errors(checkpoint.simulated, space.objectPose(path.getState(checkpoint.state), k));
                result.worstPositionErrorAfterMoves = std::max(result.worstPositionErrorAfterMoves, position);
                result.worstYawErrorAfterMoves = std::max(result.worstYawErrorAfterMoves, yaw);
            }
            space.setObjectPose(simulatedEnd, k, end);
            withinTolerances = withinTolerances && result.positionError <= tolerances.position &&
                               result.yawError <= tolerances.yaw && !result.tipped && !result.offSurface;
            check.maxPositionError = std::max(check.maxPositionError, result.positionError);
            check.maxYawError = std::max(check.maxYawError, result.yawError);
            check.objects.push_back(result);
        }
        check.goalHolds = setup.manipulationGoal()->isSatisfied(simulatedEnd);
        space.freeState(simulatedEnd);
        check.confirmed = withinTolerances && check.goalHolds;
        check.metrics = ompl_phys::computeTrajectoryMetrics(check.simulation.tool);
        check.simulatedSeconds = check.simulation.simulatedSeconds;
        check.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return check;
    }
}  // namespace ompl_mmphys
