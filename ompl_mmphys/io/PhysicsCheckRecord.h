/* A physics check as the apps and the benchmark report it. */
#pragma once

#include "ompl_core/run/RunRecord.h"
#include "ompl_mm/io/PathFile.h"
#include "ompl_mm/io/SceneHtml.h"
#include "ompl_mmphys/simulation/PhysicsCheck.h"

namespace ompl_mmphys
{
    /** check as a run record: confirmed, goal_holds, max_position_error_m, max_yaw_error_rad,
        simulated_s, time_s (the check's wall time), the metrics action, power and smoothness, and per object
       (keyed by its name, a '.' in it written as '_') position_error_m, yaw_error_rad, tipped, off_surface
       and the worst errors after its pushes and places. */
    ompl_core::RunRecord physicsCheckRecord(const PhysicsCheck &check);

    /** The simulated poses of check's objects at every waypoint, as path file columns after the
        planned ones: "sim.NAME.x", ".y", ".z", ".yaw" per object (metres, radians). */
    ompl_mm::ExtraColumns simulatedPoseColumns(const PhysicsCheck &check);

    /** The simulated poses of check's objects at every waypoint, for the plan page
        (ompl_mm::writeSceneHtml) to show beside the planned ones, labelled "simulated". */
    ompl_mm::CompanionPoses simulatedCompanions(const PhysicsCheck &check);
}  // namespace ompl_mmphys
