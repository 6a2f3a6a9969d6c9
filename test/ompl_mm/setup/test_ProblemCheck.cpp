// Tests for ProblemCheck through ManipulationSetup: every kind of impossible problem that can be
// decided before planning is reported at its scene line, and the problems just short of it build.
#include "common/MobileBlocked.h"
#include "ompl_core/compat/OmplVersions.h"
#include "ompl_core/run/GlobalSeed.h"

#include <ompl/base/PlannerData.h>
#include <ompl/base/goals/GoalState.h>
#include <ompl/base/terminationconditions/IterationTerminationCondition.h>
#include <ompl/util/Console.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>

using namespace ompl_mm;
using namespace ompl_mm::test;

namespace
{
    constexpr unsigned int OBJ1 = 0, OBJ2 = 1, OBJ3 = 2;

    /** MOBILE BLOCKED with obj3's goal at (x, y). */
    Scene obj3GoalAt(double x, double y)
    {
        Scene scene = mobileBlockedScene();
        scene.objectGoals.at(0).position = {x, y, std::nullopt};
        return scene;
    }

    /** A goal for object `name` at (x, y), with the scene's goal line for messages. */
    ObjectGoal goalFor(const std::string &name, double x, double y, const ompl_core::SourceLocation &where)
    {
        ObjectGoal goal;
        goal.object = name;
        goal.position = {x, y, std::nullopt};
        goal.where = where;
        goal.where.line += 100;  // a line of its own
        return goal;
    }
}  // namespace

TEST(ProblemCheck, AnObjectStartingInAnObstacleIsReportedAtTheObject)
{
    Scene scene = mobileBlockedScene();
    scene.objects[OBJ2].start.position = Eigen::Vector3d(2.4, -0.1, 0.0);
    EXPECT_EQ(setupError(scene),
              scene.objects[OBJ2].where.str() +
                  ": the start state is invalid: object 'obj2' and obstacle 'wall_east' collide");
    scene.objects[OBJ2].start.position.x() = 2.3;  // touching the wall is free
    EXPECT_EQ(setupError(scene), "");
}

TEST(ProblemCheck, ObjectsOverlappingAtTheStartAreReportedAtTheLaterOne)
{
    Scene scene = mobileBlockedScene();
    scene.objects[OBJ2].start.position = Eigen::Vector3d(-2.0, 0.69, 0.0);  // 0.39 from obj1
    EXPECT_EQ(setupError(scene), scene.objects[OBJ2].where.str() +
                                     ": the start state is invalid: object 'obj1' and object 'obj2' collide");
}

TEST(ProblemCheck, AnObjectGoalInAnObstacleIsReportedAtTheGoal)
{
    const Scene inside = obj3GoalAt(-1.0, 0.0);  // block1's centre
    EXPECT_EQ(
        setupError(inside),
        inside.objectGoals[0].where.str() +
            ": the goal cannot be reached: object 'obj3' and obstacle 'block1' collide at their goal poses");
    EXPECT_EQ(setupError(obj3GoalAt(-1.0, 0.71)), "") << "clear of block1 by 1 cm";
    EXPECT_NE(setupError(obj3GoalAt(-1.0, 0.69)), "");
}

TEST(ProblemCheck, TheRobotGoalInAnObstacleIsReportedAtTheRobotGoal)
{
    Scene scene = mobileBlockedScene();
    scene.robotGoal.joints = {-1.0, 0.0};
    EXPECT_EQ(setupError(scene), scene.robotGoal.where.str() +
                                     ": the goal cannot be reached: robot link 'body' and obstacle 'block1' "
                                     "collide at their goal poses");
    scene.robotGoal.joints = {-1.0, std::nullopt};  // a partial robot goal is not checked
    EXPECT_EQ(setupError(scene), "");
}

TEST(ProblemCheck, AnObjectGoalOverlappingTheRobotGoalIsReportedAtTheObjectGoal)
{
    const Scene scene = obj3GoalAt(0.3, 0.0);  // the robot's goal is (0, 0); both radii 0.2
    EXPECT_EQ(
        setupError(scene),
        scene.objectGoals[0].where.str() +
            ": the goal cannot be reached: robot link 'body' and object 'obj3' collide at their goal poses");
    EXPECT_EQ(setupError(obj3GoalAt(0.41, 0.0)), "");
}

TEST(ProblemCheck, ObjectGoalsOverlappingEachOtherAreReported)
{
    Scene scene = mobileBlockedScene();
    scene.objectGoals.push_back(goalFor("obj1", -1.2, -0.9, scene.objectGoals[0].where));
    EXPECT_EQ(
        setupError(scene),
        scene.objectGoals[0].where.str() +
            ": the goal cannot be reached: object 'obj1' and object 'obj3' collide at their goal poses");
    scene.objectGoals[1].position[0] = -1.31;  // 0.41 from obj3's goal
    EXPECT_EQ(setupError(scene), "");
}

TEST(ProblemCheck, AnImpossibleGoalIsAnsweredWithOMPLsInfeasibleStatusWithoutPlanning)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    ManipulationSetup setup(obj3GoalAt(-1.0, 0.0));
    ASSERT_TRUE(setup.goalFault());
    EXPECT_EQ(setup.solve(10.0), ompl_core::infeasibleStatus());
    EXPECT_EQ(setup.solve(ompl::base::IterationTerminationCondition(100)), ompl_core::infeasibleStatus());
    EXPECT_EQ(setup.getLastPlannerStatus(), ompl_core::infeasibleStatus());
    EXPECT_EQ(setup.mopl()->statistics().iterations, 0u) << "MOPL ran";
    // a goal of the program's own is planned for
    setup.setPlannerByName("rrtconnect");
    auto start = std::make_shared<ompl::base::GoalState>(setup.getSpaceInformation());
    start->setState(setup.getProblemDefinition()->getStartState(0));
    setup.setGoal(start);
    EXPECT_NE(setup.solve(ompl::base::IterationTerminationCondition(10)), ompl_core::infeasibleStatus());
    ompl::base::PlannerData data(setup.getSpaceInformation());
    setup.getPlannerData(data);
    EXPECT_GT(data.numVertices(), 0u) << "the planner did not run";
}

TEST(ProblemCheck, AGoalThatNeedsAnObjectMovedWithoutAPrimitiveThatMovesItIsReported)
{
    Scene scene = mobileBlockedScene();
    scene.primitives.erase(scene.primitives.begin() + 1);  // transit only
    EXPECT_EQ(setupError(scene),
              scene.objectGoals[0].where.str() +
                  ": the goal cannot be reached: object 'obj3' must move to its goal but no "
                  "primitive of the scene can move it there (primitives: transit)");
    // a goal the object already meets needs no primitive
    scene.objectGoals[0].position = {-1.5, -1.5, std::nullopt};
    EXPECT_EQ(setupError(scene), "");
    // pushing slides objects: it cannot turn one
    scene = mobileBlockedScene();
    scene.objectGoals[0].yaw = 1.0;
    EXPECT_TRUE(contains(setupError(scene), "no primitive of the scene can move it there"))
        << setupError(scene);
    scene.objectGoals[0].yaw = 0.04;  // within the yaw tolerance of the start's 0
    EXPECT_EQ(setupError(scene), "");
}

TEST(ProblemCheck, AStandoffThatMakesRobotAndObjectOverlapIsReportedAtThePrimitive)
{
    Scene scene = mobileBlockedScene();
    scene.primitives[1].params["standoff"] = "0.35";
    EXPECT_TRUE(startsWith(setupError(scene), scene.primitives[1].where.str() +
                                                  ": push_mobile standoff 0.35 leaves the robot overlapping"))
        << setupError(scene);
}

TEST(ProblemCheck, ObjectsWithoutAGoalAreLeftOutOfTheGoalChecks)
{
    // obj1 stands where obj3's goal would be: it can be pushed away, so the goal is possible
    Scene scene = mobileBlockedScene();
    scene.objects[OBJ1].start.position = Eigen::Vector3d(-0.9, -0.9, 0.0);
    scene.objects[OBJ3].start.position = Eigen::Vector3d(-1.5, -2.0, 0.0);
    EXPECT_EQ(setupError(scene), "");
}

TEST(ProblemCheck, MekaCleanUpsReachableGoalIsFoundReachableForSeedsWhoseFirstHundredTriesMiss)
{
    // with 100 reach attempts these seeds of OMPL's generator declared the goal impossible
    const Scene scene = loadScene(OMPL_MM_SCENES_DIR "/meka_cleanup.xml");
    for (const std::uint32_t seed : {532u, 695u, 1039u, 1387u, 1693u, 2297u, 2570u, 2730u, 2779u, 2917u})
    {
        ompl_core::reseedOmpl(seed);
        const ManipulationSetup setup(scene);
        EXPECT_FALSE(setup.goalFault().has_value()) << "seed " << seed << ": " << setup.goalFault()->what();
    }
}

TEST(ProblemCheck, ASlideThePushesCannotMakeIsReachedPickedUpAndSetDown)
{
    // MEKA CLEAN-UP's bottle1 slides 0.058 m on its level, less than the pickup's min_plane_distance:
    // without the scene's pushes only lifting it and setting it down again gets it there
    Scene scene = loadScene(OMPL_MM_SCENES_DIR "/meka_cleanup.xml");
    const auto without = [&scene](const std::function<bool(const PrimitiveSpec &)> &unwanted)
    {
        scene.primitives.erase(std::remove_if(scene.primitives.begin(), scene.primitives.end(), unwanted),
                               scene.primitives.end());
    };
    without([](const PrimitiveSpec &spec) { return spec.type.rfind("push", 0) == 0; });
    ASSERT_EQ(scene.primitives.size(), 3u);
    ompl_core::reseedOmpl(1);
    EXPECT_EQ(setupError(scene), "");
    // a robot that cannot set objects down cannot get it there either
    without([](const PrimitiveSpec &spec) { return spec.type == "transfer_rigid"; });
    const std::string error = setupError(scene);
    EXPECT_NE(
        error.find("object 'bottle1' must move to its goal but no primitive of the scene can move it there"),
        std::string::npos)
        << error;
}
