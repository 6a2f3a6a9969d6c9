#include "ompl_mmphys/simulation/PhysicsCheck.h"

#include "common/MobileBlocked.h"
#include "ompl_mm/io/PathFile.h"
#include "ompl_mmphys/io/PhysicsCheckRecord.h"

#include <gtest/gtest.h>

#include <iterator>
#include <set>
#include <sstream>

using namespace ompl_mm;
using namespace ompl_mm::test;
using ompl_mmphys::checkPlan;
using ompl_mmphys::PhysicsCheck;

namespace
{
    /** A fixture with MOBILE BLOCKED planned by MOPL (seed 1). */
    class PhysicsCheckTest : public MobileBlockedTest
    {
    protected:
        const ManipulationPath &plan()
        {
            setup_.mopl()->setSeed(1);
            EXPECT_TRUE(setup_.solve(30.0));
            return setup_.manipulationPath();
        }

        /** The index of the object called name. */
        unsigned int objectIndex(const std::string &name) const
        {
            const std::vector<MovableObject> &objects = space_.model()->scene().objects;
            for (unsigned int k = 0; k < objects.size(); ++k)
                if (objects[k].name == name)
                    return k;
            ADD_FAILURE() << "no object " << name;
            return 0;
        }
    };
}  // namespace

TEST_F(PhysicsCheckTest, TheSimulationFollowsThePlanStateByState)
{
    const ManipulationPath &path = plan();
    const PhysicsCheck check = checkPlan(setup_, path);
    const ompl_mmphys::SimulatedPlan &simulation = check.simulation;
    ASSERT_EQ(simulation.statePoses.size(), path.getStateCount());
    std::size_t steps = 0;
    for (const ompl_phys::RobotMove &move : simulation.tool.moves)
        steps += move.steps;
    EXPECT_EQ(simulation.tool.positions.size(), steps + 1);
    EXPECT_NEAR(check.simulatedSeconds, static_cast<double>(steps) * 0.004, 1e-9);
    // the objects start where the scene puts them, and the robot's tool follows the plan
    for (unsigned int k = 0; k < space_.objectCount(); ++k)
        EXPECT_LT(
            (simulation.statePoses[0][k].position - space_.objectPose(path.getState(0), k).position).norm(),
            1e-3);
    EXPECT_LT(
        (simulation.tool.positions.back() - space_.toolPosition(path.getState(path.getStateCount() - 1)))
            .norm(),
        1e-9);
    // every push run leaves a checkpoint, and the pushed obj3 really moves in the simulation
    EXPECT_FALSE(simulation.checkpoints.empty());
    const unsigned int obj3 = objectIndex("obj3");
    EXPECT_GT(
        (simulation.finalPoses[obj3].position - space_.objectPose(path.getState(0), obj3).position).norm(),
        0.3);
    EXPECT_GT(check.metrics.action, 0.0) << "the robot pushes, so it exerts force";
}

TEST_F(PhysicsCheckTest, APushSimulatedAloneEndsWhereTheWholePlanPutsItsObject)
{
    // the plan's first push run, executed from its first state on its own (the building block of a
    // push whose outcome is simulated while planning), against the whole plan's execution
    const ManipulationPath &path = plan();
    const ompl_mmphys::SimulatedPlan whole = ompl_mmphys::simulatePlan(path);
    ASSERT_FALSE(whole.checkpoints.empty());
    const ompl_mmphys::Checkpoint &pushed = whole.checkpoints.front();
    ASSERT_EQ(pushed.kind, PrimitiveKind::Push);
    std::size_t first = pushed.state - 1;
    while (first > 0 && path.label(first - 1) == path.label(pushed.state - 1))
        --first;
    ManipulationPath alone(setup_.getSpaceInformation());
    alone.appendFirst(path.getState(first));
    for (std::size_t i = first + 1; i <= pushed.state; ++i)
        alone.appendLabelled(path.getState(i), path.label(i - 1));
    const ompl_mmphys::SimulatedPlan local = ompl_mmphys::simulatePlan(alone);
    ASSERT_EQ(local.checkpoints.size(), 1u);
    EXPECT_LT((local.checkpoints[0].simulated.position - pushed.simulated.position).norm(), 0.001)
        << "alone " << local.checkpoints[0].simulated.position.transpose() << ", in the plan "
        << pushed.simulated.position.transpose();
    EXPECT_GT(
        (pushed.simulated.position - space_.objectPose(path.getState(first), pushed.object).position).norm(),
        0.1)
        << "the push moves its object";
}

TEST_F(PhysicsCheckTest, TheSameSeedGivesTheSameNumbers)
{
    const ManipulationPath &path = plan();
    const PhysicsCheck first = checkPlan(setup_, path), second = checkPlan(setup_, path);
    for (unsigned int k = 0; k < space_.objectCount(); ++k)
    {
        EXPECT_EQ(first.simulation.finalPoses[k].position, second.simulation.finalPoses[k].position);
        EXPECT_EQ(first.objects[k].positionError, second.objects[k].positionError);
    }
    EXPECT_EQ(first.metrics.smoothness, second.metrics.smoothness);
}

TEST_F(PhysicsCheckTest, ReportedErrorsAreTheDistancesFromThePlannedEndPoses)
{
    const ManipulationPath &path = plan();
    const PhysicsCheck check = checkPlan(setup_, path);
    double largest = 0.0;
    for (unsigned int k = 0; k < space_.objectCount(); ++k)
    {
        const ObjectPose planned = space_.objectPose(path.getState(path.getStateCount() - 1), k);
        const double error = (check.simulation.finalPoses[k].position - planned.position).norm();
        EXPECT_NEAR(check.objects[k].positionError, error, 1e-12) << check.objects[k].name;
        EXPECT_EQ(check.objects[k].yawError, 0.0) << "cylinders' yaw does not matter";
        largest = std::max(largest, error);
    }
    EXPECT_EQ(check.maxPositionError, largest);
    EXPECT_EQ(check.confirmed, largest <= 0.02 && check.goalHolds);
}

TEST_F(PhysicsCheckTest, AnObjectTeleportedInThePlanIsCaught)
{
    // obj1 is never touched; the planted plan says it ends a metre away
    const ManipulationPath &solved = plan();
    const unsigned int obj1 = objectIndex("obj1");
    ompl::base::State *end = own(space_.cloneState(solved.getState(solved.getStateCount() - 1)));
    ObjectPose moved = space_.objectPose(end, obj1);
    moved.position.x() += 1.0;
    space_.setObjectPose(end, obj1, moved);
    ManipulationPath planted(setup_.getSpaceInformation());  // the plan's labels, kept as given
    planted.appendFirst(solved.getState(0));
    for (std::size_t i = 1; i < solved.getStateCount(); ++i)
        planted.appendLabelled(i + 1 < solved.getStateCount() ? solved.getState(i) : end,
                               solved.label(i - 1));
    const PhysicsCheck check = checkPlan(setup_, planted);
    EXPECT_FALSE(check.confirmed);
    EXPECT_NEAR(check.objects[obj1].positionError, 1.0, 0.01);
    EXPECT_GE(check.maxPositionError, check.objects[obj1].positionError);
}

TEST_F(PhysicsCheckTest, ATransitLeavesTheObjectsAtRestButDoesNotReachTheGoal)
{
    ompl::base::State *start = startCopy();
    ompl::base::State *away = startCopy();
    setRobot(space_, away, 1.9, 1.0);  // down the free corridor on the east side
    ManipulationPath path(setup_.getSpaceInformation());
    path.appendFirst(start);
    path.appendLabelled(away, TRANSIT);
    const PhysicsCheck check = checkPlan(setup_, path);
    for (const ompl_mmphys::ObjectCheck &object : check.objects)
    {
        EXPECT_LT(object.positionError, 1e-3) << object.name;
        EXPECT_FALSE(object.tipped || object.offSurface) << object.name;
    }
    EXPECT_FALSE(check.goalHolds) << "obj3 stays far from its goal";
    EXPECT_FALSE(check.confirmed);
    EXPECT_EQ(check.metrics.action, 0.0) << "nothing touched";
}

TEST_F(PhysicsCheckTest, BadSettingsAreRefused)
{
    ManipulationPath empty(setup_.getSpaceInformation());
    EXPECT_THROW(ompl_mmphys::simulatePlan(empty), ompl::Exception);
    ompl_mmphys::SimulationSettings settings;
    settings.timeStep = 0.0;
    EXPECT_THROW(ompl_mmphys::simulatePlan(plan(), settings), ompl::Exception);
}

TEST_F(PhysicsCheckTest, TheReportedErrorsFollowFromThePathFilesSimulatedColumns)
{
    const ManipulationPath &path = plan();
    const PhysicsCheck check = checkPlan(setup_, path);
    std::stringstream file;
    writePathFile(file, path, ompl_mmphys::simulatedPoseColumns(check));
    std::string header, line, last;
    std::getline(file, header);
    while (std::getline(file, line))
        last = line;
    std::istringstream headerWords(header.substr(2)), lastWords(last);
    const std::vector<std::string> names{std::istream_iterator<std::string>(headerWords), {}};
    const std::vector<std::string> values{std::istream_iterator<std::string>(lastWords), {}};
    ASSERT_EQ(names.size(), values.size());
    auto column = [&](const std::string &name)
    {
        const auto found = std::find(names.begin(), names.end(), name);
        EXPECT_NE(found, names.end()) << name;
        return std::stod(values[static_cast<std::size_t>(found - names.begin())]);
    };
    for (const ompl_mmphys::ObjectCheck &object : check.objects)
    {
        const Eigen::Vector3d planned(column(object.name + ".x"), column(object.name + ".y"),
                                      column(object.name + ".z"));
        const Eigen::Vector3d simulated(column("sim." + object.name + ".x"),
                                        column("sim." + object.name + ".y"),
                                        column("sim." + object.name + ".z"));
        EXPECT_NEAR((simulated - planned).norm(), object.positionError, 1e-8) << object.name;
    }
}

TEST_F(PhysicsCheckTest, TheRecordCarriesTheCheck)
{
    const PhysicsCheck check = checkPlan(setup_, plan());
    const ompl_core::RunRecord record = ompl_mmphys::physicsCheckRecord(check);
    ASSERT_NE(record.find("confirmed"), nullptr);
    EXPECT_EQ(std::get<bool>(record.find("confirmed")->value), check.confirmed);
    EXPECT_EQ(std::get<double>(record.find("max_position_error_m")->value), check.maxPositionError);
    EXPECT_EQ(std::get<double>(record.find("objects.obj2.position_error_m")->value),
              check.objects[1].positionError);
    EXPECT_EQ(std::get<double>(record.find("action")->value), check.metrics.action);
}

namespace
{
    /** MOBILE BLOCKED without walls and blocks: the floor's edge is open. */
    Scene openFloorScene()
    {
        Scene scene = mobileBlockedScene();
        scene.obstacles.clear();
        return scene;
    }

    class OpenFloorTest : public MobileBlockedTest
    {
    protected:
        OpenFloorTest() : MobileBlockedTest(openFloorScene()) {}
    };
}  // namespace

TEST_F(OpenFloorTest, AnObjectPushedOverTheEdgeFallsAndStopsBelow)
{
    // a "transit" that in fact shoves obj1 (at x -2.0) over the floor's edge at x -2.5
    ompl::base::State *start = startCopy();
    setRobot(space_, start, -1.4, 0.3);
    ompl::base::State *edge = startCopy();
    setRobot(space_, edge, -2.5, 0.3);
    ManipulationPath path(setup_.getSpaceInformation());
    path.appendFirst(start);
    path.appendLabelled(edge, TRANSIT);
    const PhysicsCheck check = checkPlan(setup_, path);
    const ompl_mmphys::ObjectCheck &obj1 = check.objects[0];
    EXPECT_TRUE(obj1.offSurface);
    EXPECT_FALSE(check.confirmed);
    EXPECT_GT(obj1.positionError, 0.5);
    EXPECT_LT(obj1.positionError, 3.0) << "stopped a metre below the floor, not falling for ever";
    EXPECT_LT(check.objects[1].positionError, 1e-3) << "obj2 is far away";
}

TEST_F(OpenFloorTest, ATallBoxPushedLowTipsOver)
{
    // obj1 made a tall, narrow box: the disc (its centre 0.25 m up) pushes it below its middle
    Scene scene = openFloorScene();
    scene.objects[0].shape.kind = Shape::Kind::Box;
    scene.objects[0].shape.boxSize = Eigen::Vector3d(0.1, 0.1, 0.8);
    ManipulationSetup setup(scene);
    const ManipulationStateSpace &space = *setup.manipulationSpace();
    ompl::base::State *start = own(space.cloneState(setup.getProblemDefinition()->getStartState(0)));
    setRobot(space, start, -1.4, 0.3);
    ompl::base::State *pushed = own(space.cloneState(start));
    setRobot(space, pushed, -1.9, 0.3);
    ManipulationPath path(setup.getSpaceInformation());
    path.appendFirst(start);
    path.appendLabelled(pushed, TRANSIT);
    const PhysicsCheck check = checkPlan(setup, path);
    EXPECT_TRUE(check.objects[0].tipped);
    EXPECT_GT(check.simulation.finalTilts[0], 60.0 * ompl_mmphys::DEGREE) << "it lies on its side";
    EXPECT_FALSE(check.confirmed);
}

TEST(PhysicsCheck, KukaTablesPicksAndPlacesHold)
{
    ManipulationSetup setup(loadScene(OMPL_MM_SCENES_DIR "/kuka_table.xml"));
    setup.mopl()->setSeed(1);
    ASSERT_TRUE(setup.solve(60.0));
    const PhysicsCheck check = checkPlan(setup, setup.manipulationPath());
    EXPECT_TRUE(check.confirmed);
    EXPECT_TRUE(check.goalHolds);
    for (const ompl_mmphys::ObjectCheck &object : check.objects)
    {
        EXPECT_LT(object.positionError, 0.005) << object.name << ": carried rigidly, placed at rest";
        EXPECT_FALSE(object.tipped) << object.name;
    }
    // OMPL's own generator (the shortcuts) is not seeded here: a plan may place a cylinder twice
    std::set<unsigned int> placed;
    for (const ompl_mmphys::Checkpoint &checkpoint : check.simulation.checkpoints)
        if (checkpoint.kind == PrimitiveKind::Transfer)
            placed.insert(checkpoint.object);
    EXPECT_EQ(placed, (std::set<unsigned int>{0, 1, 2})) << "every cylinder placed";
}
