// Tests for PhysicsSceneLoader: the benchmark scenes load as written, and every kind of bad input throws
// ompl_core::InputError naming the file and the line of the offending element or attribute.
#include "ompl_phys/scene/PhysicsSceneLoader.h"

#include "ompl_phys/common/PhysicsTestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

using namespace ompl_phys;
using namespace ompl_phys::test;

namespace
{
    const double PI = std::acos(-1.0);
    const std::string DATA_DIR = std::string(OMPL_MM_TEST_DATA_DIR) + "/physics";

    std::string fileText(const std::string &path)
    {
        std::ifstream in(path);
        std::ostringstream text;
        text << in.rdbuf();
        return text.str();
    }

    /** How often pattern occurs in text: an independent count of what the file declares. */
    /** How often needle occurs in text (non-overlapping). */
    std::size_t occurrences(const std::string &text, const std::string &needle)
    {
        std::size_t count = 0;
        for (std::size_t at = text.find(needle); at != std::string::npos;
             at = text.find(needle, at + needle.size()))
            ++count;
        return count;
    }

    std::size_t countKind(const PhysicsScene &scene, BodyKind kind)
    {
        std::size_t n = 0;
        for (const PhysicsBody &body : scene.bodies)
            n += body.kind == kind ? 1 : 0;
        return n;
    }

    std::size_t countShape(const PhysicsScene &scene, PhysicsShape::Kind kind)
    {
        std::size_t n = 0;
        for (const PhysicsBody &body : scene.bodies)
            n += body.shape.kind == kind ? 1 : 0;
        return n;
    }

    /** smallSceneLines() with line `line` (1-based) replaced by text. */
    std::vector<std::string> replaced(int line, const std::string &text)
    {
        std::vector<std::string> lines = smallSceneLines();
        lines.at(static_cast<std::size_t>(line - 1)) = text;
        return lines;
    }

    /** Expects parsing xml as "test.xml" to fail at line `line` with a message containing phrase. */
    void expectError(const std::string &xml, int line, const std::string &phrase)
    {
        const std::string message = inputErrorOf([&] { parsePhysicsScene(xml, "test.xml"); });
        EXPECT_TRUE(startsWith(message, "test.xml:" + std::to_string(line) + ": ")) << message;
        EXPECT_TRUE(contains(message, phrase)) << message;
    }

    void expectError(const std::vector<std::string> &lines, int line, const std::string &phrase)
    {
        expectError(joinLines(lines), line, phrase);
    }
}  // namespace

// --- the benchmark scenes -------------------------------------------------------------------------------

TEST(PhysicsSceneLoader, BenchmarkScenesHaveTheBodiesTheirFilesDeclare)
{
    for (int n = 1; n <= 3; ++n)
    {
        SCOPED_TRACE("scene " + std::to_string(n));
        const std::string path = benchmarkScenePath(n);
        const std::string text = fileText(path);
        const PhysicsScene scene = loadPhysicsScene(path);
        EXPECT_EQ(scene.name, "scene" + std::to_string(n));
        EXPECT_EQ(scene.file, path);
        // counted independently in the file's text
        EXPECT_EQ(scene.bodies.size(), occurrences(text, "<body "));
        EXPECT_EQ(countKind(scene, BodyKind::Fixed), occurrences(text, R"(kind="fixed")"));
        EXPECT_EQ(countKind(scene, BodyKind::Free), occurrences(text, R"(kind="free")"));
        EXPECT_EQ(countKind(scene, BodyKind::Constrained), occurrences(text, R"(kind="constrained")"));
        EXPECT_EQ(countShape(scene, PhysicsShape::Kind::Box), occurrences(text, "<box "));
        EXPECT_EQ(countShape(scene, PhysicsShape::Kind::Prism), occurrences(text, "<prism "));
        EXPECT_EQ(scene.movableBodies().size(),
                  countKind(scene, BodyKind::Free) + countKind(scene, BodyKind::Constrained));

        // the common set-up of the three scenes (physics-facts.md, 1 unit = 1 cm)
        EXPECT_DOUBLE_EQ(scene.robot.radius, 0.08);
        EXPECT_DOUBLE_EQ(scene.robot.mass, 1.0);
        EXPECT_TRUE(scene.robot.start.isApprox(Eigen::Vector3d(-0.84, 0.97, 0.08)));
        EXPECT_TRUE(scene.goal.centre.isApprox(Eigen::Vector2d(0.92, -1.0)));
        EXPECT_DOUBLE_EQ(scene.goal.radius, 0.05);
        EXPECT_DOUBLE_EQ(scene.limits.maxForce, 10.0);
        EXPECT_DOUBLE_EQ(scene.limits.stepSize, 0.07);
        EXPECT_DOUBLE_EQ(scene.limits.goalBias, 0.05);
        EXPECT_EQ(scene.contact.substeps, 7u);
        EXPECT_DOUBLE_EQ(scene.materials.robotFloor, 0.0);
        EXPECT_DOUBLE_EQ(scene.materials.defaultMu, 0.7);
        for (const char *wall : {"room_north", "room_south", "room_east", "room_west"})
            EXPECT_EQ(scene.bodies[scene.bodyIndex(wall)].kind, BodyKind::Fixed) << wall;
        for (const PhysicsBody &body : scene.bodies)
        {
            if (body.kind == BodyKind::Fixed)
                continue;
            // movable cubes: 0.2 m, 0.5 kg, resting on the floor
            EXPECT_EQ(body.shape.kind, PhysicsShape::Kind::Box) << body.name;
            EXPECT_TRUE(body.shape.boxSize.isApprox(Eigen::Vector3d::Constant(0.2))) << body.name;
            EXPECT_DOUBLE_EQ(body.mass, 0.5) << body.name;
            EXPECT_NEAR(body.start.translation().z(), body.shape.halfHeight(), 1e-12) << body.name;
        }
    }
}

TEST(PhysicsSceneLoader, ConstrainedCubesPushAlongTheAxesOfThePaper)
{
    // scene 2: cube3 at (0.3, 0.4) with yaw 90 deg, pushable along the world y axis only
    const PhysicsScene scene2 = benchmarkScene(2);
    EXPECT_EQ(countKind(scene2, BodyKind::Constrained), 1u);
    const PhysicsBody &cube3 = scene2.bodies[scene2.bodyIndex("cube3")];
    EXPECT_EQ(cube3.kind, BodyKind::Constrained);
    EXPECT_TRUE(cube3.start.translation().head<2>().isApprox(Eigen::Vector2d(0.3, 0.4)));
    EXPECT_NEAR(yawOf(Eigen::Quaterniond(cube3.start.linear())), PI / 2, 1e-12);
    const Eigen::Vector3d worldAxis2 = cube3.start.linear() * cube3.push.axis;
    EXPECT_NEAR(std::abs(worldAxis2.y()), 1.0, 1e-12);
    EXPECT_NEAR(worldAxis2.x(), 0.0, 1e-12);
    EXPECT_DOUBLE_EQ(cube3.push.stripHalfWidth, 0.06);
    EXPECT_DOUBLE_EQ(cube3.push.lateralTolerance, 0.03);
    EXPECT_NEAR(cube3.push.angleTolerance, 10.0 * PI / 180.0, 1e-12);

    // scene 3: cube4 on the goal, pushable along x only
    const PhysicsScene scene3 = benchmarkScene(3);
    EXPECT_EQ(countKind(scene3, BodyKind::Constrained), 1u);
    const PhysicsBody &cube4 = scene3.bodies[scene3.bodyIndex("cube4")];
    EXPECT_EQ(cube4.kind, BodyKind::Constrained);
    const Eigen::Vector3d worldAxis3 = cube4.start.linear() * cube4.push.axis;
    EXPECT_NEAR(std::abs(worldAxis3.x()), 1.0, 1e-12);
    EXPECT_LT(distanceToStartFootprint(scene3, scene3.bodyIndex("cube4"), scene3.goal.centre),
              scene3.robot.radius);

    // scene 1 has no constrained body
    EXPECT_EQ(countKind(benchmarkScene(1), BodyKind::Constrained), 0u);
}

TEST(PhysicsSceneLoader, SmallSceneReadsEveryValue)
{
    const PhysicsScene scene = smallScene();
    EXPECT_EQ(scene.name, "small");
    EXPECT_EQ(scene.file, "small.xml");
    EXPECT_DOUBLE_EQ(scene.timeLimit, 5.0);
    EXPECT_DOUBLE_EQ(scene.contact.gravity, -9.81);
    EXPECT_DOUBLE_EQ(scene.contact.erp, 0.5);
    EXPECT_DOUBLE_EQ(scene.contact.cfm, 1e-4);
    EXPECT_EQ(scene.contact.maxContacts, 3u);
    EXPECT_EQ(scene.contact.iterations, 20u);
    EXPECT_EQ(scene.contact.substeps, 7u);
    EXPECT_TRUE(scene.limits.robotRegion.min().isApprox(Eigen::Vector2d(-1, -1)));
    EXPECT_TRUE(scene.limits.robotRegion.max().isApprox(Eigen::Vector2d(1, 1)));
    EXPECT_TRUE(scene.limits.bodyRegion.max().isApprox(Eigen::Vector2d(1.2, 1.2)));
    EXPECT_DOUBLE_EQ(scene.limits.maxRobotSpeed, 0.5);
    EXPECT_EQ(scene.limits.minControlSteps, 1u);
    EXPECT_EQ(scene.limits.maxControlSteps, 10u);
    EXPECT_TRUE(scene.floorSize.isApprox(Eigen::Vector2d(2.4, 2.4)));
    EXPECT_TRUE(scene.robot.start.isApprox(Eigen::Vector3d(-0.8, -0.8, 0.08)));
    EXPECT_EQ(scene.robot.where.line, 6);
    ASSERT_EQ(scene.bodies.size(), 4u);

    const PhysicsBody &wedge = scene.bodies[scene.bodyIndex("wedge")];
    EXPECT_EQ(wedge.shape.kind, PhysicsShape::Kind::Prism);
    EXPECT_DOUBLE_EQ(wedge.shape.length, 0.2);
    EXPECT_DOUBLE_EQ(wedge.shape.triangle(1, 1), 0.17);
    EXPECT_NEAR(yawOf(Eigen::Quaterniond(wedge.start.linear())), PI / 6, 1e-12);
    EXPECT_EQ(wedge.where.line, 8);

    const PhysicsBody &slider = scene.bodies[scene.bodyIndex("slider")];
    EXPECT_EQ(slider.kind, BodyKind::Constrained);
    EXPECT_EQ(slider.where.line, 10);
    EXPECT_TRUE(slider.push.axis.isApprox(Eigen::Vector3d::UnitX()));
    EXPECT_EQ(scene.movableBodies(), (std::vector<std::size_t>{2, 3}));
    EXPECT_EQ(scene.goal.where.line, 15);
}

TEST(PhysicsSceneLoader, PushAxisIsNormalised)
{
    const PhysicsScene scene =
        parsePhysicsScene(joinLines(replaced(13, R"(<push axis="3 4 0" strip_half_width="0.06" )"
                                                 R"(lateral_tolerance="0.03" angle_tolerance="0.1"/>)")),
                          "test.xml");
    EXPECT_TRUE(scene.bodies[scene.bodyIndex("slider")].push.axis.isApprox(Eigen::Vector3d(0.6, 0.8, 0.0)));
}

// --- bad input: each names file:line -----------------------------------------------------------------

TEST(PhysicsSceneLoader, MalformedXml)
{
    expectError(replaced(9, R"(  <body name="loose" kind="free" mass="0.5"><origin xyz="0.6 -0.4 0.1">)"
                            R"(<box size="0.2 0.2 0.2"/></body>)"),
                9, "XML");
}

TEST(PhysicsSceneLoader, WrongRoot)
{
    std::vector<std::string> lines = smallSceneLines();
    lines.front() = "<scene>";
    lines.back() = "</scene>";
    expectError(lines, 1, "<physics_scene>");
}

TEST(PhysicsSceneLoader, UnknownElement)
{
    expectError(replaced(5, R"(  <carpet colour="red"/>)"), 5, "<carpet>");
    // inside a body
    expectError(replaced(12, R"(    <box size="0.2 0.2 0.2"/><paint colour="red"/>)"), 12, "<paint>");
}

TEST(PhysicsSceneLoader, UnknownAttribute)
{
    expectError(
        replaced(6, R"(  <robot name="robot" radius="0.08" mass="1" start="-0.8 -0.8" colour="red"/>)"), 6,
        "colour");
}

TEST(PhysicsSceneLoader, AttributeOnItsOwnLineIsNamed)
{
    // the error names the attribute's line, not the line where its element starts
    expectError(replaced(2, "  <simulation gravity=\"-9.81\"\n      erp=\"2\"/>"), 3, "erp");
}

TEST(PhysicsSceneLoader, MissingRobotRadius)
{
    expectError(replaced(6, R"(  <robot name="robot" mass="1" start="-0.8 -0.8"/>)"), 6, "radius");
}

TEST(PhysicsSceneLoader, MissingRobotOrGoal)
{
    expectError(replaced(6, ""), 1, "<robot>");
    expectError(replaced(15, ""), 1, "<goal>");
}

TEST(PhysicsSceneLoader, NonNumericValue)
{
    expectError(replaced(6, R"(  <robot name="robot" radius="0.08" mass="heavy" start="-0.8 -0.8"/>)"), 6,
                "heavy");
    expectError(
        replaced(
            7,
            R"(  <body name="wall" kind="fixed"><origin xyz="0 0.8 0.1abc"/><box size="1 0.2 0.2"/></body>)"),
        7, "0.1abc");
}

TEST(PhysicsSceneLoader, OutOfRangeParameters)
{
    expectError(replaced(2, R"(  <simulation erp="2"/>)"), 2, "erp");
    expectError(replaced(2, R"(  <simulation substeps="0"/>)"), 2, "substeps");
    expectError(replaced(2, R"(  <simulation substeps="2.5"/>)"), 2, "substeps");
    expectError(
        replaced(4, R"(  <limits robot_region="-1 1 -1 1" body_region="-1.2 1.2 -1.2 1.2" goal_bias="-1"/>)"),
        4, "goal_bias");
    expectError(
        replaced(
            4,
            R"(  <limits robot_region="-1 1 -1 1" body_region="-1.2 1.2 -1.2 1.2" min_steps="5" max_steps="2"/>)"),
        4, "max_steps");
    expectError(replaced(4, R"(  <limits robot_region="1 -1 -1 1" body_region="-1.2 1.2 -1.2 1.2"/>)"), 4,
                "robot_region");
    expectError(
        replaced(4, R"(  <limits robot_region="-1 1 -1 1" body_region="-1.2 1.2 -1.2 1.2" step="0"/>)"), 4,
        "step");
    expectError(replaced(6, R"(  <robot name="robot" radius="-0.08" mass="1" start="-0.8 -0.8"/>)"), 6,
                "radius");
}

TEST(PhysicsSceneLoader, UnknownBodyKind)
{
    expectError(
        replaced(
            9,
            R"(  <body name="loose" kind="squishy" mass="0.5"><origin xyz="0.6 -0.4 0.1"/><box size="0.2 0.2 0.2"/></body>)"),
        9, "squishy");
}

TEST(PhysicsSceneLoader, DuplicateBodyName)
{
    expectError(
        replaced(
            9,
            R"(  <body name="wall" kind="free" mass="0.5"><origin xyz="0.6 -0.4 0.1"/><box size="0.2 0.2 0.2"/></body>)"),
        9, "line 7");
    // the robot's name is taken too
    expectError(
        replaced(
            9,
            R"(  <body name="robot" kind="free" mass="0.5"><origin xyz="0.6 -0.4 0.1"/><box size="0.2 0.2 0.2"/></body>)"),
        9, "robot");
}

TEST(PhysicsSceneLoader, ConstrainedBodyWithoutPush)
{
    expectError(replaced(13, ""), 10, "<push>");
}

TEST(PhysicsSceneLoader, PushOnAFreeBody)
{
    expectError(
        replaced(
            9,
            R"(  <body name="loose" kind="free" mass="0.5"><origin xyz="0.6 -0.4 0.1"/><box size="0.2 0.2 0.2"/>)"
            R"(<push axis="1 0 0" strip_half_width="0.06" lateral_tolerance="0.03" angle_tolerance="0.1"/></body>)"),
        9, "loose");
}

TEST(PhysicsSceneLoader, ZeroPushAxis)
{
    expectError(
        replaced(
            13,
            R"(    <push axis="0 0 0" strip_half_width="0.06" lateral_tolerance="0.03" angle_tolerance="10deg"/>)"),
        13, "axis");
}

TEST(PhysicsSceneLoader, MovablePrism)
{
    expectError(
        replaced(
            8,
            R"(  <body name="wedge" kind="free" mass="0.5"><origin xyz="-0.6 0.3 0.1"/><prism corners="0.2 0 -0.1 0.17 -0.1 -0.17" length="0.2"/></body>)"),
        8, "only be a fixed body");
}

TEST(PhysicsSceneLoader, PrismWithCollinearCorners)
{
    expectError(
        replaced(
            8,
            R"(  <body name="wedge" kind="fixed"><origin xyz="-0.6 0.3 0.1"/><prism corners="0 0 0.1 0 0.2 0" length="0.2"/></body>)"),
        8, "collinear");
    // clockwise corners are rejected with the same message
    expectError(
        replaced(
            8,
            R"(  <body name="wedge" kind="fixed"><origin xyz="-0.6 0.3 0.1"/><prism corners="0.2 0 -0.1 -0.17 -0.1 0.17" length="0.2"/></body>)"),
        8, "counter-clockwise");
}

TEST(PhysicsSceneLoader, TwoShapesInABody)
{
    expectError(replaced(12, R"(    <box size="0.2 0.2 0.2"/><sphere radius="0.1"/>)"), 12,
                "exactly one shape");
    // and none
    expectError(replaced(12, ""), 10, "exactly one shape");
}

TEST(PhysicsSceneLoader, RobotStartOutsideRobotRegion)
{
    expectError(replaced(6, R"(  <robot name="robot" radius="0.08" mass="1" start="1.1 0"/>)"), 6, "region");
}

TEST(PhysicsSceneLoader, GoalOutsideRobotRegion)
{
    expectError(replaced(15, R"(  <goal xy="1.5 0" radius="0.1"/>)"), 15, "region");
}

TEST(PhysicsSceneLoader, MovableBodyOutsideBodyRegion)
{
    expectError(
        replaced(
            9,
            R"(  <body name="loose" kind="free" mass="0.5"><origin xyz="1.3 0 0.1"/><box size="0.2 0.2 0.2"/></body>)"),
        9, "loose");
    // a fixed body may stand outside it (the room's walls do)
    EXPECT_NO_THROW(parsePhysicsScene(
        joinLines(replaced(
            7,
            R"(  <body name="wall" kind="fixed"><origin xyz="1.3 0 0.1"/><box size="0.1 1 0.2"/></body>)")),
        "test.xml"));
}

TEST(PhysicsSceneLoader, MissingFile)
{
    const std::string path = DATA_DIR + "/no_such_scene.xml";
    const std::string message = inputErrorOf([&] { loadPhysicsScene(path); });
    EXPECT_TRUE(startsWith(message, path + ": ")) << message;
    EXPECT_TRUE(contains(message, "not found")) << message;
}

TEST(PhysicsSceneLoader, FileErrorsNameThePath)
{
    // the file has an unknown element on the line that contains "<carpet"
    const std::string path = DATA_DIR + "/unknown_element.xml";
    const std::string text = fileText(path);
    ASSERT_FALSE(text.empty()) << path;
    const int line =
        1 + static_cast<int>(std::count(text.begin(), text.begin() + text.find("<carpet"), '\n'));
    const std::string message = inputErrorOf([&] { loadPhysicsScene(path); });
    EXPECT_TRUE(startsWith(message, path + ":" + std::to_string(line) + ": ")) << message;
    EXPECT_TRUE(contains(message, "carpet")) << message;
}
