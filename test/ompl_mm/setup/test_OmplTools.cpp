// OMPL's own tools on a ManipulationSetup, used as an OMPL user would: Benchmark with its default
// request (which simplifies every solution), SimpleSetup::simplifySolution and PathGeometric::check.
// Every simplified path is re-checked independently (common/PlanarRecheck.h).
#include "common/PlanarRecheck.h"
#include "ompl_core/compat/OmplVersions.h"

#include <ompl/base/PlannerData.h>
#include <ompl/base/terminationconditions/IterationTerminationCondition.h>
#include <ompl/geometric/PathSimplifier.h>
#include <ompl/tools/benchmark/Benchmark.h>
#include <ompl/util/Console.h>

#include <gtest/gtest.h>

using namespace ompl_mm;
using namespace ompl_mm::test;

TEST(OmplTools, BenchmarkWithItsDefaultRequestGivesCorrectSimplifiedPaths)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    ompl::RNG::setSeed(
        2);  // OMPL's simplifier draws from it: the seed under which B-spline smoothing broke seed 6
    const Scene scene = mobileBlockedScene();
    ManipulationSetup setup(scene);
    ompl::tools::Benchmark benchmark(setup, "mobile_blocked");
    benchmark.addPlanner(setup.getPlanner());
    unsigned int seed = 0;
    benchmark.setPreRunEvent([&](const ompl::base::PlannerPtr &) { setup.mopl()->setSeed(++seed); });
    unsigned int rechecked = 0;
    benchmark.setPostRunEvent(
        [&](const ompl::base::PlannerPtr &, ompl::tools::Benchmark::RunProperties &run)
        {
            ASSERT_EQ(run.at("solved BOOLEAN"), "1") << "seed " << seed;
            SCOPED_TRACE("seed " + std::to_string(seed));
            const ManipulationPath &path = setup.manipulationPath();
            planarRecheck(*setup.manipulationSpace(), path, scene);
            EXPECT_EQ(path.checkLabels(), "");
            EXPECT_EQ(run.at("correct solution BOOLEAN"), "1");
            EXPECT_EQ(run.at("simplified correct solution BOOLEAN"), "1");
            EXPECT_EQ(run.at("simplified solution segments INTEGER"),
                      std::to_string(path.getStateCount() - 1));
            // MOPL's properties describe the logged path: the tool (the disc's centre) travels
            // straight between waypoints, and each segment is a push or a transit
            // (a primitive is a run of segments with one label)
            double toolLength = 0.0;
            unsigned int pushes = 0;
            const ManipulationStateSpace &space = *setup.manipulationSpace();
            for (std::size_t k = 0; k + 1 < path.getStateCount(); ++k)
            {
                toolLength +=
                    (space.toolPosition(path.getState(k + 1)) - space.toolPosition(path.getState(k))).norm();
                if (path.label(k).kind == PrimitiveKind::Push &&
                    (k == 0 || !(path.label(k - 1) == path.label(k))))
                    ++pushes;
            }
            EXPECT_NEAR(std::stod(run.at("path_length_m REAL")), toolLength, 1e-9 * toolLength);
            EXPECT_EQ(run.at("primitives_push INTEGER"), std::to_string(pushes));
            ++rechecked;
        });
    ompl::tools::Benchmark::Request request;  // OMPL's defaults: simplify = true
    request.maxTime =
        30.0;  // Benchmark needs a time: the slowest of these seeds takes about 1 s, 8 s under ASan
    request.runCount = 20;
    request.displayProgress = false;
    request.saveConsoleOutput = false;
    benchmark.benchmark(request);
    EXPECT_EQ(rechecked, 20u);
}

TEST(OmplTools, CheckRejectsAnObjectMovedWithoutAPush)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    ManipulationSetup setup(mobileBlockedScene());
    setup.mopl()->setSeed(1);
    ASSERT_EQ(setup.solve(ompl::base::IterationTerminationCondition(20000)),
              ompl::base::PlannerStatus::EXACT_SOLUTION);
    ManipulationPath &path = setup.manipulationPath();
    ASSERT_TRUE(path.check());
    // move obj3 to its goal in the second state: collision-free, but nothing pushes it there
    setup.manipulationSpace()->setObjectPose(path.getState(1), 2, {Eigen::Vector3d(-0.9, -0.9, 0.0), 0.0});
    ASSERT_TRUE(setup.getSpaceInformation()->isValid(path.getState(1)));
    EXPECT_FALSE(path.check());
    EXPECT_NE(path.checkLabels(), "");
    // Benchmark reads planner data after simplifying: a broken path gives no counts, and no throw
    ompl::base::PlannerData data(setup.getSpaceInformation());
    EXPECT_NO_THROW(setup.getPlannerData(data));
    EXPECT_EQ(data.properties.count("path_length_m REAL"), 0u);
}

TEST(OmplTools, SimplifySolutionKeepsTheLabelsTrue)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    const Scene scene = mobileBlockedScene();
    ManipulationSetup setup(scene);
    setup.mopl()->setSeed(4);
    ASSERT_EQ(setup.solve(ompl::base::IterationTerminationCondition(20000)),
              ompl::base::PlannerStatus::EXACT_SOLUTION);
    const std::size_t before = setup.manipulationPath().getStateCount();
    setup.simplifySolution();
    const ManipulationPath &path = setup.manipulationPath();
    EXPECT_LE(path.getStateCount(), before);
    EXPECT_EQ(path.labels().size() + 1, path.getStateCount());
    EXPECT_TRUE(path.check());
    planarRecheck(*setup.manipulationSpace(), path, scene);
}

TEST(OmplTools, OurSmoothingAfterOMPLsKeepsThePathValidAndShortensIt)
{
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    const Scene scene = mobileBlockedScene();
    ManipulationSetup setup(scene);
    setup.mopl()->setSmoothingAttempts(0);  // MOPL's own smoothing off: leave work for the call
    setup.mopl()->setSeed(1);
    ASSERT_EQ(setup.solve(ompl::base::IterationTerminationCondition(20000)),
              ompl::base::PlannerStatus::EXACT_SOLUTION);
    setup.simplifySolution();
    const double before = setup.manipulationPath().toolPathLength();
    setup.smoothSolution(200, 3);
    const ManipulationPath &path = setup.manipulationPath();
    EXPECT_LT(path.toolPathLength(), before);
    EXPECT_EQ(ManipulationSimplifier::countRoundTrips(path), 0u);
    planarRecheck(*setup.manipulationSpace(), path, scene);
}

TEST(OmplTools, EveryStepOfOMPLsSimplifierKeepsThePathValid)
{
    // each step of PathSimplifier (RRT-Rope's too, where OMPL has it), in changing orders and from several
    // simplifier seeds, on MOPL's paths: B-spline smoothing subdivides motions without checking the new
    // states, which is safe only because any part of a valid motion is valid (continuous motion checks)
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    const Scene scene = mobileBlockedScene();
    for (unsigned int seed = 1; seed <= 8; ++seed)
    {
        SCOPED_TRACE("seed " + std::to_string(seed));
        ManipulationSetup setup(scene);
        setup.mopl()->setSeed(seed);
        ASSERT_EQ(setup.solve(ompl::base::IterationTerminationCondition(20000)),
                  ompl::base::PlannerStatus::EXACT_SOLUTION);
        const ManipulationPath &solution = setup.manipulationPath();
        ASSERT_TRUE(solution.check());
        for (unsigned int order = 0; order < 6; ++order)
        {
            ompl::geometric::PathSimplifier simplifier(setup.getSpaceInformation());
            ompl::geometric::PathGeometric path(solution);
            for (unsigned int step = 0; step < 10; ++step)
            {
                const unsigned int operation = (step + order) % 6;
                switch (operation)
                {
                    case 0:
                        simplifier.reduceVertices(path);
                        break;
                    case 1:
                        ompl_core::partialShortcut(simplifier, path);
                        break;
                    case 2:
                        simplifier.smoothBSpline(path, 3, path.length() / 100.0);
                        break;
                    case 3:
                        simplifier.collapseCloseVertices(path);
                        break;
                    case 4:
                        ompl_core::ropeShortcut(simplifier, path);
                        break;
                    default:
                        EXPECT_TRUE(path.checkAndRepair(100).first);
                }
                ASSERT_TRUE(path.check())
                    << "order " << order << ", step " << step << ", operation " << operation;
            }
            ManipulationPath relabelled(setup.getSpaceInformation());
            relabelled.append(path);
            EXPECT_EQ(relabelled.checkLabels(), "");
            planarRecheck(*setup.manipulationSpace(), relabelled, scene);
        }
    }
}
