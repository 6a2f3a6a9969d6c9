// Tests for ModalSampler.
#include "ompl_mm/planners/ModalSampler.h"

#include "common/MobileBlocked.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>

using namespace ompl_mm;
using namespace ompl_mm::test;
namespace ob = ompl::base;

namespace
{
    constexpr int SAMPLES = 20000;
    constexpr double TOLERANCE = 0.02;  // absolute, on frequencies (about 6 standard deviations)
    constexpr unsigned int OBJ1 = 0, OBJ3 = 2;

    /** Where a part of a sample came from. */
    enum Source
    {
        Undefined,
        Start,
        Goal,
        Fresh,
        SourceCount
    };

    /** Frequencies of the sources of every part over many samples, split by sampling branch. */
    struct Tally
    {
        int samples{0};
        int objectBranch{0};               // samples with a freshly sampled object
        std::array<int, 4> freshObject{};  // which object was sampled
        std::array<int, SourceCount> robotInObjectBranch{};
        std::array<int, SourceCount> robotInRobotBranch{};
        std::array<std::array<int, SourceCount>, 4> objectNotSampled{};  // per object, when not the fresh one
        int notSampled[4]{};
        bool freshOffFloor{false};
    };

    class Sampler : public MobileBlockedTest
    {
    protected:
        explicit Sampler(const Scene &scene = mobileBlockedScene()) : MobileBlockedTest(scene)
        {
            setRobot(space_, goalState_, 0.0, 0.0);
            setObject(space_, goalState_, OBJ3, -0.9, -0.9);
            // obj1 has no goal; giving it a distinct value here shows whether the sampler copies it
            setObject(space_, goalState_, OBJ1, 1.0, 1.0);
            EXPECT_TRUE(setup_.manipulationGoal()->isSatisfied(goalState_));
        }

        Source robotSource(const PartialState &s) const
        {
            if (!s.robotDefined())
                return Undefined;
            const double *q = space_.robotValues(s.state());
            auto equals = [&](const ob::State *other)
            { return q[0] == space_.robotValues(other)[0] && q[1] == space_.robotValues(other)[1]; };
            return equals(start_) ? Start : equals(goalState_) ? Goal : Fresh;
        }
        Source objectSource(const PartialState &s, unsigned int i) const
        {
            if (!s.objectDefined(i))
                return Undefined;
            return !space_.objectMoves(s.state(), start_, i)       ? Start
                   : !space_.objectMoves(s.state(), goalState_, i) ? Goal
                                                                   : Fresh;
        }

        Tally run(bool forward, std::uint_fast32_t seed,
                  const std::function<void(ModalSampler &)> &configure = {}) const
        {
            ModalSampler sampler(&space_, setup_.manipulationGoal().get(), start_, goalState_);
            if (configure)
                configure(sampler);
            ompl::RNG rng;
            rng.setLocalSeed(seed);
            PartialState s(&space_);
            Tally tally;
            for (int k = 0; k < SAMPLES; ++k)
            {
                sampler.sample(s, forward, rng);
                ++tally.samples;
                int fresh = -1;
                for (unsigned int i = 0; i < 4; ++i)
                    if (objectSource(s, i) == Fresh)
                    {
                        EXPECT_EQ(fresh, -1) << "two fresh objects in sample " << k;
                        fresh = static_cast<int>(i);
                        const ObjectPose pose = space_.objectPose(s.state(), i);
                        tally.freshOffFloor |= pose.position.z() != 0.0 ||
                                               std::abs(pose.position.x()) > 2.5 ||
                                               std::abs(pose.position.y()) > 2.5 || pose.yaw != 0.0;
                    }
                if (fresh >= 0)
                {
                    ++tally.objectBranch;
                    ++tally.freshObject[fresh];
                    ++tally.robotInObjectBranch[robotSource(s)];
                }
                else
                    ++tally.robotInRobotBranch[robotSource(s)];
                for (unsigned int i = 0; i < 4; ++i)
                    if (static_cast<int>(i) != fresh)
                    {
                        ++tally.notSampled[i];
                        ++tally.objectNotSampled[i][objectSource(s, i)];
                    }
            }
            return tally;
        }

        static double rate(int count, int total) { return static_cast<double>(count) / total; }

        ob::State *start_ = startCopy();
        ob::State *goalState_ = startCopy();
    };

    Scene withoutRobotGoal()
    {
        Scene scene = mobileBlockedScene();
        scene.robotGoal.joints.clear();
        return scene;
    }

    class SamplerNoRobotGoal : public Sampler
    {
    protected:
        SamplerNoRobotGoal() : Sampler(withoutRobotGoal()) {}
    };
}  // namespace

TEST_F(Sampler, ObjectBranchFrequency)
{
    const Tally t = run(true, 21);
    EXPECT_NEAR(rate(t.objectBranch, t.samples), 0.6, TOLERANCE);
    for (unsigned int i = 0; i < 4; ++i)
        EXPECT_NEAR(rate(t.freshObject[i], t.objectBranch), 0.25, TOLERANCE) << i;
    EXPECT_FALSE(t.freshOffFloor);
}

TEST_F(Sampler, ForwardRobotIsTheGoalPoseInOneFifthOfRobotSamples)
{
    const Tally t = run(true, 22);
    const int robotBranch = t.samples - t.objectBranch;
    EXPECT_EQ(t.robotInRobotBranch[Undefined], 0);  // the robot branch always defines the robot
    EXPECT_NEAR(rate(t.robotInRobotBranch[Goal], t.samples), 0.4 * 0.2, TOLERANCE);
    EXPECT_NEAR(rate(t.robotInRobotBranch[Goal], robotBranch), 0.2, TOLERANCE);
    EXPECT_NEAR(rate(t.robotInRobotBranch[Fresh], robotBranch), 0.8, TOLERANCE);
    EXPECT_EQ(t.robotInRobotBranch[Start], 0);
}

TEST_F(Sampler, BackwardRobotIsTheStartPoseInOneFifthOfRobotSamples)
{
    const Tally t = run(false, 23);
    const int robotBranch = t.samples - t.objectBranch;
    EXPECT_NEAR(rate(t.robotInRobotBranch[Start], robotBranch), 0.2, TOLERANCE);
    EXPECT_NEAR(rate(t.robotInRobotBranch[Fresh], robotBranch), 0.8, TOLERANCE);
    EXPECT_EQ(t.robotInRobotBranch[Goal], 0);
}

TEST_F(Sampler, RobotInTheObjectBranchIsUndefinedStartOrGoal)
{
    const Tally t = run(true, 24);
    EXPECT_NEAR(rate(t.robotInObjectBranch[Undefined], t.objectBranch), 0.4, TOLERANCE);
    EXPECT_NEAR(rate(t.robotInObjectBranch[Start], t.objectBranch), 0.3, TOLERANCE);
    EXPECT_NEAR(rate(t.robotInObjectBranch[Goal], t.objectBranch), 0.3, TOLERANCE);
    EXPECT_EQ(t.robotInObjectBranch[Fresh], 0);
}

TEST_F(Sampler, ObjectsNotSampledFollowTheProbabilities)
{
    const Tally t = run(true, 25);
    // obj3 has a goal: undefined 0.4, start 0.3, goal 0.3
    const auto &obj3 = t.objectNotSampled[OBJ3];
    EXPECT_NEAR(rate(obj3[Undefined], t.notSampled[OBJ3]), 0.4, TOLERANCE);
    EXPECT_NEAR(rate(obj3[Start], t.notSampled[OBJ3]), 0.3, TOLERANCE);
    EXPECT_NEAR(rate(obj3[Goal], t.notSampled[OBJ3]), 0.3, TOLERANCE);
    // obj1 has none: the forward tree takes it from the nearest vertex
    EXPECT_EQ(t.objectNotSampled[OBJ1][Undefined], t.notSampled[OBJ1]);
}

TEST_F(Sampler, ObjectsWithoutGoalStayUndefinedForTheForwardTreeEvenInPlay)
{
    ob::State *moved = startCopy();
    setObject(space_, moved, OBJ1, 1.5, -2.0);
    const Tally t = run(true, 28, [&](ModalSampler &sampler) { sampler.noteVertex(moved); });
    EXPECT_GT(t.notSampled[OBJ1], SAMPLES / 2);
    EXPECT_EQ(t.objectNotSampled[OBJ1][Undefined], t.notSampled[OBJ1]);
    // the goal's object keeps its three choices
    EXPECT_NEAR(rate(t.objectNotSampled[OBJ3][Start], t.notSampled[OBJ3]), 0.3, TOLERANCE);
}

TEST_F(Sampler, BackwardSamplesSetObjectsOutOfPlayToTheirStart)
{
    const Tally t = run(false, 29);
    // obj1 has no goal and no vertex has moved it (not in play): goal roots leave it at its start
    EXPECT_EQ(t.objectNotSampled[OBJ1][Start], t.notSampled[OBJ1]);
}

TEST_F(Sampler, BackwardSamplesLeaveObjectsInPlayWithoutGoalUndefinedOrAtTheirStart)
{
    ob::State *moved = startCopy();
    setObject(space_, moved, OBJ1, 1.5, -2.0);
    const Tally t = run(false, 25, [&](ModalSampler &sampler) { sampler.noteVertex(moved); });
    // obj1's "goal value" choice leaves it undefined
    const auto &obj1 = t.objectNotSampled[OBJ1];
    EXPECT_EQ(obj1[Goal], 0);
    EXPECT_EQ(obj1[Fresh], 0);
    EXPECT_NEAR(rate(obj1[Undefined], t.notSampled[OBJ1]), 0.4 + 0.3, TOLERANCE);
    EXPECT_NEAR(rate(obj1[Start], t.notSampled[OBJ1]), 0.3, TOLERANCE);
}

TEST_F(Sampler, ObjectsComeIntoPlayWhenAVertexMovesThem)
{
    ModalSampler sampler(&space_, setup_.manipulationGoal().get(), start_, goalState_);
    EXPECT_TRUE(sampler.inPlay(OBJ3)) << "the goal constrains obj3";
    EXPECT_FALSE(sampler.inPlay(OBJ1));
    sampler.noteVertex(start_);
    EXPECT_FALSE(sampler.inPlay(OBJ1)) << "the start moves nothing";
    ob::State *moved = startCopy();
    setObject(space_, moved, OBJ1, 1.5, -2.0);
    sampler.noteVertex(moved);
    EXPECT_TRUE(sampler.inPlay(OBJ1));
    EXPECT_FALSE(sampler.inPlay(1)) << "obj2 has not moved";
}

TEST_F(Sampler, ObjectSamplesFocusOnObjectsInPlay)
{
    const Tally t = run(true, 27, [](ModalSampler &sampler) { sampler.probabilities().anyObject = 0.1; });
    // obj3 alone is in play: 0.9, and a quarter of the 0.1 among all objects
    EXPECT_NEAR(rate(t.freshObject[OBJ3], t.objectBranch), 0.9 + 0.1 / 4, TOLERANCE);
    EXPECT_NEAR(rate(t.freshObject[OBJ1], t.objectBranch), 0.1 / 4, TOLERANCE);
}

TEST_F(Sampler, SameSeedSameSamples)
{
    ModalSampler sampler(&space_, setup_.manipulationGoal().get(), start_, goalState_);
    ompl::RNG a, b;
    a.setLocalSeed(9);
    b.setLocalSeed(9);
    PartialState sa(&space_), sb(&space_);
    for (int k = 0; k < 200; ++k)
    {
        sampler.sample(sa, k % 2 == 0, a);
        sampler.sample(sb, k % 2 == 0, b);
        ASSERT_EQ(sa.robotDefined(), sb.robotDefined());
        if (sa.robotDefined())
        {
            EXPECT_EQ(space_.robotValues(sa.state())[0], space_.robotValues(sb.state())[0]);
        }
        for (unsigned int i = 0; i < 4; ++i)
        {
            ASSERT_EQ(sa.objectDefined(i), sb.objectDefined(i));
            if (sa.objectDefined(i))
            {
                EXPECT_FALSE(space_.objectMoves(sa.state(), sb.state(), i));
            }
        }
    }
}

TEST_F(SamplerNoRobotGoal, ForwardRobotIsNeverAGoalPoseWhenTheGoalLeavesItFree)
{
    const Tally t = run(true, 26);
    EXPECT_EQ(t.robotInRobotBranch[Goal], 0);
    EXPECT_EQ(t.robotInObjectBranch[Goal], 0);
    EXPECT_EQ(t.robotInRobotBranch[Undefined], 0);
    EXPECT_NEAR(rate(t.robotInObjectBranch[Undefined], t.objectBranch), 0.4 + 0.3, TOLERANCE);
}
