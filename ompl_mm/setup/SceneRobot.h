#pragma once

#include "ompl_mm/robot/RobotModel.h"
#include "ompl_mm/scene/Scene.h"

namespace ompl_mm
{
    /** The scene's robot as it is planned, and the scene completed from what the robot's files
        say: the URDF read (mimic joints following their leaders); with an SRDF (RobotSpec::srdfFile)
        its planning group chosen (RobotSpec::group: the joints outside it held at their
        `<fixed_joint>` value, or else at 0, or at the middle of their limits when 0 lies outside
        them), its `<disable_collisions>` pairs added to the allowed collisions, the links of its end
        effectors (those of the planning group, or all when no group is chosen) added to the links
        that may touch a held object, and named states (Scene::robotStartState, RobotGoal::state)
        turned into joint values; then the scene's `<fixed_joint>`s held. */
    struct SceneRobot
    {
        Scene scene;  ///< the scene with start and goal joints, allowed pairs and gripper links filled in
        RobotModel robot;  ///< the robot with its held joints fixed: its variables are the planning joints
    };

    /** Loads the robot of scene and completes the scene (see SceneRobot).
        @throws ompl_core::InputError at the scene's robot element for a URDF fault or a robot without
        collision geometry; at a `<fixed_joint>`'s line for an unknown, following or out-of-range
        joint; at the SRDF's lines for SRDF faults and for a group naming a joint or link the URDF
        does not have; at the robot element when the group is unknown or leaves nothing to plan; at
        the start's or goal's robot element for a named state that no group has or that gives no
        value for a planning joint, or that comes without an SRDF file. */
    SceneRobot loadSceneRobot(const Scene &scene);
}  // namespace ompl_mm
