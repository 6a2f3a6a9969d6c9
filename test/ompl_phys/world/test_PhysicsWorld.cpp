// Tests for PhysicsWorld: motion against analytic solutions, rest, contact reports, and bit-identical
// repetition of simulations after resetRandomSeed().
#include "ompl_phys/world/PhysicsWorld.h"

#include "ompl_phys/common/PhysicsTestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace ompl_phys;
using namespace ompl_phys::test;

namespace
{
    /** A 4 m x 4 m floor with the robot (radius 0.08 m, 2 kg) at the origin and one free cube far from it. */
    PhysicsScene flatScene()
    {
        return parsePhysicsScene(R"(<physics_scene name="flat">
  <limits robot_region="-2 2 -2 2" body_region="-2 2 -2 2"/>
  <robot radius="0.08" mass="2" start="0 0"/>
  <body name="cube" kind="free" mass="0.5"><origin xyz="1 1 0.1"/><box size="0.2 0.2 0.2"/></body>
  <goal xy="1.5 -1.5" radius="0.1"/>
</physics_scene>)",
                                 "flat.xml");
    }

    /** Steps world n times by dt with force on the robot. */
    void run(PhysicsWorld &world, const Eigen::Vector2d &force, double dt, int n)
    {
        for (int k = 0; k < n; ++k)
            world.step(force, dt);
    }

    /** The states after n steps of dt with force from states, ODE's generator reset first. */
    BodyStates simulate(PhysicsWorld &world, const BodyStates &states, const Eigen::Vector2d &force,
                        double dt, int n)
    {
        world.setStates(states);
        PhysicsWorld::resetRandomSeed();
        run(world, force, dt, n);
        BodyStates result;
        world.readStates(result);
        return result;
    }

    /** Displacement of the robot after n steps of dt under force, from rest at the origin. */
    Eigen::Vector2d drivenDisplacement(PhysicsWorld &world, const Eigen::Vector2d &force, double dt, int n)
    {
        const BodyStates result = simulate(world, world.startStates(), force, dt, n);
        return result[0].position.head<2>() - world.startStates()[0].position.head<2>();
    }
}  // namespace

TEST(PhysicsWorld, StartStatesAreTheScenePosesAtRest)
{
    const PhysicsScene scene = benchmarkScene(1);
    PhysicsWorld world(shared(scene));
    const BodyStates start = world.startStates();
    ASSERT_EQ(world.movingBodyCount(), 1 + scene.movableBodies().size());
    ASSERT_EQ(start.size(), world.movingBodyCount());
    EXPECT_EQ(world.movingBodyName(0), scene.robot.name);
    EXPECT_TRUE(start[0].position.isApprox(scene.robot.start));
    for (std::size_t i = 1; i < start.size(); ++i)
    {
        const PhysicsBody &body = scene.bodies[world.sceneBodyOf(i)];
        EXPECT_EQ(world.movingBodyName(i), body.name);
        EXPECT_NE(body.kind, BodyKind::Fixed);
        EXPECT_TRUE(start[i].position.isApprox(body.start.translation()));
        EXPECT_TRUE(start[i].linearVelocity.isZero());
        EXPECT_TRUE(start[i].angularVelocity.isZero());
    }
    // setStates then readStates gives back what was written
    BodyStates moved = start;
    moved[0].position.x() += 0.1;
    moved[1].linearVelocity = Eigen::Vector3d(0.2, -0.1, 0.0);
    world.setStates(moved);
    BodyStates read;
    world.readStates(read);
    EXPECT_TRUE(sameBits(read, moved));
}

TEST(PhysicsWorld, ForceDrivenRobotFollowsTheAnalyticTrajectory)
{
    // The robot slides on a frictionless floor (robot_floor 0): the floor contact's normal is vertical
    // and passes through the centre, so the horizontal motion is that of a free mass under a constant
    // force F: x(T) = x0 + F T^2 / (2 m), v(T) = F T / m. ODE integrates semi-implicitly (v first, then
    // x with the new v), which after n steps of dt gives x0 + (F / m) dt^2 n (n + 1) / 2: the analytic
    // value plus F T dt / (2 m), first order in dt. That bias is the tolerance.
    const PhysicsScene scene = flatScene();
    PhysicsWorld world(shared(scene));
    const double m = scene.robot.mass;
    const Eigen::Vector2d force(3.0, -1.5);
    const double T = 0.7;
    const double dt = 0.01;
    const int n = 70;

    const BodyStates result = simulate(world, world.startStates(), force, dt, n);
    const Eigen::Vector2d displacement = result[0].position.head<2>() - scene.robot.start.head<2>();
    const Eigen::Vector2d analytic = force * T * T / (2.0 * m);
    const double bias = force.norm() * T * dt / (2.0 * m);
    EXPECT_LE((displacement - analytic).norm(), bias + 1e-9)
        << displacement.transpose() << " vs " << analytic.transpose();
    EXPECT_TRUE(result[0].linearVelocity.head<2>().isApprox(force * T / m, 1e-9))
        << result[0].linearVelocity.transpose();
    // the floor holds it: it stays at its radius (soft contact: within a few millimetres)
    EXPECT_NEAR(result[0].position.z(), scene.robot.radius, 0.005);
    // nothing touched, the cube did not move
    EXPECT_TRUE(world.touches().empty());
    EXPECT_NEAR((result[1].position - world.startStates()[1].position).head<2>().norm(), 0.0, 1e-6);
}

TEST(PhysicsWorld, DrivenRobotErrorIsFirstOrderInTheStep)
{
    // halving the step halves the deviation from x0 + F T^2 / (2 m) (see above)
    const PhysicsScene scene = flatScene();
    PhysicsWorld world(shared(scene));
    const Eigen::Vector2d force(2.0, 1.0);
    const double T = 0.56;
    const Eigen::Vector2d analytic = force * T * T / (2.0 * scene.robot.mass);
    const double coarse = (drivenDisplacement(world, force, 0.02, 28) - analytic).norm();
    const double fine = (drivenDisplacement(world, force, 0.01, 56) - analytic).norm();
    const double finer = (drivenDisplacement(world, force, 0.005, 112) - analytic).norm();
    EXPECT_NEAR(fine / coarse, 0.5, 1e-6);
    EXPECT_NEAR(finer / fine, 0.5, 1e-6);
}

TEST(PhysicsWorld, FreeFallFollowsTheAnalyticTrajectory)
{
    // dropped from 1 m, the robot falls for 0.3 s without reaching the floor: z = z0 + g T^2 / 2, with
    // the semi-implicit Euler bias g T dt / 2 as tolerance (see the force-driven test)
    const PhysicsScene scene = flatScene();
    PhysicsWorld world(shared(scene));
    BodyStates start = world.startStates();
    start[0].position.z() = 1.0;
    const double g = scene.contact.gravity;
    const double T = 0.3;
    const double dt = 0.01;
    const BodyStates result = simulate(world, start, Eigen::Vector2d::Zero(), dt, 30);
    EXPECT_NEAR(result[0].position.z(), 1.0 + g * T * T / 2.0, std::abs(g) * T * dt / 2.0 + 1e-9);
    EXPECT_NEAR(result[0].linearVelocity.z(), g * T, 1e-9);
    EXPECT_TRUE(result[0].position.head<2>().isZero(1e-12));
}

TEST(PhysicsWorld, CubeOnTheFloorStaysAtRest)
{
    // a cube resting on the floor with nothing pushing it: no horizontal force acts, so it must not move;
    // it may settle into the floor by the contact layer (about a millimetre)
    const PhysicsScene scene = flatScene();
    PhysicsWorld world(shared(scene));
    const BodyStates start = world.startStates();
    const BodyStates result = simulate(world, start, Eigen::Vector2d::Zero(), 0.01, 200);
    const BodyState &cube = result[1];
    EXPECT_LT((cube.position - start[1].position).head<2>().norm(), 1e-4) << cube.position.transpose();
    EXPECT_NEAR(cube.position.z(), 0.1, 0.003);
    EXPECT_LT(cube.orientation.angularDistance(start[1].orientation), 1e-3);
    EXPECT_LT(cube.linearVelocity.norm(), 1e-3) << cube.linearVelocity.transpose();
    EXPECT_LT(cube.angularVelocity.norm(), 1e-2) << cube.angularVelocity.transpose();
}

TEST(PhysicsWorld, CubesOfSceneOneStayAtRest)
{
    // the same with the scene's parameters and its propagation sub-step (0.07 s / 7)
    const PhysicsScene scene = benchmarkScene(1);
    PhysicsWorld world(shared(scene));
    const BodyStates start = world.startStates();
    const BodyStates result = simulate(world, start, Eigen::Vector2d::Zero(), 0.01, 200);
    for (std::size_t i = 1; i < result.size(); ++i)
    {
        SCOPED_TRACE(world.movingBodyName(i));
        EXPECT_LT((result[i].position - start[i].position).head<2>().norm(), 1e-4);
        EXPECT_LT(result[i].orientation.angularDistance(start[i].orientation), 1e-3);
    }
    // the robot, at rest on a frictionless floor, stays where it is too
    EXPECT_LT((result[0].position - start[0].position).head<2>().norm(), 1e-9);
}

TEST(PhysicsWorld, RestingRobotInSceneOneTouchesNothing)
{
    const PhysicsScene scene = benchmarkScene(1);
    PhysicsWorld world(shared(scene));
    world.setStates(world.startStates());
    const double depth = world.detectContacts();
    EXPECT_TRUE(world.touches().empty());
    EXPECT_LE(depth, 1e-9);  // everything rests on the floor, nothing overlaps
    run(world, Eigen::Vector2d::Zero(), 0.01, 10);
    EXPECT_TRUE(world.touches().empty());
}

TEST(PhysicsWorld, RobotAgainstAWallTouchesIt)
{
    // wall2 of scene 1 spans y in [-0.65, -0.35]; the robot stands on its north side at x = 0
    const PhysicsScene scene = benchmarkScene(1);
    const std::size_t wall2 = scene.bodyIndex("wall2");
    const double face = -0.35;
    ASSERT_NEAR(distanceToStartFootprint(scene, wall2, Eigen::Vector2d(0.0, face)), 0.0, 1e-12);
    PhysicsWorld world(shared(scene));
    BodyStates states = world.startStates();
    const double r = scene.robot.radius;

    states[0].position = Eigen::Vector3d(0.0, face + r - 0.001, r);  // 1 mm into the wall
    world.setStates(states);
    const double depth = world.detectContacts();
    EXPECT_EQ(world.touches(), std::vector<std::size_t>{wall2});
    EXPECT_NEAR(depth, 0.001, 1e-9);

    states[0].position = Eigen::Vector3d(0.0, face + r + 0.001, r);  // 1 mm away
    world.setStates(states);
    world.detectContacts();
    EXPECT_TRUE(world.touches().empty());

    // the robot driven into the wall reports it during the step
    states[0].position = Eigen::Vector3d(0.0, face + r + 0.001, r);
    states[0].linearVelocity = Eigen::Vector3d(0.0, -0.3, 0.0);
    world.setStates(states);
    bool touched = false;
    for (int k = 0; k < 5; ++k)
    {
        world.step(Eigen::Vector2d::Zero(), 0.01);
        touched = touched || world.touches() == std::vector<std::size_t>{wall2};
    }
    EXPECT_TRUE(touched);
}

TEST(PhysicsWorld, TouchesListEveryBodyOnceInOrder)
{
    // the robot squeezed into the corner between wall4 (y up to 0.55) and a cube moved beside it
    const PhysicsScene scene = benchmarkScene(1);
    PhysicsWorld world(shared(scene));
    const std::size_t wall4 = scene.bodyIndex("wall4");
    const std::size_t cube1 = scene.bodyIndex("cube1");
    BodyStates states = world.startStates();
    const double r = scene.robot.radius;
    states[0].position = Eigen::Vector3d(0.0, 0.55 + r - 0.001, r);
    // cube1 is moving body 1: clear of the wall, its west face 1 mm into the robot
    ASSERT_EQ(world.sceneBodyOf(1), cube1);
    states[1].position = Eigen::Vector3d(r - 0.001 + 0.1, 0.66, 0.1);
    world.setStates(states);
    world.detectContacts();
    std::vector<std::size_t> expected{wall4, cube1};
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(world.touches(), expected);
}

TEST(PhysicsWorld, SameStartAndForceGiveBitIdenticalStates)
{
    const PhysicsScene scene = benchmarkScene(1);
    PhysicsWorld world(shared(scene));
    const BodyStates start = world.startStates();
    const Eigen::Vector2d force(4.0, -3.0);
    const BodyStates first = simulate(world, start, force, 0.01, 40);
    const BodyStates second = simulate(world, start, force, 0.01, 40);
    EXPECT_TRUE(sameBits(first, second));
}

TEST(PhysicsWorld, PushingACubeIsBitIdenticalAfterResetRandomSeed)
{
    // the robot starts 2 mm west of cube1 and pushes it east: contacts between robot, cube and floor make
    // QuickStep draw from ODE's generator
    const PhysicsScene scene = benchmarkScene(1);
    PhysicsWorld world(shared(scene));
    const std::size_t cube1 = scene.bodyIndex("cube1");
    ASSERT_EQ(world.sceneBodyOf(1), cube1);
    BodyStates start = world.startStates();
    const double r = scene.robot.radius;
    const Eigen::Vector3d cubeCentre = start[1].position;
    start[0].position = Eigen::Vector3d(cubeCentre.x() - 0.1 - r - 0.002, cubeCentre.y(), r);
    const Eigen::Vector2d force(6.0, 0.5);

    // the first run, watching for the touch
    world.setStates(start);
    PhysicsWorld::resetRandomSeed();
    bool touchedCube = false;
    for (int k = 0; k < 60; ++k)
    {
        world.step(force, 0.01);
        for (std::size_t body : world.touches())
            touchedCube = touchedCube || body == cube1;
    }
    BodyStates first;
    world.readStates(first);
    ASSERT_TRUE(touchedCube);
    EXPECT_GT(first[1].position.x() - cubeCentre.x(), 0.01) << "the cube was not pushed";

    // another simulation in between, then the same one again
    simulate(world, world.startStates(), Eigen::Vector2d(-5.0, 5.0), 0.01, 30);
    const BodyStates second = simulate(world, start, force, 0.01, 60);
    EXPECT_TRUE(sameBits(first, second));
    // and in a second world built from the same scene
    PhysicsWorld other(shared(scene));
    const BodyStates third = simulate(other, start, force, 0.01, 60);
    EXPECT_TRUE(sameBits(first, third));
}

TEST(PhysicsWorld, MovablePrismIsRejected)
{
    PhysicsScene scene = smallScene();
    PhysicsBody &wedge = scene.bodies[scene.bodyIndex("wedge")];
    wedge.kind = BodyKind::Free;
    wedge.mass = 1.0;
    EXPECT_THROW(PhysicsWorld world(shared(scene)), ompl::Exception);
}
