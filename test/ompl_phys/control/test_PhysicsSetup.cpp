// Tests for PhysicsSetup: every planner solves every benchmark scene and its controls, replayed in a
// fresh world, reach the goal with no rule broken at any sub-step; the same seed gives the same plan;
// bad planners and bad starts or goals are rejected.
#include "ompl_phys/control/PhysicsSetup.h"

#include "ompl_core/compat/OmplVersions.h"
#include "ompl_phys/base/RobotProjection.h"
#include "ompl_phys/common/PhysicsTestSupport.h"
#include "ompl_phys/control/PDSTPlanner.h"
#include "ompl_phys/control/PathSimulation.h"
#include "ompl_phys/io/PhysicsRunResult.h"
#include "ompl_phys/metrics/TrajectoryMetrics.h"

#include <ompl/base/goals/GoalState.h>
#include <ompl/base/terminationconditions/IterationTerminationCondition.h>
#include <ompl/control/PlannerData.h>
#include <ompl/control/planners/rrt/RRT.h>
#include <ompl/control/spaces/RealVectorControlSpace.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace ompl_phys;
using namespace ompl_phys::test;

namespace
{
    /** Searches are bounded by evaluations of their termination condition (about one per iteration),
        far above what each case needs with its seed, so that a passing run stops at its solution,
        never at the bound, on any machine (the counts are deterministic per seed): SyclopRRT on
        scene 1 with seed 1 for the same-seed test, and every planner on every scene with seed 1. */
    constexpr unsigned int SYCLOPRRT_SEED_1_BOUND = 70000;
    constexpr unsigned int EVERY_PLANNER_BOUND = 400000;

    /** Seeds OMPL's generators for everything created afterwards. Re-seeding within one process is what
        these tests need; OMPL reports it as an error ("random number generation already started"), which
        is silenced here. */
    void seedOmpl(std::uint_fast32_t seed)
    {
        ompl::msg::noOutputHandler();
        ompl::RNG::setSeed(seed);
        ompl::msg::restorePreviousOutputHandler();
    }

    /** A control path's forces and durations, and its stored states, bit for bit. */
    struct PathRecord
    {
        std::vector<double> numbers;
        bool operator==(const PathRecord &other) const
        {
            return numbers.size() == other.numbers.size() &&
                   std::equal(numbers.begin(), numbers.end(), other.numbers.begin(),
                              [](double a, double b) { return sameBits(a, b); });
        }
    };

    PathRecord record(const PhysicsSetup &setup, const ompl::control::PathControl &path)
    {
        PathRecord r;
        for (std::size_t i = 0; i < path.getControlCount(); ++i)
        {
            const double *force =
                path.getControl(i)->as<ompl::control::RealVectorControlSpace::ControlType>()->values;
            r.numbers.insert(r.numbers.end(), {force[0], force[1], path.getControlDuration(i)});
        }
        for (std::size_t i = 0; i < path.getStateCount(); ++i)
        {
            BodyStates states;
            setup.physicsSpace().readState(path.getState(i), states);
            for (const BodyState &s : states)
            {
                r.numbers.insert(r.numbers.end(), s.position.data(), s.position.data() + 3);
                r.numbers.insert(r.numbers.end(), s.linearVelocity.data(), s.linearVelocity.data() + 3);
            }
        }
        return r;
    }

    /** A solved run of scene 1. */
    struct PlanRun
    {
        bool exact{false};
        PathRecord path;
        SimulatedPath simulated;
        TrajectoryMetrics metrics;
    };

    /** Re-simulates path's controls from the start in a fresh setup of the scene: a new ODE world,
        which owes nothing to the planner's. */
    SimulatedPath replayInAFreshWorld(const PhysicsScene &scene, const ompl::control::PathControl &path)
    {
        PhysicsSetup fresh(scene);
        ompl::control::PathControl replayed(fresh.getSpaceInformation());
        replayed.append(fresh.getProblemDefinition()->getStartState(0));
        for (std::size_t i = 0; i < path.getControlCount(); ++i)
            replayed.append(path.getState(i + 1), path.getControl(i), path.getControlDuration(i));
        return simulatePath(fresh, replayed);
    }

    /** Solves benchmark scene n with planner and seed, checks the plan by replaying its controls in a
        fresh world. */
    PlanRun solveScene(int n, const std::string &planner, std::uint_fast32_t seed, unsigned int bound)
    {
        ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
        seedOmpl(seed);
        const PhysicsScene scene = benchmarkScene(n);
        PhysicsSetup setup(scene);
        setup.setPlannerByName(planner);
        setup.solve(ompl::base::IterationTerminationCondition(bound));
        PlanRun run;
        run.exact = setup.haveExactSolution();
        if (!run.exact)
            return run;
        ompl::control::PathControl &path = setup.getSolutionPath();
        run.path = record(setup, path);
        run.simulated = replayInAFreshWorld(scene, path);
        run.metrics = computeTrajectoryMetrics(run.simulated.robot);

        // every control lasts a whole number of steps within the scene's limits
        const PlanningLimits &limits = setup.scene().limits;
        std::size_t steps = 0;
        for (std::size_t i = 0; i < path.getControlCount(); ++i)
        {
            const double n = path.getControlDuration(i) / limits.stepSize;
            EXPECT_NEAR(n, std::round(n), 1e-9) << "control " << i;
            EXPECT_GE(std::lround(n), static_cast<long>(limits.minControlSteps));
            EXPECT_LE(std::lround(n), static_cast<long>(limits.maxControlSteps));
            steps += static_cast<std::size_t>(std::lround(n));
            const double *force =
                path.getControl(i)->as<ompl::control::RealVectorControlSpace::ControlType>()->values;
            EXPECT_LE(std::max(std::abs(force[0]), std::abs(force[1])), limits.maxForce);
        }
        EXPECT_EQ(run.simulated.robot.positions.size(), 1 + steps);
        EXPECT_EQ(run.simulated.robot.moves.size(), path.getControlCount());

        // the re-simulation, step by step from the controls alone, passes through the planner's states
        std::size_t step = 0;
        for (std::size_t i = 0; i < path.getControlCount() && step < run.simulated.states.size(); ++i)
        {
            step += static_cast<std::size_t>(std::lround(path.getControlDuration(i) / limits.stepSize));
            if (step >= run.simulated.states.size())
                break;
            BodyStates stored;
            setup.physicsSpace().readState(path.getState(i + 1), stored);
            EXPECT_TRUE(sameBits(stored, run.simulated.states[step])) << "state " << i + 1;
        }
        // and every simulated state keeps the rules
        const ManipulationKnowledge &knowledge = setup.knowledge();
        for (const BodyStates &states : run.simulated.states)
            EXPECT_EQ(knowledge.checkStates(states), Violation::None);
        // the robot ends in the goal disc (checked here, independently of the goal object)
        const Eigen::Vector2d end = run.simulated.states.back()[0].position.head<2>();
        EXPECT_LE((end - setup.scene().goal.centre).norm(), setup.scene().goal.radius);
        return run;
    }

    struct PlannerCase
    {
        int scene;
        std::string planner;
        std::uint_fast32_t seed;
        unsigned int bound;  ///< evaluations of the termination condition, twice what the case needs
    };

    std::string caseName(const ::testing::TestParamInfo<PlannerCase> &info)
    {
        return "scene" + std::to_string(info.param.scene) + "_" + info.param.planner + "_seed" +
               std::to_string(info.param.seed);
    }

    class SolvesTheScene : public ::testing::TestWithParam<PlannerCase>
    {
    };
}  // namespace

TEST(PhysicsSetup, PlannerNamesIncludeTheBenchmarkPlanners)
{
    const std::vector<std::string> names = PhysicsSetup::plannerRegistry().names();
    for (const char *name : {"rrt", "est", "kpiece", "sycloprrt", "syclopest"})
        EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
    // each name allocates a planner
    PhysicsSetup setup(benchmarkScene(1));
    for (const std::string &name : names)
    {
        EXPECT_NO_THROW(setup.setPlannerByName(name)) << name;
        EXPECT_TRUE(setup.getPlanner()) << name;
    }
}

TEST(PhysicsSetup, UnknownPlannerThrows)
{
    PhysicsSetup setup(benchmarkScene(1));
    try
    {
        setup.setPlannerByName("rrtstar");
        ADD_FAILURE() << "no exception for an unknown planner";
    }
    catch (const ompl::Exception &e)
    {
        const std::string message = e.what();
        EXPECT_TRUE(contains(message, "rrtstar")) << message;
        EXPECT_TRUE(contains(message, "kpiece")) << message;  // lists the known ones
    }
}

TEST(PhysicsSetup, SstObjectiveDoesNotStayForTheNextPlanner)
{
    PhysicsSetup setup(benchmarkScene(1));
    setup.setPlannerByName("sst");
    EXPECT_TRUE(setup.getProblemDefinition()->hasOptimizationObjective());
    setup.setPlannerByName("rrt");
    EXPECT_FALSE(setup.getProblemDefinition()->hasOptimizationObjective());
}

TEST(PhysicsSetup, SceneGoalBiasReachesPlannersThatDeclareIt)
{
    PhysicsScene scene = benchmarkScene(1);
    scene.limits.goalBias = 0.123;
    PhysicsSetup setup(scene);
    for (const char *name : {"rrt", "est", "kpiece", "pdst", "sst"})
    {
        setup.setPlannerByName(name);
        ASSERT_TRUE(setup.getPlanner()->params().hasParam("goal_bias")) << name;
        EXPECT_EQ(std::stod(setup.getPlanner()->params().getParam("goal_bias")->getValue()), 0.123) << name;
    }
}

TEST(PhysicsSetup, UsersCanRegisterTheirOwnPlanner)
{
    auto &registry = PhysicsSetup::plannerRegistry();
    if (!registry.has("test_rrt_with_bias_half"))
        registry.add("test_rrt_with_bias_half", "RRT with goal bias 0.5, defined by a test",
                     [](PhysicsSetup &s)
                     {
                         auto planner = std::make_shared<ompl::control::RRT>(s.getSpaceInformation());
                         planner->setName("TestRRT");
                         return planner;
                     });
    PhysicsSetup setup(benchmarkScene(1));
    setup.setPlannerByName("test_rrt_with_bias_half");
    EXPECT_EQ(setup.getPlanner()->getName(), "TestRRT");
    EXPECT_THROW(registry.add("rrt", "a second rrt", nullptr), ompl::Exception);
}

TEST(PhysicsSetup, PlansAfterTheSceneIsGone)
{
    std::unique_ptr<PhysicsSetup> setup;
    std::shared_ptr<const ManipulationKnowledge> knowledge;
    {
        const PhysicsScene scene = benchmarkScene(1);
        setup = std::make_unique<PhysicsSetup>(scene);
        knowledge = std::make_shared<const ManipulationKnowledge>(shared(scene));
    }
    ompl::RNG::setSeed(1);
    setup->setPlannerByName("rrt");
    // a bounded search: whatever it finds, every state it made must be judged by the scene's rules
    setup->solve(ompl::base::IterationTerminationCondition(300));
    ompl::control::PlannerData data(setup->getSpaceInformation());
    setup->getPlanner()->getPlannerData(data);
    EXPECT_GT(data.numVertices(), 1u);
    EXPECT_EQ(setup->scene().name, "scene1");
    EXPECT_EQ(knowledge->goalOccupants(setup->world().startStates()).size(), 0u);
}

TEST(PhysicsSetup, ProblemFollowsTheScene)
{
    const PhysicsScene scene = benchmarkScene(1);
    PhysicsSetup setup(scene);
    const auto &si = setup.getSpaceInformation();
    EXPECT_DOUBLE_EQ(si->getPropagationStepSize(), scene.limits.stepSize);
    EXPECT_EQ(si->getMinControlDuration(), scene.limits.minControlSteps);
    EXPECT_EQ(si->getMaxControlDuration(), scene.limits.maxControlSteps);
    const auto *controls = si->getControlSpace()->as<ompl::control::RealVectorControlSpace>();
    ASSERT_EQ(controls->getDimension(), 2u);
    for (int k = 0; k < 2; ++k)
    {
        EXPECT_DOUBLE_EQ(controls->getBounds().low[k], -scene.limits.maxForce);
        EXPECT_DOUBLE_EQ(controls->getBounds().high[k], scene.limits.maxForce);
    }
    EXPECT_TRUE(std::dynamic_pointer_cast<RobotProjection>(setup.getStateSpace()->getDefaultProjection()));
    EXPECT_EQ(setup.physicsSpace().movingBodyCount(), 1 + scene.movableBodies().size());
    // the start is the scene's, at rest
    BodyStates start;
    setup.physicsSpace().readState(setup.getProblemDefinition()->getStartState(0), start);
    EXPECT_TRUE(sameBits(start, setup.world().startStates()));
    EXPECT_TRUE(si->isValid(setup.getProblemDefinition()->getStartState(0)));
}

TEST_P(SolvesTheScene, AndItsControlsReachTheGoalInAFreshWorld)
{
    const PlannerCase c = GetParam();
    const PlanRun run = solveScene(c.scene, c.planner, c.seed, c.bound);
    ASSERT_TRUE(run.exact) << c.planner << " found no exact solution in " << c.bound << " iterations";
    EXPECT_EQ(run.simulated.violation, Violation::None) << violationName(run.simulated.violation);
    EXPECT_TRUE(run.simulated.reachesGoal);
    EXPECT_GT(run.metrics.action, 0.0);
    EXPECT_TRUE(std::isfinite(run.metrics.power));
    EXPECT_GE(run.metrics.smoothness, 0.0);
}

// every planner of the registry on every benchmark scene, each with a seed that solves it within
// seconds (SST stops at its first solution)
INSTANTIATE_TEST_SUITE_P(
    EveryPlannerOnEveryScene, SolvesTheScene,
    ::testing::ValuesIn(
        []
        {
            std::vector<PlannerCase> cases;
            for (int scene : {1, 2, 3})
                for (const char *planner : {"rrt", "est", "kpiece", "sycloprrt", "syclopest", "pdst", "sst"})
                    cases.push_back({scene, planner, 1, EVERY_PLANNER_BOUND});
            return cases;
        }()),
    caseName);

TEST(PhysicsSetup, SameSeedGivesTheSamePlan)
{
    // SyclopRRT solves scene 1 with seed 1 in a few seconds, far inside the limit, so both runs stop at
    // the same iteration
    const PlanRun first = solveScene(1, "sycloprrt", 1, SYCLOPRRT_SEED_1_BOUND);
    const PlanRun second = solveScene(1, "sycloprrt", 1, SYCLOPRRT_SEED_1_BOUND);
    ASSERT_TRUE(first.exact);
    ASSERT_TRUE(second.exact);
    EXPECT_TRUE(first.path == second.path) << "controls, durations or states differ";
    EXPECT_TRUE(sameBits(first.metrics.action, second.metrics.action));
    EXPECT_TRUE(sameBits(first.metrics.power, second.metrics.power));
    EXPECT_TRUE(sameBits(first.metrics.smoothness, second.metrics.smoothness));
}

// --- bad starts and goals --------------------------------------------------------------------------------

namespace
{
    /** The small scene with line `line` replaced. */
    PhysicsScene smallSceneWithLine(int line, const std::string &text)
    {
        std::vector<std::string> lines = smallSceneLines();
        lines.at(static_cast<std::size_t>(line - 1)) = text;
        return parsePhysicsScene(joinLines(lines), "test.xml");
    }

    /** The fault found before planning in the small scene with line `line` replaced: the
     * ompl_core::InputError message of building a PhysicsSetup for it, else the message of its
     * goalFault(), else "". */
    std::string setupErrorWithLine(int line, const std::string &text)
    {
        return ompl_core::test::setupFaultOf<PhysicsSetup>(smallSceneWithLine(line, text));
    }
}  // namespace

TEST(PhysicsSetup, SmallSceneBuilds)
{
    EXPECT_EQ(inputErrorOf([] { PhysicsSetup setup(smallScene()); }), "");
}

TEST(PhysicsSetup, StartOverlappingAFixedBodyIsRejected)
{
    // the wall spans y in [0.7, 0.9]: a robot (radius 0.08) at y = 0.65 overlaps it by 3 cm
    const std::string message =
        setupErrorWithLine(6, R"(  <robot name="robot" radius="0.08" mass="1" start="0 0.65"/>)");
    // named at the wall's line (7), with the wall's name
    EXPECT_TRUE(startsWith(message, "test.xml:7: ")) << message;
    EXPECT_TRUE(contains(message, "starts touching 'wall'")) << message;
}

TEST(PhysicsSetup, StartOverlappingAMovableBodyIsRejected)
{
    // the free cube spans y in [-0.5, -0.3]: the robot at y = -0.25 overlaps it by 3 cm
    const std::string message =
        setupErrorWithLine(6, R"(  <robot name="robot" radius="0.08" mass="1" start="0.6 -0.25"/>)");
    EXPECT_TRUE(startsWith(message, "test.xml:6: ")) << message;
    EXPECT_TRUE(contains(message, "overlap")) << message;
}

TEST(PhysicsSetup, StartTouchingAConstrainedBodyOutsideItsStripIsRejected)
{
    // the slider (0.2 m cube at the origin) touched from the side, 1 mm deep: the error names its line (10)
    const std::string message =
        setupErrorWithLine(6, R"(  <robot name="robot" radius="0.08" mass="1" start="0.1795 0"/>)");
    EXPECT_TRUE(startsWith(message, "test.xml:10: ")) << message;
    EXPECT_TRUE(contains(message, "slider")) << message;
}

TEST(PhysicsSetup, GoalCoveredByAFixedBodyIsRejected)
{
    // the wall moved onto the goal (0.8, -0.8)
    const std::string message = setupErrorWithLine(
        7, R"(  <body name="wall" kind="fixed"><origin xyz="0.8 -0.75 0.1"/><box size="1 0.2 0.2"/></body>)");
    EXPECT_TRUE(startsWith(message, "test.xml:15: ")) << message;
    EXPECT_TRUE(contains(message, "wall")) << message;
}

TEST(PhysicsSetup, StartPenetrationJustWithinAndBeyondTheTolerance)
{
    // the free cube's north face is at y = -0.3; the robot (radius 0.08) 1.5 mm and 2.5 mm into it, against
    // a tolerance of 2 mm (soft contacts settle that deep)
    EXPECT_EQ(setupErrorWithLine(6, R"(  <robot name="robot" radius="0.08" mass="1" start="0.6 -0.2215"/>)"),
              "");
    const std::string message =
        setupErrorWithLine(6, R"(  <robot name="robot" radius="0.08" mass="1" start="0.6 -0.2225"/>)");
    EXPECT_TRUE(startsWith(message, "test.xml:6: bodies overlap at the start (0.0025")) << message;
    EXPECT_TRUE(contains(message, " m deep)")) << message;
}

TEST(PhysicsSetup, StartTouchingTheConstrainedBodyJustInsideAndOutsideItsStrip)
{
    // the slider's strip is |x| <= 0.06; the robot touches its south face (y = -0.1) 0.5 mm deep
    EXPECT_EQ(
        setupErrorWithLine(6, R"(  <robot name="robot" radius="0.08" mass="1" start="0.059 -0.1795"/>)"), "");
    EXPECT_EQ(
        setupErrorWithLine(6, R"(  <robot name="robot" radius="0.08" mass="1" start="-0.059 -0.1795"/>)"),
        "");
    const std::string message =
        setupErrorWithLine(6, R"(  <robot name="robot" radius="0.08" mass="1" start="0.061 -0.1795"/>)");
    EXPECT_EQ(message, "test.xml:10: the robot starts touching 'slider', which it must not touch");
}

TEST(PhysicsSetup, StartJustTouchingOrClearOfAFixedBody)
{
    // the wall's south face is at y = 0.7: the robot 0.5 mm into it, or 0.5 mm away
    EXPECT_EQ(setupErrorWithLine(6, R"(  <robot name="robot" radius="0.08" mass="1" start="0 0.6205"/>)"),
              "test.xml:7: the robot starts touching 'wall', which it must not touch");
    EXPECT_EQ(setupErrorWithLine(6, R"(  <robot name="robot" radius="0.08" mass="1" start="0 0.6195"/>)"),
              "");
}

TEST(PhysicsSetup, StartInsideAFixedPrismIsRejected)
{
    // the robot wholly inside the wedge (inradius about 0.099 m > 0.08 m)
    const std::string message =
        setupErrorWithLine(6, R"(  <robot name="robot" radius="0.08" mass="1" start="-0.6 0.3"/>)");
    EXPECT_EQ(message, "test.xml:8: the robot starts touching 'wedge', which it must not touch");
}

TEST(PhysicsSetup, StartBreakingARuleOfAScene)
{
    // the loader rejects such starts; a scene built or changed in code reaches the setup's own check, which
    // names the robot's line
    PhysicsScene scene = smallScene();
    scene.robot.start.x() = 1.001;  // the robot region ends at x = 1
    EXPECT_EQ(inputErrorOf([&] { PhysicsSetup setup(scene); }),
              "small.xml:6: the start breaks a rule: outside_region");
    scene.robot.start.x() = 0.999;
    scene.robot.start.y() = 0.0;
    EXPECT_EQ(inputErrorOf([&] { PhysicsSetup setup(scene); }), "");

    scene = smallScene();
    scene.bodies[scene.bodyIndex("loose")].start.translation().x() = 1.201;  // the body region ends at 1.2
    EXPECT_EQ(inputErrorOf([&] { PhysicsSetup setup(scene); }),
              "small.xml:6: the start breaks a rule: outside_region");
    scene.bodies[scene.bodyIndex("loose")].start.translation().x() = 1.199;
    EXPECT_EQ(inputErrorOf([&] { PhysicsSetup setup(scene); }), "");
}

TEST(PhysicsSetup, GoalJustCoveredOrFreeOfAFixedBody)
{
    // the wall's south face 79 mm or 81 mm north of the goal centre (0.8, -0.8); the robot's radius is 80 mm
    EXPECT_EQ(
        setupErrorWithLine(
            7,
            R"(  <body name="wall" kind="fixed"><origin xyz="0.8 -0.621 0.1"/><box size="1 0.2 0.2"/></body>)"),
        "test.xml:15: the goal cannot be reached: fixed body 'wall' covers its centre");
    EXPECT_EQ(
        setupErrorWithLine(
            7,
            R"(  <body name="wall" kind="fixed"><origin xyz="0.8 -0.619 0.1"/><box size="1 0.2 0.2"/></body>)"),
        "");
}

TEST(PhysicsSetup, AGoalCoveredByAFixedBodyIsAnsweredWithOMPLsInfeasibleStatusWithoutPlanning)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    PhysicsSetup setup(smallSceneWithLine(
        7,
        R"(  <body name="wall" kind="fixed"><origin xyz="0.8 -0.621 0.1"/><box size="1 0.2 0.2"/></body>)"));
    ASSERT_TRUE(setup.goalFault());
    EXPECT_EQ(setup.solve(10.0), ompl_core::infeasibleStatus());
    EXPECT_EQ(setup.solve(ompl::base::IterationTerminationCondition(100)), ompl_core::infeasibleStatus());
    EXPECT_EQ(setup.getLastPlannerStatus(), ompl_core::infeasibleStatus());
    EXPECT_FALSE(setup.haveSolutionPath());
    ompl::control::PlannerData data(setup.getSpaceInformation());
    setup.getPlannerData(data);
    EXPECT_EQ(data.numVertices(), 0u) << "the planner ran";
    // a goal of the program's own is planned for
    auto start = std::make_shared<ompl::base::GoalState>(setup.getSpaceInformation());
    start->setState(setup.getProblemDefinition()->getStartState(0));
    setup.setGoal(start);
    EXPECT_NE(setup.solve(ompl::base::IterationTerminationCondition(10)), ompl_core::infeasibleStatus());
    setup.getPlannerData(data);
    EXPECT_GT(data.numVertices(), 0u) << "the planner did not run";
}

TEST(PhysicsSetup, RunResultReadsPdstTreeWithoutPropagating)
{
    // PDST::getPlannerData simulates every split motion again; the run record must neither wait for
    // that after the time limit nor count it as planning
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    seedOmpl(4);
    PhysicsSetup setup(benchmarkScene(1));
    setup.setPlannerByName("pdst");
    setup.solve(ompl::base::IterationTerminationCondition(2000));
    const PhysicsStatePropagator::Counters before = setup.propagator().counters();
    const ompl_core::RunResult result = physicsRunResult({"scene 1", "pdst", 4, 1.0}, setup, nullptr);
    EXPECT_EQ(setup.propagator().counters().propagations, before.propagations);

    const auto count = [&](const std::string &path)
    { return std::get<std::uint64_t>(result.details.find(path)->value); };
    EXPECT_EQ(count("stats.propagations"), before.propagations);
    const auto *pdst = dynamic_cast<const PDSTPlanner *>(setup.getPlanner().get());
    ASSERT_NE(pdst, nullptr);
    EXPECT_EQ(count("stats.tree_vertices"), pdst->motionCount());
    EXPECT_GT(pdst->motionCount(), 100u);
}

TEST(PhysicsSetup, ResimulationLeavesTheSearchsCounters)
{
    // the JSON's propagations and substeps are the search's, not the check's that follows it
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    seedOmpl(5);
    PhysicsSetup setup(benchmarkScene(1));
    setup.setPlannerByName("rrt");
    ASSERT_TRUE(setup.solve(ompl::base::IterationTerminationCondition(32000)));
    ASSERT_TRUE(setup.haveExactSolutionPath());
    const PhysicsStatePropagator::Counters searched = setup.propagator().counters();
    const SimulatedPath simulated = simulatePath(setup, setup.getSolutionPath());
    ASSERT_GT(simulated.robot.moves.size(), 0u);
    EXPECT_EQ(setup.propagator().counters().propagations, searched.propagations);
    EXPECT_EQ(setup.propagator().counters().substeps, searched.substeps);
    EXPECT_EQ(setup.propagator().counters().stops, searched.stops);
}
