// Shared test helper: a Franka Panda (scenes/robots/panda, with visual and collision meshes) that
// picks a cylinder from one table and places it on another, for the pictures' tests.
#pragma once

#include "ompl_mm/scene/SceneLoader.h"

#include <string>

namespace ompl_mm::test
{
    /** The Panda pick-and-place scene: the arm at its SRDF's "ready" state, fingers held open, a
        cylinder of radius 0.03 m from (0.55, 0.1) on table1 to (0.2, -0.5) on table2. */
    inline Scene pandaPickScene()
    {
        const std::string robots = OMPL_MM_SCENES_DIR "/robots/panda/franka_panda/";
        const std::string xml =
            "<scene name=\"panda_pick\" time_limit=\"60\">\n"
            "  <robot urdf=\"" +
            robots + "panda.urdf\" srdf=\"" + robots +
            "panda.srdf\" group=\"panda_arm\" tool_link=\"panda_grasptarget\">\n"
            "    <fixed_joint name=\"panda_finger_joint1\" value=\"0.04\"/>\n"
            "  </robot>\n"
            "  <obstacle name=\"floor\"><origin xyz=\"0 0 -0.035\"/><box size=\"2 2 0.05\"/></obstacle>\n"
            "  <obstacle name=\"table1_top\"><origin xyz=\"0.5 0 0.405\"/><box size=\"0.54 0.54 "
            "0.05\"/></obstacle>\n"
            "  <obstacle name=\"table2_top\"><origin xyz=\"0.2 -0.6 0.405\"/><box size=\"0.54 0.54 "
            "0.05\"/></obstacle>\n"
            "  <surface name=\"table1\" height=\"0.43\" min=\"0.25 -0.25\" max=\"0.75 0.25\" "
            "obstacle=\"table1_top\"/>\n"
            "  <surface name=\"table2\" height=\"0.43\" min=\"-0.05 -0.75\" max=\"0.45 -0.35\" "
            "obstacle=\"table2_top\"/>\n"
            "  <region name=\"air\" min=\"-0.2 -0.65 0.45\" max=\"0.7 0.25 0.95\"/>\n"
            "  <object name=\"cyl1\"><cylinder radius=\"0.03\" length=\"0.07\"/></object>\n"
            "  <start><robot state=\"ready\"/><object name=\"cyl1\" xyz=\"0.55 0.1 0.43\"/></start>\n"
            "  <goal><robot state=\"ready\" tolerance=\"0.01\"/><object name=\"cyl1\" xyz=\"0.2 -0.5 0.43\" "
            "tolerance=\"0.01\"/></goal>\n"
            "  <primitives><transit/><pickup lift_height=\"0.10\" approach_distance=\"0.05\"/>"
            "<transfer_rigid approach_distance=\"0.05\"/></primitives>\n"
            "</scene>\n";
        return parseScene(xml, "panda_pick.xml", robots);
    }
}  // namespace ompl_mm::test
