// Shared helpers of the ompl_phys tests: the benchmark scenes, a small inline scene, InputError
// capture, bit-exact comparison of simulated states.
#pragma once

#include "common/InputErrors.h"
#include "ompl_phys/knowledge/Footprint.h"
#include "ompl_phys/scene/PhysicsSceneLoader.h"
#include "ompl_phys/world/BodyState.h"

#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace ompl_phys::test
{
    using ompl_core::test::contains;
    using ompl_core::test::inputErrorOf;
    using ompl_core::test::startsWith;

    /** Path of the benchmark scene n (1, 2 or 3). */
    inline std::string benchmarkScenePath(int n)
    {
        return std::string(OMPL_MM_SCENES_DIR) + "/physics/scene" + std::to_string(n) + ".xml";
    }

    /** A shared copy of scene, as the world, the space and the knowledge hold one. */
    inline PhysicsScenePtr shared(const PhysicsScene &scene)
    {
        return std::make_shared<const PhysicsScene>(scene);
    }

    /** The benchmark scene n (1, 2 or 3) from scenes/physics. */
    inline PhysicsScene benchmarkScene(int n)
    {
        return loadPhysicsScene(benchmarkScenePath(n));
    }

    /** A small valid scene, one element per line (except the constrained body, lines 10-14), so that a
        test can replace line n (1-based) and expect an error at line n. A 2 m x 2 m robot region; a
        fixed wall near its top edge, a fixed prism, a free cube, and a constraint-oriented cube at the
        origin turned by 90 degrees, so that its push axis (body x) is the world y axis. */
    inline std::vector<std::string> smallSceneLines()
    {
        return {
            R"(<physics_scene name="small" time_limit="5">)",  // 1
            R"(  <simulation gravity="-9.81" erp="0.5" cfm="0.0001" max_contacts="3" iterations="20" substeps="7"/>)",  // 2
            R"(  <materials robot_floor="0" default="0.7"/>)",  // 3
            R"(  <limits robot_region="-1 1 -1 1" body_region="-1.2 1.2 -1.2 1.2" max_robot_speed="0.5" max_force="10" step="0.07" min_steps="1" max_steps="10" goal_bias="0.05"/>)",  // 4
            R"(  <floor size="2.4 2.4"/>)",                                         // 5
            R"(  <robot name="robot" radius="0.08" mass="1" start="-0.8 -0.8"/>)",  // 6
            R"(  <body name="wall" kind="fixed"><origin xyz="0 0.8 0.1"/><box size="1 0.2 0.2"/></body>)",  // 7
            R"(  <body name="wedge" kind="fixed"><origin xyz="-0.6 0.3 0.1" rpy="0 0 30deg"/><prism corners="0.2 0 -0.1 0.17 -0.1 -0.17" length="0.2"/></body>)",  // 8
            R"(  <body name="loose" kind="free" mass="0.5"><origin xyz="0.6 -0.4 0.1"/><box size="0.2 0.2 0.2"/></body>)",  // 9
            R"(  <body name="slider" kind="constrained" mass="0.5">)",  // 10
            R"(    <origin xyz="0 0 0.1" rpy="0 0 90deg"/>)",           // 11
            R"(    <box size="0.2 0.2 0.2"/>)",                         // 12
            R"(    <push axis="1 0 0" strip_half_width="0.06" lateral_tolerance="0.03" angle_tolerance="10deg"/>)",  // 13
            R"(  </body>)",                             // 14
            R"(  <goal xy="0.8 -0.8" radius="0.1"/>)",  // 15
            R"(</physics_scene>)",                      // 16
        };
    }

    /** Lines joined with newlines. */
    inline std::string joinLines(const std::vector<std::string> &lines)
    {
        std::string xml;
        for (const std::string &line : lines)
            xml += line + "\n";
        return xml;
    }

    /** The small scene, parsed as "small.xml". */
    inline PhysicsScene smallScene()
    {
        return parsePhysicsScene(joinLines(smallSceneLines()), "small.xml");
    }

    /** True when two doubles have the same bits (so -0.0 differs from 0.0 and a NaN equals itself). */
    inline bool sameBits(double a, double b)
    {
        return std::memcmp(&a, &b, sizeof(double)) == 0;
    }

    /** True when every number of a equals the one of b bit for bit. */
    inline bool sameBits(const BodyStates &a, const BodyStates &b)
    {
        if (a.size() != b.size())
            return false;
        for (std::size_t i = 0; i < a.size(); ++i)
        {
            const double *pairs[4][2] = {{a[i].position.data(), b[i].position.data()},
                                         {a[i].orientation.coeffs().data(), b[i].orientation.coeffs().data()},
                                         {a[i].linearVelocity.data(), b[i].linearVelocity.data()},
                                         {a[i].angularVelocity.data(), b[i].angularVelocity.data()}};
            for (int part = 0; part < 4; ++part)
                for (int k = 0; k < (part == 1 ? 4 : 3); ++k)
                    if (!sameBits(pairs[part][0][k], pairs[part][1][k]))
                        return false;
        }
        return true;
    }

    /** Distance from point to the footprint of scene body `body` at its start pose. */
    inline double distanceToStartFootprint(const PhysicsScene &scene, std::size_t body,
                                           const Eigen::Vector2d &point)
    {
        const PhysicsBody &b = scene.bodies[body];
        return footprintDistance(b.shape, b.start.translation().head<2>(),
                                 yawOf(Eigen::Quaterniond(b.start.linear())), point);
    }
}  // namespace ompl_phys::test
