// Tests for MOPL: solves MOBILE BLOCKED for fixed seeds and re-checks every solution with an
// independent planar geometry model (common/PlanarRecheck.h), then checks reproducibility and the
// input checks of MOPL's parameters.
#include "common/MoplIterations.h"
#include "common/PlanarRecheck.h"
#include "ompl_core/run/ParameterSetting.h"

#include <ompl/base/PlannerData.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/util/Console.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>

using namespace ompl_mm;
using namespace ompl_mm::test;

namespace
{
    /** Searches here end after twice the iterations the slowest seed needs (seed 138: 35905), so
        that a regression fails in seconds instead of running to a time limit; a passing search stops
        at its solution, never at the bound (iteration counts are deterministic per seed). */
    constexpr unsigned int MAX_ITERATIONS = 72000;

    ompl::base::PlannerStatus boundedSolve(ManipulationSetup &setup)
    {
        return setup.solve(test::moplIterations(setup, MAX_ITERATIONS));
    }
    class MOPLOnMobileBlocked : public ::testing::TestWithParam<unsigned int>
    {
    protected:
        void SetUp() override { ompl::msg::setLogLevel(ompl::msg::LOG_WARN); }
    };
}  // namespace

TEST_P(MOPLOnMobileBlocked, SolvesAndSolutionPassesIndependentRecheck)
{
    const Scene scene = mobileBlockedScene();
    ManipulationSetup setup(scene);
    setup.mopl()->setSeed(GetParam());
    ASSERT_EQ(boundedSolve(setup), ompl::base::PlannerStatus::EXACT_SOLUTION);
    const ManipulationPath &path = setup.manipulationPath();
    EXPECT_TRUE(path.check()) << "OMPL's own re-check of the path";
    EXPECT_TRUE(setup.getGoal()->isSatisfied(path.getState(path.getStateCount() - 1)));
    EXPECT_GT(path.primitiveCounts().at("push"), 0u) << "obj3 must be pushed";
    EXPECT_EQ(ManipulationSimplifier::countRoundTrips(path), 0u) << "seed 1 pushed obj4 away and back";
    // seed 70 pushed obj3 and obj4 past where they were wanted and back; in seeds 13 and 74 a
    // replanned window pushed an object on where a later push brought it back; seeds 138 and 224
    // keep reversals unless an earlier push may be dropped, or the object pushed once to where
    // the later pushes leave it
    EXPECT_TRUE(path.pushReversals().empty());
    planarRecheck(*setup.manipulationSpace(), path, scene);
}

INSTANTIATE_TEST_SUITE_P(Seeds, MOPLOnMobileBlocked,
                         ::testing::Values(1u, 2u, 3u, 4u, 5u, 6u, 13u, 70u, 74u, 138u, 224u));

namespace
{
    /** A connect_step, a seed that solves with it, and twice the iterations that seed needs. */
    struct ConnectStepCase
    {
        const char *connectStep;
        unsigned int seed;
        unsigned int iterations;
    };

    class MOPLAcrossConnectSteps : public ::testing::TestWithParam<ConnectStepCase>
    {
    protected:
        void SetUp() override { ompl::msg::setLogLevel(ompl::msg::LOG_WARN); }
    };
}  // namespace

TEST_P(MOPLAcrossConnectSteps, EveryPathPassesTheIndependentRecheck)
{
    // connect_step once decided how finely motions were checked (at 1 m a "solved" path drove
    // through block3); motions are now checked continuously whatever it is
    const ConnectStepCase &c = GetParam();
    const Scene scene = mobileBlockedScene();
    ManipulationSetup setup(scene);
    ompl_core::applyParameters(*setup.getPlanner(), {{"connect_step", c.connectStep, {}}});
    setup.mopl()->setSeed(c.seed);
    ASSERT_EQ(setup.solve(test::moplIterations(setup, c.iterations)),
              ompl::base::PlannerStatus::EXACT_SOLUTION);
    planarRecheck(*setup.manipulationSpace(), setup.manipulationPath(), scene);
}

// the ends and the inside of connect_step's declared range, 0.001:0.001:1.
INSTANTIATE_TEST_SUITE_P(Range, MOPLAcrossConnectSteps,
                         ::testing::Values(ConnectStepCase{"0.001", 1, 7100},
                                           ConnectStepCase{"0.01", 5, 7700}, ConnectStepCase{"0.25", 1, 9000},
                                           ConnectStepCase{"0.5", 1, 5800}, ConnectStepCase{"1", 8, 37000}));

TEST(MOPL, SameSeedGivesSamePath)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    const Scene scene = mobileBlockedScene();
    std::vector<std::vector<double>> paths[2];
    for (auto &values : paths)
    {
        ManipulationSetup setup(scene);
        setup.mopl()->setSeed(42);
        ASSERT_EQ(boundedSolve(setup), ompl::base::PlannerStatus::EXACT_SOLUTION);
        const ManipulationPath &path = setup.manipulationPath();
        for (std::size_t k = 0; k < path.getStateCount(); ++k)
        {
            std::vector<double> reals;
            setup.getStateSpace()->copyToReals(reals, path.getState(k));
            values.push_back(reals);
        }
    }
    EXPECT_EQ(paths[0], paths[1]);
}

TEST(MOPL, DifferentSeedsExploreDifferently)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    const Scene scene = mobileBlockedScene();
    std::uint64_t iterations[2];
    for (unsigned int seed : {1u, 2u})
    {
        ManipulationSetup setup(scene);
        setup.mopl()->setSeed(seed);
        ASSERT_EQ(boundedSolve(setup), ompl::base::PlannerStatus::EXACT_SOLUTION);
        iterations[seed - 1] = setup.mopl()->statistics().iterations;
    }
    EXPECT_NE(iterations[0], iterations[1]);
}

TEST(MOPL, StartInsideGoalIsSolvedWithoutSearch)
{
    Scene scene = mobileBlockedScene();
    scene.robotStart = {0.0, 0.0};
    scene.objects[2].start.position = {-0.9, -0.9, 0.0};
    ManipulationSetup setup(scene);
    ASSERT_EQ(setup.solve(1.0), ompl::base::PlannerStatus::EXACT_SOLUTION);
    EXPECT_EQ(setup.manipulationPath().getStateCount(), 1u);
    EXPECT_EQ(setup.mopl()->statistics().iterations, 0u);
}

TEST(MOPL, ReportsTimeoutWhenGoalIsWalledIn)
{
    // obj3's goal is free, but walls around it make every push there collide
    Scene scene = mobileBlockedScene();
    Obstacle cage;
    cage.name = "cage";
    cage.shape.kind = Shape::Kind::Box;
    cage.shape.boxSize = {0.74, 0.1, 1.0};
    for (double y : {-0.58, -1.22})
    {
        cage.pose = Eigen::Translation3d(-0.9, y, 0.5);
        scene.obstacles.push_back(cage);
    }
    cage.shape.boxSize = {0.1, 0.74, 1.0};
    for (double x : {-0.58, -1.22})
    {
        cage.pose = Eigen::Translation3d(x, -0.9, 0.5);
        scene.obstacles.push_back(cage);
    }
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    ManipulationSetup setup(scene);
    setup.mopl()->setSeed(1);
    EXPECT_EQ(setup.solve(0.5), ompl::base::PlannerStatus::TIMEOUT);
    EXPECT_FALSE(setup.getProblemDefinition()->hasExactSolution());
    ompl::base::PlannerData data(setup.getSpaceInformation());
    setup.getPlannerData(data);
    EXPECT_EQ(data.properties.count("path_length_m REAL"), 0u) << "no solution, no solution properties";
    EXPECT_EQ(data.properties.count("iterations INTEGER"), 1u);
}

TEST(MOPL, TreeVerticesLieAtMostAVertexStepApart)
{
    // walks add a vertex every vertex_step (and at each trajectory waypoint), so no tree edge moves the
    // robot or an object farther than vertex_step plus the one check step that overshoots it
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    ManipulationSetup setup(mobileBlockedScene());
    setup.mopl()->setSeed(1);
    setup.solve(test::moplIterations(setup, 300));
    ompl::base::PlannerData data(setup.getSpaceInformation());
    setup.getPlannerData(data);
    const ManipulationStateSpace &space = *setup.manipulationSpace();
    const double bound = setup.mopl()->getVertexStep() + setup.mopl()->getConnectStep() + 1e-9;
    std::vector<unsigned int> children;
    std::size_t edges = 0;
    double longest = 0.0;
    for (unsigned int v = 0; v < data.numVertices(); ++v)
    {
        data.getEdges(v, children);
        for (unsigned int w : children)
        {
            const ompl::base::State *a = data.getVertex(v).getState();
            const ompl::base::State *b = data.getVertex(w).getState();
            double move = std::hypot(space.robotValues(a)[0] - space.robotValues(b)[0],
                                     space.robotValues(a)[1] - space.robotValues(b)[1]);
            for (unsigned int i = 0; i < space.objectCount(); ++i)
                move = std::max(move, (space.objectPosition(a, i) - space.objectPosition(b, i)).norm());
            longest = std::max(longest, move);
            ++edges;
        }
    }
    EXPECT_GT(edges, 50u);
    EXPECT_LE(longest, bound);
    EXPECT_GT(longest, 0.5 * setup.mopl()->getVertexStep()) << "walks do leave vertices behind them";
}

TEST(MOPL, DeclaresEveryTunableParameter)
{
    ManipulationSetup setup(mobileBlockedScene());
    for (const char *name :
         {"connect_step", "vertex_step", "smoothing_attempts", "restart_iterations", "robot_weight",
          "moving_object_penalty", "move_to_object_penalty", "move_to_object_factor", "contact_distance",
          "object_sample_probability", "undefined_probability", "start_value_probability",
          "random_robot_probability", "any_object_probability", "clear_probability", "clear_radius",
          "clear_min_free_objects"})
        EXPECT_TRUE(setup.mopl()->params().hasParam(name)) << name;
    EXPECT_EQ(setup.mopl()->params().getParam("vertex_step")->getValue(), "0.35") << "set by the scene";
    EXPECT_THROW(setup.mopl()->params().setParam("connect_step", "-1"), std::runtime_error);
    EXPECT_THROW(setup.mopl()->params().setParam("undefined_probability", "1.5"), std::runtime_error);
    EXPECT_THROW(setup.mopl()->params().setParam("vertex_step", "abc"), std::runtime_error);
}

TEST(MOPL, ClearsOnlyWhenTheGoalLeavesEnoughObjectsFree)
{
    // MOBILE BLOCKED's goal leaves three of its four objects free: below the default of four
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    auto clearings = [](unsigned int minFreeObjects)
    {
        ManipulationSetup setup(mobileBlockedScene());
        setup.mopl()->setSeed(1);
        setup.mopl()->setClearMinFreeObjects(minFreeObjects);
        EXPECT_EQ(boundedSolve(setup), ompl::base::PlannerStatus::EXACT_SOLUTION) << minFreeObjects;
        return setup.mopl()->statistics().clearings;
    };
    EXPECT_EQ(clearings(4), 0u);
    EXPECT_GT(clearings(3), 0u);
}

TEST(MOPL, RestartsClearTheTreesAndStillSolve)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    ManipulationSetup setup(mobileBlockedScene());
    setup.mopl()->setSeed(8);
    setup.mopl()->setRestartIterations(300);  // far below a typical run: forces restarts
    ASSERT_EQ(boundedSolve(setup), ompl::base::PlannerStatus::EXACT_SOLUTION);
    const MOPLStatistics &stats = setup.mopl()->statistics();
    EXPECT_GT(stats.restarts, 0u);
    // run k may last 300 * 2^k iterations: the last run is the one that solved
    EXPECT_LT(stats.iterations, 300u * ((1u << (stats.restarts + 1)) - 1) + 1);
    EXPECT_TRUE(setup.manipulationPath().check());
}

TEST(MOPLParameters, StepsMustLieInTheirDeclaredRanges)
{
    // the C++ setters hold the same ranges as the declared parameters: a step of 1e-9 once made
    // every interpolation take billions of steps; their ends are accepted, just beyond them not
    ManipulationSetup setup(mobileBlockedScene());
    MOPL &mopl = *setup.mopl();
    const double inf = std::numeric_limits<double>::infinity();
    for (const auto &[value, shown] : std::vector<std::pair<double, std::string>>{
             {0.0, "0"}, {-0.05, "-0.05"}, {0.000999, "0.000999"}, {1.001, "1.001"}, {inf, "inf"}})
        EXPECT_EQ(ompl_core::test::exceptionOf([&] { mopl.setConnectStep(value); }),
                  "MOPL: connect_step must be in [0.001, 1], got " + shown);
    EXPECT_TRUE(startsWith(ompl_core::test::exceptionOf([&] { mopl.setConnectStep(std::nan("")); }),
                           "MOPL: connect_step must be in [0.001, 1], got "));
    EXPECT_EQ(mopl.getConnectStep(), 0.05) << "a rejected value leaves the scene's";
    for (double inside : {MIN_CONNECT_STEP, MAX_CONNECT_STEP})
    {
        EXPECT_EQ(ompl_core::test::exceptionOf([&] { mopl.setConnectStep(inside); }), "");
        EXPECT_EQ(mopl.getConnectStep(), inside);
    }
    EXPECT_EQ(mopl.params().getParam("connect_step")->getRangeSuggestion(), "0.001:0.001:1");

    for (const auto &[value, shown] : std::vector<std::pair<double, std::string>>{
             {0.0, "0"}, {-1.0, "-1"}, {0.00999, "0.00999"}, {10.01, "10.01"}, {inf, "inf"}})
        EXPECT_EQ(ompl_core::test::exceptionOf([&] { mopl.setVertexStep(value); }),
                  "MOPL: vertex_step must be in [0.01, 10], got " + shown);
    EXPECT_TRUE(startsWith(ompl_core::test::exceptionOf([&] { mopl.setVertexStep(std::nan("")); }),
                           "MOPL: vertex_step must be in [0.01, 10], got "));
    EXPECT_EQ(mopl.getVertexStep(), 0.35) << "a rejected value leaves the scene's";
    for (double inside : {MIN_VERTEX_STEP, MAX_VERTEX_STEP})
    {
        EXPECT_EQ(ompl_core::test::exceptionOf([&] { mopl.setVertexStep(inside); }), "");
        EXPECT_EQ(mopl.getVertexStep(), inside);
    }
    EXPECT_EQ(mopl.params().getParam("vertex_step")->getRangeSuggestion(), "0.01:0.01:10");
}

TEST(MOPLParameters, ProbabilitiesMustLieInTheClosedUnitInterval)
{
    // each probability accepts 0 and 1 and rejects values just outside, naming parameter and value
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    ManipulationSetup setup(mobileBlockedScene());
    ompl::base::ParamSet &params = setup.mopl()->params();
    for (const std::string name : {"object_sample_probability", "undefined_probability",
                                   "start_value_probability", "random_robot_probability"})
    {
        EXPECT_EQ(ompl_core::test::exceptionOf([&] { params.setParam(name, "-0.01"); }),
                  "MOPL: " + name + " must be in [0, 1], got -0.01");
        EXPECT_EQ(ompl_core::test::exceptionOf([&] { params.setParam(name, "1.01"); }),
                  "MOPL: " + name + " must be in [0, 1], got 1.01");
        for (const char *inside : {"0", "1"})
        {
            EXPECT_TRUE(params.setParam(name, inside)) << name << " = " << inside;
            EXPECT_EQ(std::stod(params.getParam(name)->getValue()), std::stod(inside)) << name;
        }
    }
}

TEST(MOPLParameters, MetricWeightsMustNotBeNegative)
{
    // the nearest-neighbour search's lower bounds hold only for weights of 0 or more
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    ManipulationSetup setup(mobileBlockedScene());
    ompl::base::ParamSet &params = setup.mopl()->params();
    EXPECT_EQ(ompl_core::test::exceptionOf([&] { params.setParam("joint_weight", "-1"); }),
              "MOPL: joint_weight must be in [0, 100], got -1");
    EXPECT_EQ(ompl_core::test::exceptionOf([&] { params.setParam("contact_distance", "11"); }),
              "MOPL: contact_distance must be in [0, 10], got 11");
    for (const char *name :
         {"robot_weight", "joint_weight", "base_joint_weight", "tool_weight", "rotation_weight",
          "moving_object_penalty", "move_to_object_penalty", "move_to_object_factor", "contact_distance"})
    {
        const std::string before = params.getParam(name)->getValue();
        EXPECT_THROW(params.setParam(name, "-0.5"), std::runtime_error) << name;
        EXPECT_EQ(params.getParam(name)->getValue(), before) << name << " keeps its value";
        EXPECT_TRUE(params.setParam(name, "0")) << name;
        EXPECT_EQ(std::stod(params.getParam(name)->getValue()), 0.0) << name;
    }
}

TEST(MOPLParameters, ObjectsOutOfPlayKeepAChanceAndClearingHasItsRanges)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    ManipulationSetup setup(mobileBlockedScene());
    ompl::base::ParamSet &params = setup.mopl()->params();
    EXPECT_EQ(params.getParam("any_object_probability")->getValue(), "1");
    EXPECT_EQ(ompl_core::test::exceptionOf([&] { params.setParam("any_object_probability", "0"); }),
              "MOPL: any_object_probability must be in [0.01, 1], got 0");
    EXPECT_TRUE(params.setParam("any_object_probability", "0.01"));
    EXPECT_EQ(params.getParam("any_object_probability")->getRangeSuggestion(), "0.01:0.01:1");

    EXPECT_EQ(setup.mopl()->getClearProbability(), 1.0);
    EXPECT_EQ(setup.mopl()->getClearMinFreeObjects(), 4u);
    EXPECT_TRUE(params.setParam("clear_min_free_objects", "0"));
    EXPECT_EQ(setup.mopl()->getClearMinFreeObjects(), 0u);
    EXPECT_EQ(ompl_core::test::exceptionOf([&] { params.setParam("clear_probability", "1.5"); }),
              "MOPL: clear_probability must be in [0, 1], got 1.5");
    EXPECT_EQ(setup.mopl()->getClearRadius(), 1.0);
    EXPECT_EQ(ompl_core::test::exceptionOf([&] { setup.mopl()->setClearRadius(0.0); }),
              "MOPL: clear_radius must be in [0.01, 100], got 0");
    EXPECT_TRUE(params.setParam("clear_radius", "0.5"));
    EXPECT_EQ(setup.mopl()->getClearRadius(), 0.5);
}

TEST(MOPL, ClearingPushesObjectsInTheWayAsideAndStillSolves)
{
    // every object that stops the start tree is pushed aside: the plans stay correct
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    const Scene scene = mobileBlockedScene();
    for (unsigned int seed : {1u, 2u})
    {
        ManipulationSetup setup(scene);
        setup.mopl()->setSeed(seed);
        setup.mopl()->setClearMinFreeObjects(0);
        ASSERT_EQ(boundedSolve(setup), ompl::base::PlannerStatus::EXACT_SOLUTION) << seed;
        EXPECT_GT(setup.mopl()->statistics().clearings, 0u) << seed;
        const ManipulationPath &path = setup.manipulationPath();
        EXPECT_TRUE(path.check()) << seed;
        EXPECT_TRUE(setup.getGoal()->isSatisfied(path.getState(path.getStateCount() - 1))) << seed;
        planarRecheck(*setup.manipulationSpace(), path, scene);
    }
}

TEST(MOPLParameters, UndefinedAndStartValueProbabilitiesMayNotSumAboveOne)
{
    // checked when the planner is set up: a sum of exactly 1 is fine, just above is not
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    auto setupError = [](const char *undefined, const char *startValue)
    {
        ManipulationSetup setup(mobileBlockedScene());
        EXPECT_TRUE(setup.mopl()->params().setParam("undefined_probability", undefined));
        EXPECT_TRUE(setup.mopl()->params().setParam("start_value_probability", startValue));
        return ompl_core::test::exceptionOf([&] { setup.setup(); });
    };
    EXPECT_EQ(setupError("0.5", "0.5"), "");
    EXPECT_EQ(setupError("0.75", "0.25"), "");
    EXPECT_EQ(setupError("1", "0"), "");
    EXPECT_EQ(setupError("0.5", "0.5000001"),
              "MOPL: undefined_probability + start_value_probability exceeds 1");
    EXPECT_EQ(setupError("1", "1"), "MOPL: undefined_probability + start_value_probability exceeds 1");
}

TEST(MOPLParameters, AContradictionBetweenSettingsIsNamedAtTheLastSetting)
{
    // each probability is in range; together they are not: the message names where the settings
    // came from, so a scene's <planner> line or the command line option is found at once
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    ManipulationSetup setup(mobileBlockedScene());
    const ompl_core::SourceLocation first{"s.xml", 70}, last{"s.xml", 71};
    EXPECT_EQ(ompl_core::test::inputErrorOf(
                  [&]
                  {
                      setup.applyParameters({{"undefined_probability", "0.8", first},
                                             {"start_value_probability", "0.3", last}});
                  }),
              "s.xml:71: MOPL: undefined_probability + start_value_probability exceeds 1");
    // just inside, in either order
    EXPECT_EQ(ompl_core::test::inputErrorOf(
                  [&]
                  {
                      setup.applyParameters({{"start_value_probability", "0.2", first},
                                             {"undefined_probability", "0.8", last}});
                  }),
              "");
}

TEST(MOPLParameters, SetupWithoutPrimitivesThrows)
{
    // a planner made without primitives (or emptied) cannot plan
    ManipulationSetup setup(mobileBlockedScene());
    setup.mopl()->setPrimitives({});
    EXPECT_EQ(ompl_core::test::exceptionOf([&] { setup.setup(); }),
              "MOPL: has no primitives: call setPrimitives() first");
}

TEST(MOPLParameters, NeedsAManipulationStateSpace)
{
    // MOPL plans only in a ManipulationStateSpace; another space is named in the message
    auto space = std::make_shared<ompl::base::RealVectorStateSpace>(2);
    space->setName("plane");
    auto si = std::make_shared<ompl::base::SpaceInformation>(space);
    EXPECT_EQ(ompl_core::test::exceptionOf([&] { MOPL mopl(si, {}); }),
              "MOPL: needs a ManipulationStateSpace, got plane");
}
