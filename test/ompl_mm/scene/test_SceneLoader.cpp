// Tests for SceneLoader.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "ompl_core/io/XmlReading.h"

#include "common/MobileBlocked.h"
#include "ompl_core/io/NumberText.h"

using namespace ompl_mm;
using namespace ompl_mm::test;

namespace
{
    const std::string SCENES_DIR = OMPL_MM_SCENES_DIR;
    const std::string DATA_DIR = std::string(OMPL_MM_TEST_DATA_DIR) + "/scenes";
    const double PI = std::acos(-1.0);

    /** A small valid scene, one element per line, so that a test can replace line n (1-based) and
        expect the error at line n. URDF paths resolve against the scenes directory. */
    std::vector<std::string> validLines()
    {
        return {
            R"(<scene name="inline">)",                                                           // 1
            R"(  <robot urdf="robots/mobile_disc.urdf" tool_link="body"/>)",                      // 2
            R"(  <obstacle name="block"><origin xyz="1 1 0.5"/><box size="1 1 1"/></obstacle>)",  // 3
            R"(  <surface name="floor" height="0" min="-2.5 -2.5" max="2.5 2.5"/>)",              // 4
            R"(  <object name="obj1"><cylinder radius="0.2" length="0.5"/></object>)",            // 5
            R"(  <start>)",                                                                       // 6
            R"(    <robot joints="0 0"/>)",                                                       // 7
            R"(    <object name="obj1" xyz="-1 0 0"/>)",                                          // 8
            R"(  </start>)",                                                                      // 9
            R"(  <goal>)",                                                                        // 10
            R"(    <object name="obj1" xyz="1 * *"/>)",                                           // 11
            R"(  </goal>)",                                                                       // 12
            R"(  <primitives><transit/></primitives>)",                                           // 13
            R"(</scene>)",                                                                        // 14
        };
    }

    /** validLines() with line `line` (1-based) replaced by text. */
    std::vector<std::string> replaced(int line, const std::string &text)
    {
        std::vector<std::string> lines = validLines();
        lines.at(line - 1) = text;
        return lines;
    }

    Scene parseLines(const std::vector<std::string> &lines, const std::string &sourceName = "inline.xml")
    {
        std::string xml;
        for (const std::string &line : lines)
            xml += line + "\n";
        return parseScene(xml, sourceName, SCENES_DIR);
    }

    /** Expects parsing lines to fail at inline.xml:line with a message containing phrase. */
    void expectError(const std::vector<std::string> &lines, int line, const std::string &phrase)
    {
        const std::string message = inputErrorOf([&] { parseLines(lines); });
        EXPECT_TRUE(startsWith(message, "inline.xml:" + std::to_string(line) + ": ")) << message;
        EXPECT_TRUE(contains(message, phrase)) << message;
    }

    /** Expects loading DATA_DIR/name to fail with a message starting with the file and `where` and
        containing phrase; returns the message. */
    std::string expectLoadError(const std::string &name, const std::string &where, const std::string &phrase)
    {
        const std::string file = DATA_DIR + "/" + name;
        const std::string message = inputErrorOf([&] { loadScene(file); });
        EXPECT_TRUE(startsWith(message, file + where)) << message;
        EXPECT_TRUE(contains(message, phrase)) << message;
        return message;
    }

    /** The 1-based number of the first line of the file containing text. */
    int lineContaining(const std::string &file, const std::string &text)
    {
        std::ifstream in(file);
        std::string line;
        for (int number = 1; std::getline(in, line); ++number)
            if (line.find(text) != std::string::npos)
                return number;
        return 0;
    }
}  // namespace

TEST(SceneLoader, LoadsMobileBlocked)
{
    const std::string file = SCENES_DIR + "/mobile_blocked.xml";
    const Scene scene = loadScene(file);

    EXPECT_EQ(scene.name, "mobile_blocked");
    EXPECT_EQ(scene.file, file);
    EXPECT_DOUBLE_EQ(scene.timeLimit, 60.0);
    EXPECT_EQ(std::filesystem::path(scene.robot.urdfFile),
              std::filesystem::canonical(SCENES_DIR + "/robots/mobile_disc.urdf"));
    EXPECT_EQ(scene.robot.toolLink, "body");
    EXPECT_EQ(scene.robot.where.line, lineContaining(file, "<robot urdf="));

    EXPECT_EQ(scene.obstacles.size(), 7u);
    ASSERT_EQ(scene.surfaces.size(), 1u);
    EXPECT_EQ(scene.surfaces[0].name, "floor");
    EXPECT_DOUBLE_EQ(scene.surfaces[0].height, 0.0);
    EXPECT_TRUE(scene.surfaces[0].obstacle.empty());

    const std::vector<Eigen::Vector2d> starts{{-2.0, 0.3}, {0.8, -0.1}, {-1.5, -1.5}, {1.2, 1.9}};
    ASSERT_EQ(scene.objects.size(), 4u);
    for (std::size_t i = 0; i < starts.size(); ++i)
    {
        const MovableObject &object = scene.objects[i];
        EXPECT_EQ(object.name, "obj" + std::to_string(i + 1));
        EXPECT_EQ(object.shape.kind, Shape::Kind::Cylinder);
        EXPECT_DOUBLE_EQ(object.shape.radius, 0.2);
        EXPECT_DOUBLE_EQ(object.shape.height(), 0.5);
        EXPECT_TRUE(object.start.position.isApprox(Eigen::Vector3d(starts[i].x(), starts[i].y(), 0.0)));
        EXPECT_DOUBLE_EQ(object.start.yaw, 0.0);
    }
    EXPECT_EQ(scene.objectIndex("obj3"), 2);
    EXPECT_EQ(scene.objectIndex("nothing"), -1);
    EXPECT_EQ(scene.robotStart, (std::vector<double>{1.9, 1.9}));
    EXPECT_EQ(scene.robotStartWhere.line, lineContaining(file, "<robot joints=\"1.9 1.9\""));

    ASSERT_EQ(scene.robotGoal.joints.size(), 2u);
    EXPECT_EQ(scene.robotGoal.joints[0], 0.0);
    EXPECT_EQ(scene.robotGoal.joints[1], 0.0);
    EXPECT_DOUBLE_EQ(scene.robotGoal.tolerance, 0.01);
    ASSERT_EQ(scene.objectGoals.size(), 1u);
    const ObjectGoal &goal = scene.objectGoals[0];
    EXPECT_EQ(goal.object, "obj3");
    EXPECT_EQ(goal.position[0], -0.9);
    EXPECT_EQ(goal.position[1], -0.9);
    EXPECT_FALSE(goal.position[2].has_value());
    EXPECT_FALSE(goal.yaw.has_value());
    EXPECT_DOUBLE_EQ(goal.positionTolerance, 0.01);

    ASSERT_EQ(scene.primitives.size(), 2u);
    EXPECT_EQ(scene.primitives[0].type, "transit");
    EXPECT_TRUE(scene.primitives[0].params.empty());
    EXPECT_EQ(scene.primitives[1].type, "push_mobile");
    EXPECT_EQ(scene.primitives[1].params.at("standoff"), "0.41");

    EXPECT_EQ(scene.planner, "mopl");
    const std::vector<std::pair<std::string, std::string>> params{
        {"connect_step", "0.05"},          {"vertex_step", "0.35"},          {"moving_object_penalty", "0.6"},
        {"move_to_object_penalty", "0.1"}, {"move_to_object_factor", "1.0"}, {"restart_iterations", "5000"}};
    ASSERT_EQ(scene.plannerParams.size(), params.size());
    for (std::size_t i = 0; i < params.size(); ++i)
    {
        EXPECT_EQ(scene.plannerParams[i].name, params[i].first);
        EXPECT_EQ(scene.plannerParams[i].value, params[i].second);
    }
}

TEST(SceneLoader, SetPushModelGivesEveryPushTheModelAndNothingElse)
{
    Scene scene = loadScene(OMPL_MM_SCENES_DIR "/kuka_cabinet.xml");
    const std::vector<PrimitiveSpec> before = scene.primitives;
    scene.setPushModel("physics");
    unsigned int pushes = 0;
    for (std::size_t i = 0; i < before.size(); ++i)
    {
        std::map<std::string, std::string> expected = before[i].params;
        if (before[i].type.rfind("push_", 0) == 0)
        {
            expected["model"] = "physics";
            ++pushes;
        }
        EXPECT_EQ(scene.primitives[i].params, expected) << before[i].type;
    }
    EXPECT_EQ(pushes, 3u) << "push_interior, push_exterior, push_frontal";
    EXPECT_TRUE(contains(inputErrorOf([&] { scene.setPushModel("exact"); }),
                         "push model must be kinematic or physics, got 'exact'"));
}

TEST(SceneLoader, AnglesInDegreesOrRadians)
{
    std::vector<std::string> lines = replaced(
        3,
        R"(  <obstacle name="block"><origin xyz="1 1 0.5" rpy="0 0 90deg"/><box size="1 1 1"/></obstacle>)");
    lines.at(7) = R"(    <object name="obj1" xyz="-1 0 0" yaw="0.5"/>)";
    lines.at(10) = R"(    <object name="obj1" xyz="1 * *" yaw="-45deg" yaw_tolerance="2deg"/>)";
    const Scene scene = parseLines(lines);

    // rpy = (0, 0, 90 degrees) turns x onto y
    const Eigen::Vector3d turned = scene.obstacles[0].pose.linear() * Eigen::Vector3d::UnitX();
    EXPECT_TRUE(turned.isApprox(Eigen::Vector3d::UnitY())) << turned.transpose();
    EXPECT_DOUBLE_EQ(scene.objects[0].start.yaw, 0.5);
    EXPECT_DOUBLE_EQ(*scene.objectGoals[0].yaw, -PI / 4.0);
    EXPECT_DOUBLE_EQ(scene.objectGoals[0].yawTolerance, 2.0 * PI / 180.0);
}

TEST(SceneLoader, RpyComposesLikeUrdf)
{
    const Scene scene = parseLines(replaced(
        3, R"(  <obstacle name="block"><origin rpy="0.3 -0.2 1.1"/><box size="1 1 1"/></obstacle>)"));
    const Eigen::Matrix3d expected =
        (Eigen::AngleAxisd(1.1, Eigen::Vector3d::UnitZ()) *
         Eigen::AngleAxisd(-0.2, Eigen::Vector3d::UnitY()) * Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()))
            .toRotationMatrix();
    EXPECT_TRUE(scene.obstacles[0].pose.linear().isApprox(expected));
    EXPECT_TRUE(scene.obstacles[0].pose.translation().isZero());
}

TEST(SceneLoader, DefaultsWhenOptionalPartsAreAbsent)
{
    const Scene scene = parseLines(replaced(1, "<scene>"), "/some/dir/kitchen.xml");
    EXPECT_EQ(scene.name, "kitchen");
    EXPECT_DOUBLE_EQ(scene.timeLimit, 60.0);
    EXPECT_EQ(scene.planner, "mopl");
    EXPECT_TRUE(scene.plannerParams.empty());
    EXPECT_TRUE(scene.robot.basePose.isApprox(Eigen::Isometry3d::Identity()));
    EXPECT_TRUE(scene.robotGoal.joints.empty());
    const ObjectGoal &goal = scene.objectGoals.at(0);
    EXPECT_FALSE(goal.yaw.has_value());
    EXPECT_DOUBLE_EQ(goal.positionTolerance, 0.01);
    EXPECT_DOUBLE_EQ(goal.yawTolerance, 0.05);
}

TEST(SceneLoader, NumbersParseCompletelyAndFinitely)
{
    EXPECT_EQ(ompl_core::parseNumber("-0.25"), -0.25);
    EXPECT_EQ(ompl_core::parseNumber("+2e-3"), 2e-3);
    EXPECT_FALSE(ompl_core::parseNumber("0.3abc"));
    EXPECT_FALSE(ompl_core::parseNumber("nan"));
    EXPECT_FALSE(ompl_core::parseNumber("inf"));
    EXPECT_FALSE(ompl_core::parseNumber("1e999"));
    EXPECT_FALSE(ompl_core::parseNumber(""));
    EXPECT_DOUBLE_EQ(*ompl_core::parseAngle("180deg"), PI);
    EXPECT_FALSE(ompl_core::parseAngle("deg"));
    EXPECT_FALSE(ompl_core::parseAngle("90 deg"));
}

TEST(SceneLoader, MissingFileNamesTheFile)
{
    expectLoadError("no_such_scene.xml", ": ", "scene file not found");
}

TEST(SceneLoader, MalformedXmlNamesFileAndLine)
{
    const std::string message = expectLoadError("malformed.xml", ":5: ", "XML syntax error");
    EXPECT_TRUE(contains(message, "<box>")) << message;
}

TEST(SceneLoader, WrongRootElement)
{
    std::vector<std::string> lines = replaced(1, "<world>");
    lines.back() = "</world>";
    expectError(lines, 1, "the root element must be <scene>, found <world>");
}

TEST(SceneLoader, UnknownElement)
{
    expectError(replaced(3, R"(  <obstcle name="block"><box size="1 1 1"/></obstcle>)"), 3,
                "unknown element <obstcle> in <scene>");
}

TEST(SceneLoader, ObjectsHaveAMassAndAFriction)
{
    const Scene defaults = parseLines(validLines());
    EXPECT_EQ(defaults.objects.at(0).mass, MovableObject::DEFAULT_MASS);
    EXPECT_EQ(defaults.objects.at(0).friction, MovableObject::DEFAULT_FRICTION);
    const Scene given = parseLines(replaced(
        5,
        R"(  <object name="obj1" mass="2.5" friction="0.3"><cylinder radius="0.2" length="0.5"/></object>)"));
    EXPECT_EQ(given.objects.at(0).mass, 2.5);
    EXPECT_EQ(given.objects.at(0).friction, 0.3);
    for (const char *bad : {R"(mass="0")", R"(mass="-1")", R"(mass="1001")", R"(mass="heavy")",
                            R"(friction="-0.1")", R"(friction="6")"})
        expectError(replaced(5, std::string(R"(  <object name="obj1" )") + bad +
                                    R"(><cylinder radius="0.2" length="0.5"/></object>)"),
                    5, std::string(bad).substr(0, std::string(bad).find('=')));
    expectError(replaced(3, R"(  <obstacle name="block" mass="2"><box size="1 1 1"/></obstacle>)"), 3,
                "unknown attribute 'mass' on <obstacle>");
}

TEST(SceneLoader, UnknownAttribute)
{
    expectError(
        replaced(4, R"(  <surface name="floor" height="0" min="-2.5 -2.5" max="2.5 2.5" colour="red"/>)"), 4,
        "unknown attribute 'colour' on <surface>");
}

TEST(SceneLoader, MissingRequiredAttribute)
{
    expectError(replaced(4, R"(  <surface name="floor" min="-2.5 -2.5" max="2.5 2.5"/>)"), 4,
                "missing required attribute 'height' on <surface>");
}

TEST(SceneLoader, MalformedNumber)
{
    for (const std::string bad : {"0.3abc", "nan", "inf"})
        expectError(replaced(8, R"(    <object name="obj1" xyz="-1 )" + bad + R"( 0"/>)"), 8,
                    "malformed number '" + bad + "' in attribute 'xyz' of <object>");
}

TEST(SceneLoader, WrongNumberOfValues)
{
    expectError(replaced(8, R"(    <object name="obj1" xyz="-1 0"/>)"), 8,
                "attribute 'xyz' of <object> needs 3 values, got 2");
}

TEST(SceneLoader, SizesLieBetweenAMillimetreAndAHundredMetres)
{
    expectError(replaced(5, R"(  <object name="obj1"><cylinder radius="0" length="0.5"/></object>)"), 5,
                "radius must be in [0.001, 100], got 0");
    expectError(replaced(3, R"(  <obstacle name="block"><box size="1 -1 1"/></obstacle>)"), 3,
                "attribute 'size' of <box> must be in [0.001, 100] in every component, got '1 -1 1'");
    // a cylinder of length 1e308 was accepted, and plans went through it
    expectError(replaced(5, R"(  <object name="obj1"><cylinder radius="0.2" length="1e308"/></object>)"), 5,
                "length must be in [0.001, 100], got 1e308");
}

TEST(SceneLoader, AtMostSixtyFourObjects)
{
    // the metric keeps sets of objects as bits of a 64-bit word: the 65th object is named at its line
    const auto withObjects = [](unsigned int extra)
    {
        std::vector<std::string> lines = validLines();
        for (unsigned int k = 0; k < extra; ++k)
            lines.insert(lines.begin() + 5, R"(  <object name="extra)" + std::to_string(k) +
                                                R"("><cylinder radius="0.2" length="0.5"/></object>)");
        return lines;
    };
    expectError(withObjects(64), 69, "a scene holds at most 64 movable objects");
    // just inside: 64 objects load (the extra ones have no start, which is the next error)
    expectError(withObjects(63), 6, "object 'extra62' has no start");
}

TEST(SceneLoader, DuplicateName)
{
    expectError(replaced(5, R"(  <object name="block"><cylinder radius="0.2" length="0.5"/></object>)"), 5,
                "duplicate name 'block' (first at line 3)");
}

TEST(SceneLoader, StartForUnknownObject)
{
    expectError(replaced(8, R"(    <object name="obj9" xyz="-1 0 0"/>)"), 8,
                "start for unknown object 'obj9'");
}

TEST(SceneLoader, ObjectWithoutStart)
{
    // the error points at the object's declaration, the line to look at for its name
    expectError(replaced(8, ""), 5, "object 'obj1' has no start");
}

TEST(SceneLoader, GoalForUnknownObject)
{
    expectError(replaced(11, R"(    <object name="obj2" xyz="1 * *"/>)"), 11,
                "goal for unknown object 'obj2'");
}

TEST(SceneLoader, MissingUrdfNamesTheRobotLine)
{
    expectLoadError("missing_urdf.xml", ":4: ", "URDF file 'robots/no_such_robot.urdf' not found");
}

TEST(SceneLoader, SurfaceMinNotBelowMax)
{
    expectError(replaced(4, R"(  <surface name="floor" height="0" min="-2.5 2.5" max="2.5 2.5"/>)"), 4,
                "surface 'floor': min must be less than max");
}

TEST(SceneLoader, NegativeTolerance)
{
    expectError(replaced(11, R"(    <object name="obj1" xyz="1 * *" tolerance="-0.01"/>)"), 11,
                "attribute 'tolerance' of <object> must not be negative");
}

TEST(SceneLoader, StartObjectOffEverySurface)
{
    expectError(replaced(8, R"(    <object name="obj1" xyz="-1 0 0.3"/>)"), 8,
                "start of object 'obj1' does not rest on any <surface>");
}

TEST(SceneLoader, SceneWithoutSurfaceIsRejectedAtTheRoot)
{
    // at least one support surface is needed; the error points at <scene>
    expectError(replaced(4, ""), 1, "missing <surface> in <scene> (at least one support surface is needed)");
}

TEST(SceneLoader, SceneWithoutStartGoalOrPrimitivesIsRejectedAtTheRoot)
{
    // each of <start>, <goal> and <primitives> is required; the error points at <scene>
    const std::vector<std::pair<std::string, std::vector<int>>> sections{
        {"start", {6, 7, 8, 9}}, {"goal", {10, 11, 12}}, {"primitives", {13}}};
    for (const auto &[tag, lines] : sections)
    {
        std::vector<std::string> without = validLines();
        for (int line : lines)
            without.at(line - 1) = "";
        expectError(without, 1, "missing <" + tag + "> in <scene>");
    }
}

TEST(SceneLoader, BodyWithoutShapeIsRejected)
{
    // an object or obstacle needs one shape; zero is reported at the body, naming it
    expectError(replaced(5, R"(  <object name="obj1"></object>)"), 5,
                "<object> 'obj1' needs exactly one shape (<box>, <cylinder> or <sphere>), found 0");
    expectError(replaced(3, R"(  <obstacle name="block"><origin xyz="1 1 0.5"/></obstacle>)"), 3,
                "<obstacle> 'block' needs exactly one shape (<box>, <cylinder> or <sphere>), found 0");
}

TEST(SceneLoader, BodyWithTwoShapesIsRejectedAtTheSecondShape)
{
    // the error points at the second shape, the one to remove
    expectError(
        replaced(3,
                 "  <obstacle name=\"block\"><box size=\"1 1 1\"/>\n    <sphere radius=\"0.5\"/></obstacle>"),
        4, "<obstacle> 'block' needs exactly one shape (<box>, <cylinder> or <sphere>), found 2");
    expectError(replaced(5,
                         "  <object name=\"obj1\"><cylinder radius=\"0.2\" length=\"0.5\"/>\n"
                         "    <box size=\"0.1 0.1 0.1\"/></object>"),
                6, "<object> 'obj1' needs exactly one shape (<box>, <cylinder> or <sphere>), found 2");
}

TEST(SceneLoader, SurfaceMinMustBeBelowMaxInXAndAnyPositiveSizeIsAccepted)
{
    const std::string floor = validLines().at(3);
    // equal or reversed in x is rejected, naming the surface; 1e-6 wide in both is accepted
    expectError(replaced(4, floor + R"( <surface name="shelf" height="1" min="0 0" max="0 1"/>)"), 4,
                "surface 'shelf': min must be less than max in both x and y");
    expectError(replaced(4, floor + R"( <surface name="shelf" height="1" min="0.5 0" max="0.4 1"/>)"), 4,
                "surface 'shelf': min must be less than max");
    const Scene scene =
        parseLines(replaced(4, floor + R"( <surface name="shelf" height="1" min="0 0" max="1e-6 1e-6"/>)"));
    ASSERT_EQ(scene.surfaces.size(), 2u);
    EXPECT_EQ(scene.surfaces[1].max, Eigen::Vector2d(1e-6, 1e-6));
}

TEST(SceneLoader, SurfaceNamingAnUnknownObstacleIsRejected)
{
    // the obstacle attribute must name one of the scene's <obstacle>s
    expectError(
        replaced(4, R"(  <surface name="floor" height="0" min="-2.5 -2.5" max="2.5 2.5" obstacle="table"/>)"),
        4, "surface 'floor' names unknown obstacle 'table'");
    const Scene scene = parseLines(replaced(
        4, R"(  <surface name="floor" height="0" min="-2.5 -2.5" max="2.5 2.5" obstacle="block"/>)"));
    EXPECT_EQ(scene.surfaces.at(0).obstacle, "block");
}

TEST(SceneLoader, RegionMinMustBeBelowMaxInEveryAxis)
{
    const std::string floor = validLines().at(3);
    // equal in z is rejected, naming the region; just above in z is accepted
    expectError(replaced(4, floor + R"( <region name="air" min="-1 -1 1" max="1 1 1"/>)"), 4,
                "region 'air': min must be less than max in x, y and z");
    expectError(replaced(4, floor + R"( <region name="air" min="1 -1 0" max="-1 1 1"/>)"), 4,
                "region 'air': min must be less than max in x, y and z");
    const Scene scene =
        parseLines(replaced(4, floor + R"( <region name="air" min="-1 -1 1" max="1 1 1.0001"/>)"));
    ASSERT_EQ(scene.samplingRegions.size(), 1u);
    EXPECT_EQ(scene.samplingRegions[0].name, "air");
    EXPECT_DOUBLE_EQ(scene.samplingRegions[0].box.max().z(), 1.0001);
}

TEST(SceneLoader, DuplicateSurfaceOrRegionNameNamesTheFirstLine)
{
    const std::string floor = validLines().at(3);
    expectError(replaced(4, floor + "\n" + floor), 5, "duplicate surface name 'floor' (first at line 4)");
    const std::string region = R"(  <region name="air" min="-1 -1 0" max="1 1 1"/>)";
    expectError(replaced(4, floor + region + "\n" + region), 5,
                "duplicate region name 'air' (first at line 4)");
}

TEST(SceneLoader, StartWithoutRobotJointsIsRejectedAtTheStart)
{
    expectError(replaced(7, ""), 6, "missing <robot joints=\"...\"/> in <start>");
}

TEST(SceneLoader, SecondStartOrGoalForAnObjectNamesTheFirstLine)
{
    const std::vector<std::string> lines = validLines();
    expectError(replaced(8, lines.at(7) + "\n" + lines.at(7)), 9,
                "second start for object 'obj1' (first at line 8)");
    expectError(replaced(11, lines.at(10) + "\n" + lines.at(10)), 12,
                "second goal for object 'obj1' (first at line 11)");
}

TEST(SceneLoader, StartRestsWithinTheToleranceAndInsideTheSurfaceEdges)
{
    // z within 1e-4 of the surface and x, y on its edges rest; just beyond either does not
    for (const char *xyz : {"-1 0 0.00009", "-1 0 -0.00009", "2.5 -2.5 0", "-2.5 2.5 0"})
        EXPECT_EQ(
            inputErrorOf(
                [&]
                { parseLines(replaced(8, std::string(R"(    <object name="obj1" xyz=")") + xyz + "\"/>")); }),
            "")
            << xyz;
    for (const char *xyz : {"-1 0 0.00011", "-1 0 -0.00011", "2.5001 0 0", "0 -2.5001 0"})
        expectError(replaced(8, std::string(R"(    <object name="obj1" xyz=")") + xyz + "\"/>"), 8,
                    "start of object 'obj1' does not rest on any <surface>");
}

TEST(SceneLoader, GoalWithoutChildrenIsRejected)
{
    expectError(replaced(11, ""), 10, "<goal> needs at least one <robot> or <object> child");
}

TEST(SceneLoader, EmptyPrimitivesIsRejected)
{
    expectError(replaced(13, "  <primitives></primitives>"), 13,
                "<primitives> needs at least one primitive, e.g. <transit/>");
}

TEST(SceneLoader, SecondPlannerParamNamesTheFirstLine)
{
    const std::string planner =
        "\n  <planner type=\"mopl\">\n    <param name=\"connect_step\" value=\"0.05\"/>\n"
        "    <param name=\"connect_step\" value=\"0.1\"/>\n  </planner>";
    expectError(replaced(13, validLines().at(12) + planner), 16,
                "second <param> 'connect_step' (first at line 15)");
}

TEST(SceneLoader, TimeLimitMustBePositive)
{
    expectError(replaced(1, R"(<scene name="inline" time_limit="0">)"), 1,
                "attribute 'time_limit' of <scene> must be positive, got 0");
    EXPECT_DOUBLE_EQ(parseLines(replaced(1, R"(<scene name="inline" time_limit="0.001">)")).timeLimit, 0.001);
}

TEST(SceneLoader, ZeroTolerancesAreAcceptedAndNegativeOnesRejected)
{
    // tolerances may be 0 (exact goals), not below
    const Scene scene = parseLines(
        replaced(11, R"(    <object name="obj1" xyz="1 * *" yaw="0" tolerance="0" yaw_tolerance="0"/>)"));
    EXPECT_EQ(scene.objectGoals.at(0).positionTolerance, 0.0);
    EXPECT_EQ(scene.objectGoals.at(0).yawTolerance, 0.0);
    expectError(replaced(11, R"(    <object name="obj1" xyz="1 * *" yaw="0" yaw_tolerance="-1deg"/>)"), 11,
                "attribute 'yaw_tolerance' of <object> must not be negative, got -1deg");
    std::vector<std::string> lines = validLines();
    lines.at(10) += "\n    <robot joints=\"0 0\" tolerance=\"0\"/>";
    EXPECT_EQ(parseLines(lines).robotGoal.tolerance, 0.0);
    lines.at(10) = validLines().at(10) + "\n    <robot joints=\"0 0\" tolerance=\"-0.001\"/>";
    expectError(lines, 12, "attribute 'tolerance' of <robot> must not be negative, got -0.001");
}

TEST(Shape, FootprintAndBoundingRadii)
{
    Shape box;
    box.boxSize = {0.6, 0.8, 1.2};
    EXPECT_DOUBLE_EQ(box.footprintRadius(), 0.5);
    EXPECT_DOUBLE_EQ(box.boundingRadius(), 0.5 * std::sqrt(0.36 + 0.64 + 1.44));
    Shape cylinder;
    cylinder.kind = Shape::Kind::Cylinder;
    cylinder.radius = 0.3;
    cylinder.length = 0.8;
    EXPECT_DOUBLE_EQ(cylinder.footprintRadius(), 0.3);
    EXPECT_DOUBLE_EQ(cylinder.boundingRadius(), 0.5);
    Shape sphere;
    sphere.kind = Shape::Kind::Sphere;
    sphere.radius = 0.25;
    EXPECT_DOUBLE_EQ(sphere.footprintRadius(), 0.25);
    EXPECT_DOUBLE_EQ(sphere.boundingRadius(), 0.25);
    Shape broken;
    broken.kind = static_cast<Shape::Kind>(7);
    EXPECT_THROW(broken.footprintRadius(), ompl::Exception);
    EXPECT_THROW(broken.boundingRadius(), ompl::Exception);
}

TEST(SceneLoader, ToolFramesAreNamedFramesOnLinks)
{
    const Scene scene = parseLines(replaced(
        2,
        R"(  <robot urdf="robots/mobile_disc.urdf" tool_link="body"><tool name="grasp" link="body"><origin xyz="0 0 0.2" rpy="0 90deg 0"/></tool><tool name="push" link="slider"/></robot>)"));
    ASSERT_EQ(scene.robot.tools.size(), 2u);
    const ToolFrame &grasp = scene.robot.tools[0];
    EXPECT_EQ(grasp.name, "grasp");
    EXPECT_EQ(grasp.link, "body");
    EXPECT_EQ(grasp.where.line, 2);
    EXPECT_LT((grasp.pose.translation() - Eigen::Vector3d(0, 0, 0.2)).norm(), 1e-15);
    EXPECT_LT((grasp.pose.linear() * Eigen::Vector3d::UnitZ() - Eigen::Vector3d::UnitX()).norm(), 1e-12)
        << "turned 90 deg about y";
    EXPECT_TRUE(scene.robot.tools[1].pose.isApprox(Eigen::Isometry3d::Identity()))
        << "no origin: the link's frame";
}

TEST(SceneLoader, ToolFrameErrors)
{
    const std::string robot = R"(  <robot urdf="robots/mobile_disc.urdf" tool_link="body">)";
    expectError(replaced(2, robot + R"(<tool name="a" link="body"/><tool name="a" link="slider"/></robot>)"),
                2, "duplicate tool frame 'a'");
    expectError(replaced(2, robot + R"(<tool name="a"/></robot>)"), 2, "link");
    expectError(replaced(2, robot + R"(<tool name="a" link="body" frame="x"/></robot>)"), 2, "frame");
    expectError(replaced(2, robot + R"(<tool name="a" link="body"><origin/><origin/></tool></robot>)"), 2,
                "origin");
}

TEST(SceneLoader, FixedJointsAreReadInFileOrder)
{
    const Scene scene = parseLines(replaced(
        2,
        R"(  <robot urdf="robots/mobile_disc.urdf" tool_link="body"><fixed_joint name="y" value="0.5"/><fixed_joint name="x" value="-1"/></robot>)"));
    ASSERT_EQ(scene.robot.fixedJoints.size(), 2u);
    EXPECT_EQ(scene.robot.fixedJoints[0].joint, "y");
    EXPECT_EQ(scene.robot.fixedJoints[0].value, 0.5);
    EXPECT_EQ(scene.robot.fixedJoints[0].where.line, 2);
    EXPECT_EQ(scene.robot.fixedJoints[1].joint, "x");
    EXPECT_EQ(scene.robot.fixedJoints[1].value, -1.0);
}

TEST(SceneLoader, FixedJointErrors)
{
    const std::string robot = R"(  <robot urdf="robots/mobile_disc.urdf" tool_link="body">)";
    expectError(
        replaced(2, robot + R"(<fixed_joint name="x" value="0"/><fixed_joint name="x" value="1"/></robot>)"),
        2, "joint 'x' is fixed twice");
    expectError(replaced(2, robot + R"(<fixed_joint name="x"/></robot>)"), 2, "value");
    expectError(replaced(2, robot + R"(<fixed_joint name="x" value="open"/></robot>)"), 2, "value");
    expectError(replaced(2, robot + R"(<fixed_joint name="x" value="0" unit="m"/></robot>)"), 2, "unit");
}

TEST(SceneLoader, SrdfGroupAndNamedStatesAreRead)
{
    std::vector<std::string> lines = replaced(
        2,
        R"(  <robot urdf="robots/panda/franka_panda/panda.urdf" srdf="robots/panda/franka_panda/panda.srdf" group="panda_arm" tool_link="panda_hand"/>)");
    lines.at(6) = R"(    <robot state="ready"/>)";
    lines.at(10) = R"(    <robot state="extended" tolerance="0.02"/><object name="obj1" xyz="1 * *"/>)";
    const Scene scene = parseLines(lines);
    EXPECT_EQ(scene.robot.srdfFile, SCENES_DIR + "/robots/panda/franka_panda/panda.srdf");
    EXPECT_EQ(scene.robot.group, "panda_arm");
    EXPECT_EQ(scene.robotStartState, "ready");
    EXPECT_TRUE(scene.robotStart.empty());
    EXPECT_EQ(scene.robotGoal.state, "extended");
    EXPECT_EQ(scene.robotGoal.tolerance, 0.02);
}

TEST(SceneLoader, SrdfErrors)
{
    expectError(replaced(2, R"(  <robot urdf="robots/mobile_disc.urdf" srdf="none.srdf" tool_link="body"/>)"),
                2, "SRDF file 'none.srdf' not found");
    expectError(replaced(2, R"(  <robot urdf="robots/mobile_disc.urdf" group="arm" tool_link="body"/>)"), 2,
                "a planning group needs an SRDF file");
    expectError(replaced(7, R"(    <robot state="ready"/>)"), 7, "a named state needs an SRDF file");
    expectError(replaced(7, R"(    <robot joints="0 0" state="ready"/>)"), 7,
                "<robot> in <start> needs either joints=\"...\" or state=\"NAME\"");
    expectError(replaced(7, R"(    <robot/>)"), 7, "<robot> in <start> needs either");
}

TEST(SceneLoader, ToolOffsetTakesARotation)
{
    const Scene scene = parseLines(replaced(
        2,
        R"(  <robot urdf="robots/mobile_disc.urdf" tool_link="body"><tool_offset xyz="0 0 0.1" rpy="0 0 90deg"/></robot>)"));
    EXPECT_LT((scene.robot.toolOffset.translation() - Eigen::Vector3d(0, 0, 0.1)).norm(), 1e-15);
    EXPECT_LT((scene.robot.toolOffset.linear() * Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitY()).norm(),
              1e-12)
        << "the tool's x turned onto the link's y";
    expectError(
        replaced(
            2,
            R"(  <robot urdf="robots/mobile_disc.urdf" tool_link="body"><tool_offset xyz="0 0 0.1" rpy="0 0"/></robot>)"),
        2, "rpy");
}
