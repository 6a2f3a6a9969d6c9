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
            .addNumber("time_s", check.wallSeconds)
            .addNumber("action", check.metrics.action)
            .addNumber("power", check.metrics.power)
            .addNumber("smoothness", check.metrics.smoothness)
            .addRecord("objects", objects);
        return record;
    }

    ompl_mm::ExtraColumns simulatedPoseColumns(const PhysicsCheck &check)
    {
        ompl_mm::ExtraColumns columns;
        for (const ObjectCheck &object : check.objects)
            for (const char *coordinate : {".x", ".y", ".z", ".yaw"})
                columns.names.push_back("sim." + object.name + coordinate);
        for (const std::vector<ompl_mm::ObjectPose> &poses : check.simulation.statePoses)
        {
            std::vector<double> &row = columns.values.emplace_back();
            for (const ompl_mm::ObjectPose &pose : poses)
                row.insert(row.end(), {pose.position.x(), pose.position.y(), pose.position.z(), pose.yaw});
        }
        return columns;
    }

    ompl_mm::CompanionPoses simulatedCompanions(const PhysicsCheck &check)
    {
        return {"simulated", check.simulation.statePoses};
    }
}  // namespace ompl_mmphys
