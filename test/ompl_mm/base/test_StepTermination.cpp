// Tests for StepTermination: the view of a planner's termination condition that the inside of the
// planner's steps polls, which evaluates the condition only when a step takes long.
#include "ompl_mm/base/StepTermination.h"

#include <ompl/base/terminationconditions/IterationTerminationCondition.h>

#include <gtest/gtest.h>

using ompl_mm::StepTermination;
namespace ob = ompl::base;

TEST(StepTermination, AQuickStepCostsNoEvaluation)
{
    // a period no step lasts: however often the step polls, the condition is not evaluated
    unsigned int evaluations = 0;
    const ob::PlannerTerminationCondition counting(
        [&evaluations]
        {
            ++evaluations;
            return true;
        });
    const StepTermination view(counting, 1e6);
    for (int k = 0; k < 1000; ++k)
        EXPECT_FALSE(view.condition()());
    EXPECT_EQ(evaluations, 0u);
}

TEST(StepTermination, AnIterationCountingConditionCountsThePlannersIterationsAlone)
{
    // OMPL's IterationTerminationCondition takes every evaluation for an iteration: five
    // iterations whose steps poll the view a hundred times each are still five
    ob::IterationTerminationCondition iterations(5);
    const ob::PlannerTerminationCondition ptc = iterations;
    StepTermination view(ptc, 1e6);
    unsigned int done = 0;
    while (!ptc)
    {
        view.startStep();
        for (int k = 0; k < 100; ++k)
            ASSERT_FALSE(view.condition()());
        ++done;
    }
    EXPECT_EQ(done, 5u);
}

TEST(StepTermination, WithoutAPeriodEveryPollEvaluatesAndTrueStaysTrue)
{
    unsigned int evaluations = 0;
    const ob::PlannerTerminationCondition thirdIsTrue([&evaluations] { return ++evaluations >= 3; });
    const StepTermination view(thirdIsTrue, 0.0);
    EXPECT_FALSE(view.condition()());
    EXPECT_FALSE(view.condition()());
    EXPECT_TRUE(view.condition()());
    EXPECT_TRUE(view.condition()());
    EXPECT_EQ(evaluations, 3u) << "a true answer is remembered, not asked again";
}

TEST(StepTermination, CopiesOfTheConditionShareTheView)
{
    unsigned int evaluations = 0;
    const ob::PlannerTerminationCondition firstIsTrue([&evaluations] { return ++evaluations >= 1; });
    const StepTermination view(firstIsTrue, 0.0);
    const ob::PlannerTerminationCondition copy = view.condition();
    EXPECT_TRUE(copy());
    EXPECT_TRUE(view.condition()());
    EXPECT_EQ(evaluations, 1u);
}
