// Tests for PhysicsSceneLoader: the benchmark scenes load as written, and every kind of bad input throws
// ompl_core::InputError naming the file and the line of the offending element or attribute.
#include "ompl_phys/scene/PhysicsSceneLoader.h"

#include "ompl_phys/common/PhysicsTestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

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

// --- every range: the value just outside is rejected with file:line, attribute and value; just inside is
// --- accepted ---------------------------------------------------------------------------------------------

namespace
{
    /** Parses lines as "test.xml", expecting no error. */
    PhysicsScene accepted(const std::vector<std::string> &lines)
    {
        PhysicsScene scene;
        const std::string message =
            inputErrorOf([&] { scene = parsePhysicsScene(joinLines(lines), "test.xml"); });
        EXPECT_EQ(message, "");
        return scene;
    }

    /** The small scene with <simulation> (line 2) carrying only these attributes. */
    std::vector<std::string> simulation(const std::string &attributes)
    {
        return replaced(2, "  <simulation " + attributes + "/>");
    }

    /** The small scene with <materials> (line 3) carrying only these attributes. */
    std::vector<std::string> materials(const std::string &attributes)
    {
        return replaced(3, "  <materials " + attributes + "/>");
    }

    /** The small scene with <limits> (line 4) carrying its regions and these attributes. */
    std::vector<std::string> limits(const std::string &attributes)
    {
        return replaced(
            4, R"(  <limits robot_region="-1 1 -1 1" body_region="-1.2 1.2 -1.2 1.2" )" + attributes + "/>");
    }

    /** limits() with one ODE sub-step per propagation step, so that up to 2000 steps per control
        stay within the work a control may take. */
    std::vector<std::string> limitsWithOneSubstep(const std::string &attributes)
    {
        std::vector<std::string> lines = limits(attributes);
        lines[1] = R"(  <simulation substeps="1"/>)";
        return lines;
    }

    /** The small scene with the free cube (line 9) made of these origin, shape and extra attributes. */
    std::vector<std::string> looseCube(const std::string &origin, const std::string &shape,
                                       const std::string &bodyAttributes = R"(kind="free" mass="0.5")")
    {
        return replaced(9, R"(  <body name="loose" )" + bodyAttributes + "><origin xyz=\"" + origin + "\"/>" +
                               shape + "</body>");
    }

    /** The small scene with the slider's <push> (line 13) carrying these attributes. */
    std::vector<std::string> push(const std::string &attributes)
    {
        return replaced(13, "    <push " + attributes + "/>");
    }

    const std::string PUSH_AXIS = R"(axis="1 0 0" )";
}  // namespace

TEST(PhysicsSceneLoader, ErpInItsRange)
{
    expectError(simulation(R"(erp="0")"), 2, "erp must be in [1e-06, 1], got 0");
    expectError(simulation(R"(erp="9e-7")"), 2, "erp must be in [1e-06, 1], got 9e-7");
    expectError(simulation(R"(erp="1.000001")"), 2, "erp must be in [1e-06, 1], got 1.000001");
    EXPECT_EQ(accepted(simulation(R"(erp="1e-6")")).contact.erp, 1e-6);
    EXPECT_EQ(accepted(simulation(R"(erp="1")")).contact.erp, 1.0);
}

TEST(PhysicsSceneLoader, CfmInItsRange)
{
    expectError(simulation(R"(cfm="-1e-9")"), 2, "cfm must be in [0, 1], got -1e-9");
    expectError(simulation(R"(cfm="1.000001")"), 2, "cfm must be in [0, 1], got 1.000001");
    EXPECT_EQ(accepted(simulation(R"(cfm="0")")).contact.cfm, 0.0);
    EXPECT_EQ(accepted(simulation(R"(cfm="1")")).contact.cfm, 1.0);
}

TEST(PhysicsSceneLoader, MaxContactsAndIterationsAreWholeNumbersInTheirRanges)
{
    struct Count
    {
        const char *attribute;
        unsigned int low, high;
        std::vector<const char *> bad;
        unsigned int ContactParameters::*field;
    };
    for (const Count &c :
         {Count{"max_contacts", 1, 16, {"0", "17", "2.5"}, &ContactParameters::maxContacts},
          Count{"iterations", 1, 1000, {"0", "1001", "20.5"}, &ContactParameters::iterations}})
    {
        const std::string range = " must be a whole number in [" + std::to_string(c.low) + ", " +
                                  std::to_string(c.high) + "], got ";
        for (const char *bad : c.bad)
            expectError(simulation(std::string(c.attribute) + "=\"" + bad + "\""), 2,
                        c.attribute + range + bad);
        for (unsigned int good : {c.low, c.high})
            EXPECT_EQ(
                accepted(simulation(std::string(c.attribute) + "=\"" + std::to_string(good) + "\"")).contact.*
                    c.field,
                good);
    }
}

TEST(PhysicsSceneLoader, SubstepsIsAWholeNumberInItsRange)
{
    expectError(simulation(R"(substeps="0")"), 2, "substeps must be a whole number in [1, 2000], got 0");
    expectError(simulation(R"(substeps="2001")"), 2,
                "substeps must be a whole number in [1, 2000], got 2001");
    EXPECT_EQ(accepted(simulation(R"(substeps="1")")).contact.substeps, 1u);
    // with the scene's max_steps of 10, 200 sub-steps make the most work a control may take
    EXPECT_EQ(accepted(simulation(R"(substeps="200")")).contact.substeps, 200u);
}

TEST(PhysicsSceneLoader, WorkPerControlIsBounded)
{
    // max_steps × substeps ODE sub-steps run without polling the time limit (a scene with huge values
    // ran 75 s under a 2 s limit)
    expectError(simulation(R"(substeps="201")"), 4,
                "max_steps × substeps = 10 × 201 = 2010 ODE sub-steps per control, more than 2000: one "
                "control's propagation could overrun the planner's time limit");
    std::vector<std::string> lines = limitsWithOneSubstep(R"(min_steps="1" max_steps="2000")");
    EXPECT_EQ(accepted(lines).limits.maxControlSteps, 2000u);
    lines[1] = R"(  <simulation substeps="2"/>)";
    expectError(lines, 4, "max_steps × substeps = 2000 × 2 = 4000 ODE sub-steps per control");
}

TEST(PhysicsSceneLoader, GravityPointsDownAndIsBounded)
{
    expectError(simulation(R"(gravity="down")"), 2, "malformed number 'down' in attribute 'gravity'");
    expectError(simulation(R"(gravity="-9.81 0")"), 2,
                "attribute 'gravity' of <simulation> needs 1 value, got 2");
    // -1e308 aborted ODE
    expectError(simulation(R"(gravity="-1e308")"), 2, "gravity must be in [-100, 0], got -1e308");
    expectError(simulation(R"(gravity="-100.001")"), 2, "gravity must be in [-100, 0], got -100.001");
    expectError(simulation(R"(gravity="0.001")"), 2, "gravity must be in [-100, 0], got 0.001");
    EXPECT_EQ(accepted(simulation(R"(gravity="0")")).contact.gravity, 0.0);
    EXPECT_EQ(accepted(simulation(R"(gravity="-100")")).contact.gravity, -100.0);
}

TEST(PhysicsSceneLoader, FrictionIsInItsRange)
{
    for (const char *attribute : {"robot_floor", "default"})
    {
        SCOPED_TRACE(attribute);
        const std::string name = attribute;
        expectError(materials(name + "=\"-0.001\""), 3, name + " must be in [0, 100], got -0.001");
        expectError(materials(name + "=\"100.001\""), 3, name + " must be in [0, 100], got 100.001");
    }
    const PhysicsScene zero = accepted(materials(R"(robot_floor="0" default="0")"));
    EXPECT_EQ(zero.materials.robotFloor, 0.0);
    EXPECT_EQ(zero.materials.defaultMu, 0.0);
    const PhysicsScene high = accepted(materials(R"(robot_floor="100" default="100")"));
    EXPECT_EQ(high.materials.robotFloor, 100.0);
    EXPECT_EQ(high.materials.defaultMu, 100.0);
    expectError(materials(R"(rubber="1")"), 3, "unknown attribute 'rubber' on <materials>");
}

TEST(PhysicsSceneLoader, SpeedsForceAndStepArePositiveAndBounded)
{
    const struct
    {
        const char *attribute, *high, *above;
    } limitsOf[] = {{"max_robot_speed", "100", "100.001"},
                    {"max_body_speed", "100", "100.001"},
                    {"max_angular_speed", "1000", "1000.001"},
                    {"max_force", "10000", "1e308"},  // 1e308 aborted ODE
                    {"step", "1", "1.001"}};
    for (const auto &limit : limitsOf)
    {
        SCOPED_TRACE(limit.attribute);
        const std::string name = limit.attribute;
        expectError(limits(name + "=\"0\""), 4,
                    "attribute '" + name + "' of <limits> must be positive, got 0");
        expectError(limits(name + "=\"-1\""), 4,
                    "attribute '" + name + "' of <limits> must be positive, got -1");
        expectError(limits(name + "=\"" + limit.above + "\""), 4,
                    name + " must be in [0, " + limit.high + "], got " + limit.above);
        accepted(limits(name + "=\"1e-9\""));
        accepted(limits(name + "=\"" + limit.high + "\""));
    }
    const PhysicsScene scene = accepted(limits(
        R"(max_robot_speed="1e-9" max_body_speed="2e-9" max_angular_speed="3e-9" max_force="4e-9" step="5e-9")"));
    EXPECT_EQ(scene.limits.maxRobotSpeed, 1e-9);
    EXPECT_EQ(scene.limits.maxBodySpeed, 2e-9);
    EXPECT_EQ(scene.limits.maxAngularSpeed, 3e-9);
    EXPECT_EQ(scene.limits.maxForce, 4e-9);
    EXPECT_EQ(scene.limits.stepSize, 5e-9);
}

TEST(PhysicsSceneLoader, ControlStepsInTheirRangeAndMaxNotBelowMin)
{
    for (const char *attribute : {"min_steps", "max_steps"})
    {
        SCOPED_TRACE(attribute);
        const std::string name = attribute;
        expectError(limits(name + "=\"0\""), 4, name + " must be a whole number in [1, 2000], got 0");
        expectError(limits(name + "=\"2001\""), 4, name + " must be a whole number in [1, 2000], got 2001");
        expectError(limits(name + "=\"1.5\""), 4, name + " must be a whole number in [1, 2000], got 1.5");
    }
    expectError(limits(R"(min_steps="5" max_steps="4")"), 4, "max_steps (4) must not be below min_steps (5)");
    // the default max_steps (10) is below a min_steps of 11
    expectError(limits(R"(min_steps="11")"), 4, "max_steps (10) must not be below min_steps (11)");
    const PhysicsScene equal = accepted(limits(R"(min_steps="5" max_steps="5")"));
    EXPECT_EQ(equal.limits.minControlSteps, 5u);
    EXPECT_EQ(equal.limits.maxControlSteps, 5u);
    // with one sub-step per step (the work per control is bounded: WorkPerControlIsBounded)
    EXPECT_EQ(accepted(limitsWithOneSubstep(R"(min_steps="1" max_steps="2000")")).limits.maxControlSteps,
              2000u);
    EXPECT_EQ(accepted(limitsWithOneSubstep(R"(min_steps="2000" max_steps="2000")")).limits.minControlSteps,
              2000u);
}

TEST(PhysicsSceneLoader, MassesLengthsAndPositionsAreBoundedForODE)
{
    // a mass of 1e200 aborted ODE; sizes and positions far outside a room are not simulated correctly
    expectError(replaced(6, R"(  <robot name="robot" radius="0.08" mass="1e200" start="-0.8 -0.8"/>)"), 6,
                "mass must be in [0.001, 1000], got 1e200");
    expectError(replaced(6, R"(  <robot name="robot" radius="0.08" mass="0.0009" start="-0.8 -0.8"/>)"), 6,
                "mass must be in [0.001, 1000], got 0.0009");
    expectError(looseCube("0.6 -0.4 0.1", R"(<box size="0.2 0.2 0.2"/>)", R"(kind="free" mass="1000.1")"), 9,
                "mass must be in [0.001, 1000], got 1000.1");
    expectError(replaced(6, R"(  <robot name="robot" radius="100.1" mass="1" start="-0.8 -0.8"/>)"), 6,
                "radius must be in [0.001, 100], got 100.1");
    expectError(looseCube("0.6 -0.4 0.1", R"(<box size="0.2 0.0009 0.2"/>)"), 9,
                "attribute 'size' of <box> must be in [0.001, 100] in every component, got '0.2 0.0009 0.2'");
    expectError(looseCube("0.6 -0.4 0.1", R"(<cylinder radius="0.1" length="100.1"/>)"), 9,
                "length must be in [0.001, 100], got 100.1");
    expectError(replaced(15, R"(  <goal xy="1000.1 -0.8" radius="0.1"/>)"), 15,
                "attribute 'xy' of <goal> must lie within ±1000 in every component, got '1000.1'");
    expectError(
        replaced(4, R"(  <limits robot_region="-1000.1 1 -1 1" body_region="-1.2 1.2 -1.2 1.2"/>)"), 4,
        "attribute 'robot_region' of <limits> must lie within ±1000 in every component, got '-1000.1'");
    // just inside
    const PhysicsScene heavy =
        accepted(replaced(6, R"(  <robot name="robot" radius="0.001" mass="1000" start="-0.8 -0.8"/>)"));
    EXPECT_EQ(heavy.robot.mass, 1000.0);
    EXPECT_EQ(heavy.robot.radius, 0.001);
    EXPECT_EQ(accepted(replaced(6, R"(  <robot name="robot" radius="0.08" mass="0.001" start="-0.8 -0.8"/>)"))
                  .robot.mass,
              0.001);
    accepted(looseCube("0.6 -0.4 0.1", R"(<box size="0.2 0.001 0.2"/>)"));
}

TEST(PhysicsSceneLoader, GoalBiasInItsRange)
{
    expectError(limits(R"(goal_bias="-0.000001")"), 4, "goal_bias must be in [0, 1], got -0.000001");
    expectError(limits(R"(goal_bias="1.000001")"), 4, "goal_bias must be in [0, 1], got 1.000001");
    EXPECT_EQ(accepted(limits(R"(goal_bias="0")")).limits.goalBias, 0.0);
    EXPECT_EQ(accepted(limits(R"(goal_bias="1")")).limits.goalBias, 1.0);
}

TEST(PhysicsSceneLoader, RegionsNeedMinBelowMax)
{
    const std::string minBelowMax = "must be \"xmin xmax ymin ymax\" with min < max";
    expectError(replaced(4, R"(  <limits robot_region="-1 1 1 -1" body_region="-1.2 1.2 -1.2 1.2"/>)"), 4,
                "robot_region " + minBelowMax);
    // equal bounds are not a region
    expectError(replaced(4, R"(  <limits robot_region="-1 -1 -1 1" body_region="-1.2 1.2 -1.2 1.2"/>)"), 4,
                "robot_region " + minBelowMax);
    expectError(replaced(4, R"(  <limits robot_region="-1 1 -1 1" body_region="1.2 -1.2 -1.2 1.2"/>)"), 4,
                "body_region " + minBelowMax);
    expectError(replaced(4, R"(  <limits robot_region="-1 1 -1 1" body_region="-1.2 1.2 0 0"/>)"), 4,
                "body_region " + minBelowMax);
    expectError(replaced(4, R"(  <limits robot_region="-1 1 -1" body_region="-1.2 1.2 -1.2 1.2"/>)"), 4,
                "attribute 'robot_region' of <limits> needs 4 values, got 3");
    // just inside: a region of width 1e-9 (about the robot's and the goal's x)
    std::vector<std::string> lines =
        replaced(4, R"(  <limits robot_region="-0.8 -0.799999999 -1 1" body_region="-1.2 1.2 -1.2 1.2"/>)");
    lines[14] = R"(  <goal xy="-0.8 0.8" radius="0.1"/>)";
    const PhysicsScene thin = accepted(lines);
    EXPECT_EQ(thin.limits.robotRegion.max().x(), -0.799999999);
}

TEST(PhysicsSceneLoader, NoRobotOrBodyRegion)
{
    // named at the robot's line, which the region is for
    expectError(replaced(4, R"(  <limits body_region="-1.2 1.2 -1.2 1.2"/>)"), 6,
                "no robot region: give <limits robot_region=\"xmin xmax ymin ymax\">");
    expectError(replaced(4, ""), 6, "no robot region");
    expectError(replaced(4, R"(  <limits robot_region="-1 1 -1 1"/>)"), 6,
                "no body region: give <limits body_region=\"xmin xmax ymin ymax\">");
}

TEST(PhysicsSceneLoader, FloorSizeIsTwoPositiveNumbers)
{
    expectError(replaced(5, R"(  <floor size="0 2.4"/>)"), 5, "the floor size must be two positive numbers");
    expectError(replaced(5, R"(  <floor size="2.4 -1"/>)"), 5, "the floor size must be two positive numbers");
    expectError(replaced(5, R"(  <floor size="2.4"/>)"), 5,
                "attribute 'size' of <floor> needs 2 values, got 1");
    EXPECT_TRUE(accepted(replaced(5, R"(  <floor size="1e-9 1e-9"/>)"))
                    .floorSize.isApprox(Eigen::Vector2d(1e-9, 1e-9)));
    // the floor is optional
    EXPECT_TRUE(accepted(replaced(5, "")).floorSize.isZero());
}

TEST(PhysicsSceneLoader, RootAttributes)
{
    expectError(replaced(1, R"(<physics_scene name="small" time_limit="0">)"), 1,
                "attribute 'time_limit' of <physics_scene> must be positive, got 0");
    expectError(replaced(1, R"(<physics_scene name="" time_limit="5">)"), 1,
                "attribute 'name' of <physics_scene> must not be empty");
    expectError(replaced(1, R"(<physics_scene name="small" author="me">)"), 1,
                "unknown attribute 'author' on <physics_scene> (allowed: name, time_limit)");
    EXPECT_EQ(accepted(replaced(1, R"(<physics_scene time_limit="1e-9">)")).timeLimit, 1e-9);
    // without a name, the file's stem names the scene
    EXPECT_EQ(accepted(replaced(1, R"(<physics_scene>)")).name, "test");
}

TEST(PhysicsSceneLoader, SecondSingleElement)
{
    std::vector<std::string> lines = smallSceneLines();
    lines.insert(lines.begin() + 2, R"(  <simulation erp="0.4"/>)");  // line 3
    expectError(lines, 3, "second <simulation> in <physics_scene>, only one is allowed (first at line 2)");
    lines = smallSceneLines();
    lines.insert(lines.begin() + 15,
                 R"(  <goal xy="0 0" radius="0.1"/>)");  // line 16, after the goal of line 15
    expectError(lines, 16, "second <goal> in <physics_scene>, only one is allowed (first at line 15)");
    lines = smallSceneLines();
    lines.insert(lines.begin() + 6, R"(  <robot radius="0.08" mass="1" start="0 0"/>)");  // line 7
    expectError(lines, 7, "second <robot>");
}

TEST(PhysicsSceneLoader, TextInAnElement)
{
    expectError(replaced(5, R"(  <floor size="2.4 2.4">big</floor>)"), 5, "unexpected text in <floor>");
    expectError(replaced(5, R"(  <floor size="2.4 2.4"><tile/></floor>)"), 5,
                "unknown element <tile> in <floor>");
}

TEST(PhysicsSceneLoader, RobotValues)
{
    expectError(replaced(6, R"(  <robot name="robot" radius="0" mass="1" start="-0.8 -0.8"/>)"), 6,
                "radius must be in [0.001, 100], got 0");
    expectError(replaced(6, R"(  <robot name="robot" radius="0.08" mass="0" start="-0.8 -0.8"/>)"), 6,
                "mass must be in [0.001, 1000], got 0");
    expectError(replaced(6, R"(  <robot name="robot" radius="0.08" start="-0.8 -0.8"/>)"), 6,
                "missing required attribute 'mass' on <robot>");
    expectError(replaced(6, R"(  <robot name="" radius="0.08" mass="1" start="-0.8 -0.8"/>)"), 6,
                "attribute 'name' of <robot> must not be empty");
    expectError(replaced(6, R"(  <robot name="robot" radius="0.08" mass="1" start="-0.8"/>)"), 6,
                "attribute 'start' of <robot> needs 2 values, got 1");
    const PhysicsScene scene =
        accepted(replaced(6, R"(  <robot name="r2" radius="0.001" mass="0.001" start="-0.8 -0.8"/>)"));
    EXPECT_EQ(scene.robot.name, "r2");
    EXPECT_EQ(scene.robot.radius, 0.001);
    EXPECT_EQ(scene.robot.mass, 0.001);
    EXPECT_EQ(scene.robot.start.z(), 0.001);  // on the floor
}

TEST(PhysicsSceneLoader, RobotStartJustInsideAndOutsideItsRegion)
{
    const std::string outside = "the robot starts outside its region (limits robot_region)";
    expectError(replaced(6, R"(  <robot name="robot" radius="0.08" mass="1" start="-1.001 -0.8"/>)"), 6,
                outside);
    expectError(replaced(6, R"(  <robot name="robot" radius="0.08" mass="1" start="-0.8 -1.001"/>)"), 6,
                outside);
    expectError(replaced(6, R"(  <robot name="robot" radius="0.08" mass="1" start="-0.8 1.001"/>)"), 6,
                outside);
    // the region bounds the centre, edges included
    accepted(replaced(6, R"(  <robot name="robot" radius="0.08" mass="1" start="-0.999 -0.999"/>)"));
    accepted(replaced(6, R"(  <robot name="robot" radius="0.08" mass="1" start="-1 -1"/>)"));
}

TEST(PhysicsSceneLoader, GoalJustInsideAndOutsideTheRobotRegion)
{
    const std::string outside = "the goal centre is outside the robot region (limits robot_region)";
    expectError(replaced(15, R"(  <goal xy="0.8 -1.001" radius="0.1"/>)"), 15, outside);
    expectError(replaced(15, R"(  <goal xy="1.001 -0.8" radius="0.1"/>)"), 15, outside);
    EXPECT_TRUE(accepted(replaced(15, R"(  <goal xy="0.999 -0.999" radius="0.1"/>)"))
                    .goal.centre.isApprox(Eigen::Vector2d(0.999, -0.999)));
    accepted(replaced(15, R"(  <goal xy="1 -1" radius="0.1"/>)"));
}

TEST(PhysicsSceneLoader, GoalValues)
{
    expectError(replaced(15, R"(  <goal xy="0.8 -0.8" radius="0"/>)"), 15,
                "radius must be in [0.001, 100], got 0");
    expectError(replaced(15, R"(  <goal radius="0.1"/>)"), 15, "missing required attribute 'xy' on <goal>");
    expectError(replaced(15, R"(  <goal xy="0.8 *" radius="0.1"/>)"), 15, "'*' (don't care) is not allowed");
    EXPECT_EQ(accepted(replaced(15, R"(  <goal xy="0.8 -0.8" radius="0.001"/>)")).goal.radius, 0.001);
}

TEST(PhysicsSceneLoader, MovableBodiesJustInsideAndOutsideTheBodyRegion)
{
    const std::string box = R"(<box size="0.2 0.2 0.2"/>)";
    expectError(looseCube("1.201 -0.4 0.1", box), 9,
                "body 'loose' starts outside the body region (limits body_region)");
    expectError(looseCube("0.6 -1.201 0.1", box), 9, "body 'loose' starts outside the body region");
    EXPECT_DOUBLE_EQ(accepted(looseCube("1.199 -0.4 0.1", box)).bodies[2].start.translation().x(), 1.199);
    accepted(looseCube("1.2 -1.2 0.1", box));  // edges included
    // a constrained body too, named at its own line
    std::vector<std::string> lines = smallSceneLines();
    lines[10] = R"(    <origin xyz="0 1.201 0.1" rpy="0 0 90deg"/>)";
    expectError(lines, 10, "body 'slider' starts outside the body region");
    lines[10] = R"(    <origin xyz="0 1.199 0.1" rpy="0 0 90deg"/>)";
    accepted(lines);
}

TEST(PhysicsSceneLoader, FixedBodyHasNoMassAndMovableBodiesNeedOne)
{
    expectError(
        replaced(
            7,
            R"(  <body name="wall" kind="fixed" mass="1"><origin xyz="0 0.8 0.1"/><box size="1 0.2 0.2"/></body>)"),
        7, "a fixed body has no mass");
    const std::string box = R"(<box size="0.2 0.2 0.2"/>)";
    expectError(looseCube("0.6 -0.4 0.1", box, R"(kind="free" mass="0")"), 9,
                "mass must be in [0.001, 1000], got 0");
    expectError(looseCube("0.6 -0.4 0.1", box, R"(kind="free")"), 9,
                "missing required attribute 'mass' on <body>");
    EXPECT_EQ(accepted(looseCube("0.6 -0.4 0.1", box, R"(kind="free" mass="0.001")")).bodies[2].mass, 0.001);
    // a constrained body needs one too
    std::vector<std::string> lines = smallSceneLines();
    lines[9] = R"(  <body name="slider" kind="constrained">)";
    expectError(lines, 10, "missing required attribute 'mass' on <body>");
}

TEST(PhysicsSceneLoader, BodyNameAndAttributes)
{
    const std::string box = R"(<box size="0.2 0.2 0.2"/>)";
    expectError(replaced(9, R"(  <body kind="free" mass="0.5"><box size="0.2 0.2 0.2"/></body>)"), 9,
                "missing required attribute 'name' on <body>");
    expectError(looseCube("0.6 -0.4 0.1", box, R"(kind="free" mass="0.5" colour="red")"), 9,
                "unknown attribute 'colour' on <body> (allowed: name, kind, mass)");
    expectError(looseCube("0.6 -0.4 0.1", box, R"(mass="0.5")"), 9,
                "missing required attribute 'kind' on <body>");
}

TEST(PhysicsSceneLoader, SecondOriginOrPushInABody)
{
    expectError(replaced(12, R"(    <box size="0.2 0.2 0.2"/><origin xyz="0 0 0.1"/>)"), 12,
                "second <origin> in body 'slider'");
    std::vector<std::string> lines = smallSceneLines();
    // line 12: a push, then the box; line 13: the push again
    lines[11] = lines[12] + "<box size=\"0.2 0.2 0.2\"/>";
    expectError(lines, 13, "second <push> in body 'slider'");
}

TEST(PhysicsSceneLoader, ShapeSizesAreInTheirRange)
{
    const std::string at = "0.6 -0.4 0.1";
    expectError(looseCube(at, R"(<box size="0.2 0 0.2"/>)"), 9,
                "attribute 'size' of <box> must be in [0.001, 100] in every component, got '0.2 0 0.2'");
    expectError(looseCube(at, R"(<box size="0.2 0.2"/>)"), 9,
                "attribute 'size' of <box> needs 3 values, got 2");
    expectError(looseCube(at, R"(<cylinder radius="0" length="0.2"/>)"), 9,
                "radius must be in [0.001, 100], got 0");
    expectError(looseCube(at, R"(<cylinder radius="0.1" length="0"/>)"), 9,
                "length must be in [0.001, 100], got 0");
    expectError(looseCube(at, R"(<sphere radius="-0.1"/>)"), 9, "radius must be in [0.001, 100], got -0.1");
    expectError(looseCube(at, R"(<sphere radius="0.1" length="0.2"/>)"), 9,
                "unknown attribute 'length' on <sphere> (allowed: radius)");
    expectError(
        replaced(
            8,
            R"(  <body name="wedge" kind="fixed"><prism corners="0.2 0 -0.1 0.17 -0.1 -0.17" length="0"/></body>)"),
        8, "length must be in [0.001, 100], got 0");
    expectError(
        replaced(
            8,
            R"(  <body name="wedge" kind="fixed"><prism corners="0.2 0 -0.1 0.17 -0.1" length="0.2"/></body>)"),
        8, "attribute 'corners' of <prism> needs 6 values, got 5");

    // just inside
    const PhysicsScene box = accepted(looseCube(at, R"(<box size="0.001 0.001 0.001"/>)"));
    EXPECT_TRUE(box.bodies[2].shape.boxSize.isApprox(Eigen::Vector3d::Constant(0.001)));
    const PhysicsScene cylinder = accepted(looseCube(at, R"(<cylinder radius="0.001" length="100"/>)"));
    EXPECT_EQ(cylinder.bodies[2].shape.kind, PhysicsShape::Kind::Cylinder);
    EXPECT_EQ(cylinder.bodies[2].shape.radius, 0.001);
    EXPECT_EQ(cylinder.bodies[2].shape.length, 100.0);
    const PhysicsScene sphere = accepted(looseCube(at, R"(<sphere radius="100"/>)"));
    EXPECT_EQ(sphere.bodies[2].shape.kind, PhysicsShape::Kind::Sphere);
    EXPECT_EQ(sphere.bodies[2].shape.radius, 100.0);
}

TEST(PhysicsSceneLoader, PrismAreaJustAboveAndBelowTheLimit)
{
    // twice the area of the triangle (0,0) (1,0) (0,h) is h; the limit is 1e-9
    const auto wedge = [](const std::string &h)
    {
        return replaced(8, R"(  <body name="wedge" kind="fixed"><prism corners="0 0 1 0 0 )" + h +
                               R"(" length="0.2"/></body>)");
    };
    expectError(wedge("0.5e-9"), 8, "the prism's corners must be counter-clockwise and not collinear");
    expectError(wedge("-2e-9"), 8, "counter-clockwise");
    EXPECT_EQ(accepted(wedge("2e-9")).bodies[1].shape.triangle(1, 2), 2e-9);
}

TEST(PhysicsSceneLoader, PushWidthsArePositive)
{
    const std::string angle = R"( angle_tolerance="10deg")";
    expectError(push(PUSH_AXIS + R"(strip_half_width="0" lateral_tolerance="0.03")" + angle), 13,
                "attribute 'strip_half_width' of <push> must be positive, got 0");
    expectError(push(PUSH_AXIS + R"(strip_half_width="0.06" lateral_tolerance="0")" + angle), 13,
                "attribute 'lateral_tolerance' of <push> must be positive, got 0");
    expectError(push(PUSH_AXIS + R"(lateral_tolerance="0.03")" + angle), 13,
                "missing required attribute 'strip_half_width' on <push>");
    const PhysicsScene scene =
        accepted(push(PUSH_AXIS + R"(strip_half_width="1e-9" lateral_tolerance="2e-9")" + angle));
    EXPECT_EQ(scene.bodies[3].push.stripHalfWidth, 1e-9);
    EXPECT_EQ(scene.bodies[3].push.lateralTolerance, 2e-9);
    expectError(push(PUSH_AXIS + R"(strip_half_width="0.06" lateral_tolerance="0.03" depth="1")" + angle), 13,
                "unknown attribute 'depth' on <push>");
}

TEST(PhysicsSceneLoader, PushAngleToleranceIsGivenAndPositive)
{
    const std::string widths = PUSH_AXIS + R"(strip_half_width="0.06" lateral_tolerance="0.03")";
    expectError(push(widths), 13, "angle_tolerance must be given and > 0");
    expectError(push(widths + R"( angle_tolerance="0")"), 13, "angle_tolerance must be given and > 0");
    expectError(push(widths + R"( angle_tolerance="-0.001deg")"), 13,
                "attribute 'angle_tolerance' of <push> must not be negative, got -0.001deg");
    expectError(push(widths + R"( angle_tolerance="wide")"), 13, "malformed number 'wide'");
    EXPECT_NEAR(accepted(push(widths + R"( angle_tolerance="0.001deg")")).bodies[3].push.angleTolerance,
                0.001 * PI / 180.0, 1e-18);
    EXPECT_EQ(accepted(push(widths + R"( angle_tolerance="1e-9")")).bodies[3].push.angleTolerance, 1e-9);
}

TEST(PhysicsSceneLoader, PushAxisJustAboveAndBelowZero)
{
    const std::string rest = R"( strip_half_width="0.06" lateral_tolerance="0.03" angle_tolerance="10deg")";
    expectError(push(R"(axis="1e-10 0 0")" + rest), 13, "the push axis must not be zero");
    expectError(push(R"(axis="1 0")" + rest), 13, "attribute 'axis' of <push> needs 3 values, got 2");
    expectError(push(rest), 13, "missing required attribute 'axis' on <push>");
    EXPECT_TRUE(
        accepted(push(R"(axis="0 1e-8 0")" + rest)).bodies[3].push.axis.isApprox(Eigen::Vector3d::UnitY()));
}

TEST(PhysicsSceneLoader, OriginValues)
{
    const std::string box = R"(<box size="0.2 0.2 0.2"/>)";
    expectError(
        replaced(
            9, R"(  <body name="loose" kind="free" mass="0.5"><origin xyz="0.6 -0.4 0.1" rpy="0 0 right"/>)" +
                   box + "</body>"),
        9, "malformed number 'right' in attribute 'rpy' of <origin>");
    expectError(replaced(9, R"(  <body name="loose" kind="free" mass="0.5"><origin xyz="0.6 -0.4"/>)" + box +
                                "</body>"),
                9, "attribute 'xyz' of <origin> needs 3 values, got 2");
    // without an origin a body stands at the world origin
    const PhysicsScene scene =
        accepted(replaced(9, R"(  <body name="loose" kind="free" mass="0.5">)" + box + "</body>"));
    EXPECT_TRUE(scene.bodies[2].start.isApprox(Eigen::Isometry3d::Identity()));
}

TEST(PhysicsSceneLoader, DirectoryInsteadOfAFile)
{
    const std::string message = inputErrorOf([&] { loadPhysicsScene(DATA_DIR); });
    EXPECT_EQ(message, DATA_DIR + ": is a directory, not a scene file");
}
