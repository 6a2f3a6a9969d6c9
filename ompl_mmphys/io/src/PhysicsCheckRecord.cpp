#include "ompl_mmphys/io/PhysicsCheckRecord.h"

#include <algorithm>

namespace ompl_mmphys
{
    ompl_core::RunRecord physicsCheckRecord(const PhysicsCheck &check)
    {
        ompl_core::RunRecord objects;
        for (const ObjectCheck &object : check.objects)
        {
            std::string key = object.name;
            std::replace(key.begin(), key.end(), '.', '_');  // record keys hold no '.'
            objects.addRecord(
                key, ompl_core::RunRecord()
                         .addNumber("position_error_m", object.positionError)
                         .addNumber("yaw_error_rad", object.yawError)
                         .addFlag("tipped", object.tipped)
                         .addFlag("off_surface", object.offSurface)
                         .addNumber("worst_position_error_after_moves_m", object.worstPositionErrorAfterMoves)
                         .addNumber("worst_yaw_error_after_moves_rad", object.worstYawErrorAfterMoves));
        }
        ompl_core::RunRecord record;
        record.addFlag("confirmed", check.confirmed)
            .addFlag("goal_holds", check.goalHolds)
            .addNumber("max_position_error_m", check.maxPositionError)
            .addNumber("max_yaw_error_rad", check.maxYawError)
            .addNumber("simulated_s", check.simulatedSeconds)
            .addNumber("action", check.metrics.action)
            .addNumber("power", check.metrics.power)
            .addNumber("smoothness", check.metrics.smoothness)
            .addRecord("objects", objects);
        return record;
    }
}  // namespace ompl_mmphys
