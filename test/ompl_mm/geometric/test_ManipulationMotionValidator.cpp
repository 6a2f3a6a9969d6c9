// Tests for ManipulationMotionValidator: which motions a primitive explains, collisions along them,
// the last valid state, and the relabelling of paths that OMPL's tools change.
#include "ompl_mm/geometric/ManipulationMotionValidator.h"

#include "common/MobileBlocked.h"

#include <ompl/geometric/PathSimplifier.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace ompl_mm;
using namespace ompl_mm::test;
namespace ob = ompl::base;

namespace
{

    class MotionValidation : public MobileBlockedTest
    {
    protected:
        MotionValidation()
        {
            si_->setup();
            validator_ = std::dynamic_pointer_cast<ManipulationMotionValidator>(si_->getMotionValidator());
            // obj2 stands at (0.8, -0.1); a push along +y starts with the robot STANDOFF below it
            from_ = startCopy();
            to_ = startCopy();
            setRobot(space_, from_, 0.8, -0.1 - STANDOFF);
            setRobot(space_, to_, 0.8, 0.3 - STANDOFF);
            setObject(space_, to_, 1, 0.8, 0.3);
            // free, 0.5 m below from_
            below_ = startCopy();
            setRobot(space_, below_, 0.8, -0.1 - STANDOFF - 0.5);
        }

        ob::SpaceInformationPtr si_ = setup_.getSpaceInformation();
        std::shared_ptr<ManipulationMotionValidator> validator_;
        ob::State *from_;
        ob::State *to_;
        ob::State *below_;
    };
}  // namespace

namespace
{
    /** MOBILE BLOCKED without its walls: the robot can pass its joint limit (x = 2.5) without
        touching anything. */
    Scene openEndedScene()
    {
        Scene scene = mobileBlockedScene();
        scene.obstacles.erase(std::remove_if(scene.obstacles.begin(), scene.obstacles.end(),
                                             [](const Obstacle &o) { return o.name.rfind("wall_", 0) == 0; }),
                              scene.obstacles.end());
        return scene;
    }

    class OpenEndedMotions : public MobileBlockedTest
    {
    protected:
        OpenEndedMotions() : MobileBlockedTest(openEndedScene()) { setup_.setup(); }

        /** Whether both of the space information's checks reject the motion, the one with a last
            valid state giving its start. */
        bool rejected(const ob::State *from, const ob::State *to)
        {
            const ob::SpaceInformationPtr si = setup_.getSpaceInformation();
            std::pair<ob::State *, double> last{nullptr, -1.0};
            return !si->checkMotion(from, to) && !si->checkMotion(from, to, last) && last.second == 0.0;
        }
    };
}  // namespace

TEST_F(OpenEndedMotions, AMotionWhoseEndBreaksARuleOtherThanCollisionIsInvalid)
{
    const ob::SpaceInformationPtr si = setup_.getSpaceInformation();
    const auto validator = std::dynamic_pointer_cast<ManipulationMotionValidator>(si->getMotionValidator());
    // a transit 5 cm past the robot's joint limit, through free space
    ob::State *from = startCopy();
    setRobot(space_, from, 2.0, 1.9);
    ob::State *past = startCopy();
    setRobot(space_, past, 2.55, 1.9);
    ASSERT_TRUE(si->isValid(from));
    ASSERT_FALSE(si->isValid(past));
    EXPECT_TRUE(validator->explain(from, past) == TRANSIT);
    EXPECT_TRUE(rejected(from, past));
    setRobot(space_, past, 2.45, 1.9);
    EXPECT_TRUE(si->checkMotion(from, past)) << "just inside the limit";
    // (the end's other rule, objects on their surfaces, no explained motion can break: a push that
    // leaves its object off its surface is no push, and nothing else moves an object that rests)
}

TEST_F(MotionValidation, SetupInstallsIt)
{
    ASSERT_NE(validator_, nullptr);
    EXPECT_EQ(validator_->primitives().size(), 2u);
}

TEST_F(MotionValidation, TransitMovesTheRobotOnly)
{
    ob::State *there = startCopy();
    setRobot(space_, there, 2.2, 1.9);
    EXPECT_TRUE(validator_->explain(startCopy(), there) == TRANSIT);
    EXPECT_TRUE(si_->checkMotion(startCopy(), there));
}

TEST_F(MotionValidation, PushWithTheToolBehindTheObjectIsValid)
{
    EXPECT_TRUE(validator_->explain(from_, to_) == (SegmentLabel{PrimitiveKind::Push, 1}));
    EXPECT_TRUE(si_->checkMotion(from_, to_));
    EXPECT_TRUE(si_->checkMotion(to_, from_) == false) << "pulling back: the tool is in front of the object";
}

TEST_F(MotionValidation, AnObjectMovingWithoutThePushIsInvalid)
{
    // the object slides while the robot is elsewhere: every state on the way is collision-free
    ob::State *slid = startCopy();
    setObject(space_, slid, 1, 0.8, 0.3);
    EXPECT_FALSE(validator_->explain(startCopy(), slid));
    EXPECT_FALSE(si_->checkMotion(startCopy(), slid));
    // the tool 1 cm off the push line at the end, or a standoff 1 cm short, is no push either
    setRobot(space_, to_, 0.81, 0.3 - STANDOFF);
    EXPECT_FALSE(validator_->explain(from_, to_));
    setRobot(space_, to_, 0.8, 0.31 - STANDOFF);
    EXPECT_FALSE(validator_->explain(from_, to_));
    // just inside the 1e-6 m tolerance still is
    setRobot(space_, to_, 0.8 + 5e-7, 0.3 - STANDOFF);
    EXPECT_TRUE(validator_->explain(from_, to_));
}

TEST_F(MotionValidation, TwoObjectsMovingAtOnceAreInvalid)
{
    setObject(space_, to_, 3, 1.2, 1.5);
    EXPECT_FALSE(validator_->explain(from_, to_));
}

TEST_F(MotionValidation, AnObjectLiftedOffItsSurfaceIsNoPush)
{
    setObject(space_, to_, 1, 0.8, 0.3, 0.1);
    EXPECT_FALSE(validator_->explain(from_, to_));
}

TEST_F(MotionValidation, CollisionsAlongAnExplainedMotionAreFound)
{
    // the robot from its start (1.9, 1.9) straight through block3 (x 1.2..2.2, y 0.15..1.45)
    ob::State *through = startCopy();
    setRobot(space_, through, 1.9, 0.0);
    ASSERT_TRUE(validator_->explain(startCopy(), through));
    EXPECT_FALSE(si_->checkMotion(startCopy(), through));
    std::pair<ob::State *, double> lastValid{startCopy(), -1.0};
    EXPECT_FALSE(si_->checkMotion(startCopy(), through, lastValid));
    // the disc (radius 0.2) touches the block at y = 1.65; steps of at most 0.05 from y 1.9
    EXPECT_GT(space_.robotValues(lastValid.first)[1], 1.65);
    EXPECT_LT(space_.robotValues(lastValid.first)[1], 1.65 + 0.05 + 1e-9);
    EXPECT_NEAR(lastValid.second, (1.9 - space_.robotValues(lastValid.first)[1]) / 1.9, 1e-12);
    EXPECT_TRUE(si_->isValid(lastValid.first));
}

TEST_F(MotionValidation, ProbingRejectsOnlyWhatTheSweepRejects)
{
    // random transits and pushes over the room: the quick answer (probes, then the sweep) and the
    // one with a last valid state (the sweep alone) agree
    ompl::RNG rng(11);
    unsigned int valid = 0, invalid = 0;
    for (int k = 0; k < 300; ++k)
    {
        ob::State *a = startCopy(), *b = startCopy();
        setRobot(space_, a, rng.uniformReal(-2.3, 2.3), rng.uniformReal(-2.3, 2.3));
        setRobot(space_, b, rng.uniformReal(-2.3, 2.3), rng.uniformReal(-2.3, 2.3));
        if (!si_->isValid(a))
            continue;
        std::pair<ob::State *, double> lastValid{newState(), -1.0};
        const bool quick = si_->checkMotion(a, b);
        EXPECT_EQ(quick, si_->checkMotion(a, b, lastValid)) << "motion " << k;
        ++(quick ? valid : invalid);
    }
    EXPECT_GT(valid, 20u);
    EXPECT_GT(invalid, 20u);
}

TEST_F(MotionValidation, AnUnexplainedMotionHasItsStartAsLastValidState)
{
    ob::State *slid = startCopy();
    setObject(space_, slid, 1, 0.8, 0.3);
    std::pair<ob::State *, double> lastValid{newState(), -1.0};
    EXPECT_FALSE(si_->checkMotion(startCopy(), slid, lastValid));
    EXPECT_EQ(lastValid.second, 0.0);
    EXPECT_TRUE(space_.equalStates(lastValid.first, startCopy()));
}

TEST_F(MotionValidation, CountsValidAndInvalidMotions)
{
    validator_->resetMotionCounter();
    si_->checkMotion(from_, to_);
    si_->checkMotion(to_, from_);
    si_->checkMotion(to_, from_);
    EXPECT_EQ(validator_->getValidMotionCount(), 1u);
    EXPECT_EQ(validator_->getInvalidMotionCount(), 2u);
}

TEST_F(MotionValidation, AStoppedCheckNeverPasses)
{
    // a valid transit, checked once more with its termination condition over: not free
    ob::State *there = startCopy();
    setRobot(space_, there, 2.2, 1.9);
    ASSERT_TRUE(si_->checkMotion(startCopy(), there));
    const ob::PlannerTerminationCondition ended([] { return true; });
    const CollisionWorld::SweepCheck stopped = validator_->checkSweep(startCopy(), there, ended);
    EXPECT_FALSE(stopped.free);
    EXPECT_EQ(stopped.safeFraction, 0.0);
    {
        // for OMPL's callers, which cannot pass one: every check within the scope
        const ManipulationMotionValidator::TerminationScope scope(*validator_, ended);
        EXPECT_FALSE(si_->checkMotion(startCopy(), there));
        std::pair<ob::State *, double> lastValid{newState(), -1.0};
        EXPECT_FALSE(si_->checkMotion(startCopy(), there, lastValid));
        EXPECT_EQ(lastValid.second, 0.0);
        EXPECT_FALSE(validator_->checkSweep(startCopy(), there).free);
    }
    // once the scope ends, the checks are as before
    EXPECT_TRUE(si_->checkMotion(startCopy(), there));
    EXPECT_TRUE(validator_->checkSweep(startCopy(), there, ob::plannerNonTerminatingCondition()).free);
}

TEST_F(MotionValidation, ACheckStopsBetweenTheRoundsOfItsSweep)
{
    // the robot from its start (1.9, 1.9) straight into block3 (y 0.15..1.45): the sweep closes in
    // over several rounds and finds the contact, with a safe fraction on the way there
    ob::State *through = startCopy();
    setRobot(space_, through, 1.9, 0.0);
    unsigned int polls = 0;
    const ob::PlannerTerminationCondition counting(
        [&polls]
        {
            ++polls;
            return false;
        });
    const CollisionWorld::SweepCheck full = validator_->checkSweep(startCopy(), through, counting);
    ASSERT_FALSE(full.free);
    ASSERT_GT(full.safeFraction, 0.0);
    ASSERT_GE(polls, 3u) << "once before the sweep, then once per round after the first";
    // true from its second poll on: the sweep stops after its first round, at that poll
    polls = 0;
    const ob::PlannerTerminationCondition secondPoll([&polls] { return ++polls >= 2; });
    const CollisionWorld::SweepCheck stopped = validator_->checkSweep(startCopy(), through, secondPoll);
    EXPECT_FALSE(stopped.free);
    EXPECT_EQ(stopped.safeFraction, 0.0) << "nothing of a stopped check counts as free";
    EXPECT_EQ(polls, 2u);
    // and the validator is ready for the next check
    const CollisionWorld::SweepCheck again = validator_->checkSweep(startCopy(), through);
    EXPECT_FALSE(again.free);
    EXPECT_EQ(again.safeFraction, full.safeFraction);
}

TEST_F(MotionValidation, AMotionFoundFreeIsNotSweptAgainButEveryOtherIs)
{
    // a check polls a scope's condition before it starts and a sweep at every further round:
    // counting the polls tells whether checkMotion swept
    unsigned int polls = 0;
    const ob::PlannerTerminationCondition counting(
        [&polls]
        {
            ++polls;
            return false;
        });
    const ManipulationMotionValidator::TerminationScope scope(*validator_, counting);
    // MOBILE BLOCKED's sweeps are quick: remember them all
    validator_->setShortestRememberedSweep(0.0);
    ob::State *there = startCopy();
    setRobot(space_, there, 2.2, 1.9);
    ASSERT_TRUE(si_->checkMotion(startCopy(), there));
    const unsigned int swept = polls;
    // the same motion, bit for bit: the same answer, without the sweep's rounds
    polls = 0;
    EXPECT_TRUE(si_->checkMotion(startCopy(), there));
    const unsigned int remembered = polls;
    EXPECT_LT(remembered, swept);
    // so is the reverse motion, through the same configurations
    polls = 0;
    EXPECT_TRUE(si_->checkMotion(there, startCopy()));
    EXPECT_EQ(polls, remembered);
    // the end moved by the least amount is swept anew
    space_.robotValues(there)[0] = std::nextafter(space_.robotValues(there)[0], 0.0);
    polls = 0;
    EXPECT_TRUE(si_->checkMotion(startCopy(), there));
    EXPECT_GT(polls, remembered);
    // a motion that collides is never remembered (checked without the probes, which would
    // reject it before any sweep): the same rounds again
    ob::State *through = startCopy();
    setRobot(space_, through, 1.9, 0.0);
    std::pair<ob::State *, double> lastValid{newState(), -1.0};
    polls = 0;
    EXPECT_FALSE(si_->checkMotion(startCopy(), through, lastValid));
    const unsigned int blocked = polls;
    EXPECT_GT(blocked, remembered);
    polls = 0;
    EXPECT_FALSE(si_->checkMotion(startCopy(), through, lastValid));
    EXPECT_EQ(polls, blocked);
    EXPECT_GT(lastValid.second, 0.0);
    // sweeps quicker than the shortest remembered one are swept every time
    validator_->setShortestRememberedSweep(1e9);
    setRobot(space_, there, 2.0, 1.9);
    polls = 0;
    ASSERT_TRUE(si_->checkMotion(startCopy(), there));
    const unsigned int first = polls;
    polls = 0;
    EXPECT_TRUE(si_->checkMotion(startCopy(), there));
    EXPECT_EQ(polls, first);
    EXPECT_GT(first, remembered);
}

TEST_F(MotionValidation, PathsChangedByOMPLAreRelabelledFromTheirMotions)
{
    ManipulationPath path(si_);
    path.appendFirst(below_);
    path.appendLabelled(from_, TRANSIT);
    path.appendLabelled(to_, {PrimitiveKind::Push, 1});
    path.interpolate(12);  // OMPL's own: inserts states, knows nothing of labels
    ASSERT_EQ(path.getStateCount(), 12u);
    ASSERT_EQ(path.labels().size(), 11u);
    EXPECT_EQ(path.checkLabels(), "");
    EXPECT_EQ(path.primitiveCounts().at("transit"), 1u);
    EXPECT_EQ(path.primitiveCounts().at("push"), 1u);
    EXPECT_TRUE(path.label(0) == TRANSIT);
    EXPECT_TRUE(path.label(10) == (SegmentLabel{PrimitiveKind::Push, 1}));
    EXPECT_TRUE(path.check());

    // a state changed in place so that an object slides by itself: reported, never mislabelled
    setObject(space_, path.getState(5), 3, 1.2, 1.5);
    EXPECT_FALSE(path.check());
    EXPECT_THROW(path.labels(), ompl::Exception);
    EXPECT_TRUE(
        startsWith(path.checkLabels(), "ManipulationPath: segment 4 of the changed path is no motion"))
        << path.checkLabels();
}

TEST_F(MotionValidation, WithoutTheValidatorChangedPathsAreReported)
{
    auto si = std::make_shared<ob::SpaceInformation>(setup_.getStateSpace());
    si->setStateValidityChecker(setup_.getStateValidityChecker());
    si->setup();
    ManipulationPath path(si);
    path.appendFirst(startCopy());
    path.appendLabelled(to_, TRANSIT);
    EXPECT_TRUE(path.label(0) == TRANSIT) << "unchanged states keep the labels given";
    path.interpolate(3);
    EXPECT_THROW(path.labels(), ompl::Exception);
}

TEST_F(MotionValidation, WorksOnASpaceInformationOfYourOwn)
{
    auto si = std::make_shared<ob::SpaceInformation>(setup_.getStateSpace());
    si->setStateValidityChecker(setup_.getStateValidityChecker());
    si->setMotionValidator(std::make_shared<ManipulationMotionValidator>(si, setup_.primitives()));
    si->setup();
    ob::State *slid = startCopy();
    setObject(space_, slid, 1, 0.8, 0.3);
    EXPECT_FALSE(si->checkMotion(startCopy(), slid));
    EXPECT_TRUE(si->checkMotion(from_, to_));
}

TEST_F(MotionValidation, OMPLsSimplifierKeepsPushesPushes)
{
    // a push made of three collinear steps becomes one push; the transit before it straightens
    ManipulationPath path(si_);
    path.appendFirst(below_);
    ob::State *corner = startCopy();
    setRobot(space_, corner, 1.3, -0.8);
    path.appendLabelled(corner, TRANSIT);
    path.appendLabelled(from_, TRANSIT);
    for (double y : {0.0, 0.1, 0.2, 0.3})
    {
        ob::State *step = startCopy();
        setRobot(space_, step, 0.8, y - STANDOFF);
        setObject(space_, step, 1, 0.8, y);
        path.appendLabelled(step, {PrimitiveKind::Push, 1});
    }
    ompl::geometric::PathSimplifier simplifier(si_);
    simplifier.simplifyMax(path);
    EXPECT_TRUE(path.check());
    EXPECT_EQ(path.checkLabels(), "");
    EXPECT_EQ(path.primitiveCounts().at("push"), 1u);
    EXPECT_TRUE(space_.equalStates(path.getState(path.getStateCount() - 1), to_));
    EXPECT_LT(path.getStateCount(), 6u);
}
