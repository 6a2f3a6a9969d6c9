/* A mobile manipulator for tests: a base sliding in x and y, a shoulder about z, a lift, an elbow. */
#pragma once

#include "ompl_mm/model/ManipulationModel.h"

#include <memory>

namespace ompl_mm::test
{
    /** A mobile base (x, y prismatic) carrying an arm: a shoulder about z, a prismatic lift under
        it, an elbow about y, and a hand. */
    inline const char *const MOBILE_ARM = R"(<?xml version="1.0"?>
<robot name="mobile_arm">
  <link name="world"/>
  <joint name="x" type="prismatic"><parent link="world"/><child link="sled"/>
    <axis xyz="1 0 0"/><limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <link name="sled"/>
  <joint name="y" type="prismatic"><parent link="sled"/><child link="base"/>
    <axis xyz="0 1 0"/><limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <link name="base"><collision><geometry><cylinder radius="0.3" length="0.4"/></geometry></collision></link>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="column"/>
    <origin xyz="0.1 0 0.3"/><axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <link name="column"/>
  <joint name="lift" type="prismatic"><parent link="column"/><child link="upper"/>
    <origin xyz="0 0 0.2"/><axis xyz="0 0 1"/><limit lower="0" upper="0.5" effort="1" velocity="1"/></joint>
  <link name="upper"><collision><origin xyz="0.2 0 0"/><geometry><box size="0.4 0.05 0.05"/></geometry></collision></link>
  <joint name="elbow" type="revolute"><parent link="upper"/><child link="fore"/>
    <origin xyz="0.4 0 0"/><axis xyz="0 1 0"/><limit lower="-2" upper="2" effort="1" velocity="1"/></joint>
  <link name="fore"><collision><origin xyz="0.15 0 0"/><geometry><sphere radius="0.05"/></geometry></collision></link>
  <joint name="wrist" type="fixed"><parent link="fore"/><child link="hand"/><origin xyz="0.3 0 0"/></joint>
  <link name="hand"/>
</robot>)";

    /** The mobile arm as a model, its tool at the hand, in an empty scene. */
    inline ManipulationModelPtr mobileArm()
    {
        Scene scene;
        scene.robot.toolLink = "hand";
        return std::make_shared<ManipulationModel>(scene,
                                                   RobotModel::fromUrdfString(MOBILE_ARM, "mobile_arm"));
    }
}  // namespace ompl_mm::test
