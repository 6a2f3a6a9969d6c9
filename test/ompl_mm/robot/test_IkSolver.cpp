// Tests for IkSolver on the KUKA LWR-like arm: full 6-D IK of 2,000 random reachable poses from the
// middle of the joint ranges (every answer within the limits and 1e-5 of its target, at least 99.9 %
// solved, bounded by iterations), the 5-D task with the yaw free (whatever the target's yaw) and the
// 3-D task, determinism, an unreachable target leaving the joints as they were, restarts that give up
// when stuck, solves from the seed alone (NearSeed), and the declared parameters.
#include "ompl_mm/robot/IkSolver.h"

#include "common/InputErrors.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace ompl_mm;

namespace
{
    const std::string KUKA = std::string(OMPL_MM_SCENES_DIR) + "/robots/kuka_lwr.urdf";

    class LwrIk : public ::testing::Test
    {
    protected:
        LwrIk()
            : robot_(RobotModel::fromUrdfFile(KUKA)),
              solver_(KinematicChain(robot_, robot_.linkIndex("tool")), base_)
        {
        }

        const KinematicChain &chain() const { return solver_.chain(); }

        std::vector<double> middle() const
        {
            std::vector<double> q(robot_.dof());
            for (unsigned int i = 0; i < chain().size(); ++i)
                q[chain().variable(i)] = 0.5 * (chain().lower(i) + chain().upper(i));
            return q;
        }

        std::vector<double> random(ompl::RNG &rng) const
        {
            std::vector<double> q(robot_.dof());
            for (unsigned int i = 0; i < chain().size(); ++i)
                q[chain().variable(i)] = rng.uniformReal(chain().lower(i), chain().upper(i));
            return q;
        }

        bool withinLimits(const std::vector<double> &q) const
        {
            for (unsigned int i = 0; i < chain().size(); ++i)
                if (q[chain().variable(i)] < chain().lower(i) || q[chain().variable(i)] > chain().upper(i))
                    return false;
            return true;
        }

        RobotModel robot_;
        Eigen::Isometry3d base_{Eigen::Translation3d(0.1, -0.2, 0.3)};
        IkSolver solver_;
    };
}  // namespace

TEST_F(LwrIk, SolvesRandomReachablePosesWithinLimitsAndTolerance)
{
    ompl::RNG poses(11), restarts(12);
    unsigned int solved = 0;
    const unsigned int count = 2000;
    for (unsigned int k = 0; k < count; ++k)
    {
        const Eigen::Isometry3d target = chain().toolPose(random(poses).data(), base_);
        std::vector<double> q = middle();
        if (!solver_.solve(target, IkTask::Pose6D, q.data(), restarts))
            continue;
        ++solved;
        EXPECT_TRUE(withinLimits(q)) << "query " << k;
        const Eigen::Isometry3d reached = chain().toolPose(q.data(), base_);
        const Eigen::AngleAxisd turn(target.linear() * reached.linear().transpose());
        EXPECT_LT(std::hypot((target.translation() - reached.translation()).norm(), turn.angle()), 1e-5)
            << "query " << k;
    }
    EXPECT_GE(solved, 1998u) << "at least 99.9 % of " << count;
}

TEST_F(LwrIk, FiveDimensionalTaskLeavesOnlyTheYawAboutTheVerticalFree)
{
    ompl::RNG poses(21), restarts(22);
    for (int k = 0; k < 100; ++k)
    {
        const Eigen::Isometry3d reachable = chain().toolPose(random(poses).data(), base_);
        // the same pose turned about the world vertical through the tool point: reachable or not,
        // the 5-D task accepts any yaw, so the reachable one is a solution
        const Eigen::Isometry3d target = Eigen::Translation3d(reachable.translation()) *
                                         Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitZ()) *
                                         Eigen::Translation3d(-reachable.translation()) * reachable;
        std::vector<double> q = middle();
        ASSERT_TRUE(solver_.solve(target, IkTask::Pose5DFreeYaw, q.data(), restarts)) << "query " << k;
        const Eigen::Isometry3d reached = chain().toolPose(q.data(), base_);
        EXPECT_LT((reached.translation() - target.translation()).norm(), 1e-5);
        // the tool's axes differ from the target's by a turn about the world vertical only
        const Eigen::Matrix3d residual = target.linear() * reached.linear().transpose();
        EXPECT_NEAR(residual(2, 2), 1.0, 1e-9);
        EXPECT_LT(solver_.error(target, IkTask::Pose5DFreeYaw, q.data()), 1e-5);
    }
}

TEST_F(LwrIk, FiveDimensionalTaskWithAnyYawConvergesWhateverTheTargetsYaw)
{
    // targets whose yaw lies far (2.5 to 3.1 rad) from a solution's, solved from near that
    // solution alone: with anyYaw the yaw the task leaves free must not pull the solver away
    solver_.anyYaw = true;
    ompl::RNG poses(23), restarts(24);
    unsigned int solved = 0;
    const unsigned int count = 100;
    for (unsigned int k = 0; k < count; ++k)
    {
        const std::vector<double> solution = random(poses);
        const Eigen::Isometry3d reachable = chain().toolPose(solution.data(), base_);
        const Eigen::Isometry3d target =
            Eigen::Translation3d(reachable.translation()) *
            Eigen::AngleAxisd(poses.uniformReal(2.5, 3.1), Eigen::Vector3d::UnitZ()) *
            Eigen::Translation3d(-reachable.translation()) * reachable;
        std::vector<double> q = solution;
        for (unsigned int i = 0; i < chain().size(); ++i)
            q[chain().variable(i)] = std::clamp(q[chain().variable(i)] + poses.uniformReal(-0.1, 0.1),
                                                chain().lower(i), chain().upper(i));
        if (solver_.solve(target, IkTask::Pose5DFreeYaw, q.data(), restarts, IkScope::NearSeed))
            ++solved;
    }
    // 91 of these 100 converge (3 without anyYaw, whose error keeps the target's own yaw)
    EXPECT_GE(solved, 85u) << "of " << count;
}

TEST_F(LwrIk, PositionTaskReachesThePointWhateverTheOrientation)
{
    ompl::RNG restarts(31);
    const Eigen::Isometry3d target(Eigen::Translation3d(0.6, -0.1, 0.5) *
                                   Eigen::AngleAxisd(2.0, Eigen::Vector3d::UnitX()));
    std::vector<double> q = middle();
    ASSERT_TRUE(solver_.solve(target, IkTask::Position3D, q.data(), restarts));
    EXPECT_LT((chain().toolPose(q.data(), base_).translation() - target.translation()).norm(), 1e-5);
    EXPECT_GT(solver_.error(target, IkTask::Pose6D, q.data()), 0.1) << "the orientation was free";
}

TEST_F(LwrIk, SameRandomGeneratorStateGivesTheSameSolution)
{
    ompl::RNG poses(41);
    const Eigen::Isometry3d target = chain().toolPose(random(poses).data(), base_);
    std::vector<double> first = middle(), second = middle();
    ompl::RNG a(7), b(7);
    ASSERT_TRUE(solver_.solve(target, IkTask::Pose6D, first.data(), a));
    ASSERT_TRUE(solver_.solve(target, IkTask::Pose6D, second.data(), b));
    EXPECT_EQ(first, second);
}

TEST_F(LwrIk, UnreachableTargetFailsAndLeavesTheJoints)
{
    ompl::RNG restarts(51);
    solver_.restarts = 20;
    const Eigen::Isometry3d far(Eigen::Translation3d(3.0, 0.0, 0.5));
    std::vector<double> q = middle();
    const std::vector<double> before = q;
    EXPECT_FALSE(solver_.solve(far, IkTask::Position3D, q.data(), restarts));
    EXPECT_EQ(q, before);
    // every attempt, the one from the seed too, gives up once stuck
    const unsigned int stuckAfter = solver_.stallIterations + 1;
    EXPECT_GE(solver_.lastIterations(), 21u * stuckAfter);
    EXPECT_LT(solver_.lastIterations(), 21u * 2u * stuckAfter);
    // the attempt from the seed alone (NearSeed) gives up long before its iterations run out
    const unsigned int iterations = solver_.iterations;
    solver_.iterations = 200;
    EXPECT_FALSE(solver_.solve(far, IkTask::Position3D, q.data(), restarts, IkScope::NearSeed));
    EXPECT_LT(solver_.lastIterations(), 2u * stuckAfter);
    solver_.iterations = iterations;
    solver_.stallIterations = 0;
    EXPECT_FALSE(solver_.solve(far, IkTask::Position3D, q.data(), restarts));
    EXPECT_EQ(solver_.lastIterations(), 21u * solver_.iterations) << "every attempt ran out";
}

TEST_F(LwrIk, StuckRestartsGiveUpButFewThatWouldConverge)
{
    // random reachable poses from random seeds, with and without giving up when stuck: as many
    // solved, in fewer iterations
    ompl::RNG poses(53);
    unsigned int solved[2] = {0, 0};
    unsigned long iterations[2] = {0, 0};
    for (int k = 0; k < 300; ++k)
    {
        const std::vector<double> answer = random(poses);
        const Eigen::Isometry3d target = chain().toolPose(answer.data(), base_);
        const std::vector<double> seed = random(poses);
        for (const unsigned int stall : {0u, 8u})
        {
            const int lane = stall == 0 ? 0 : 1;
            solver_.stallIterations = stall;
            solver_.restarts = 5;
            ompl::RNG restarts(1000 + k);
            std::vector<double> q = seed;
            solved[lane] += solver_.solve(target, IkTask::Pose6D, q.data(), restarts) ? 1 : 0;
            iterations[lane] += solver_.lastIterations();
        }
    }
    EXPECT_GE(solved[1] + 3, solved[0]);
    EXPECT_LT(iterations[1], iterations[0]);
}

TEST_F(LwrIk, NearSeedSolvesFromTheSeedAloneWithoutRestarts)
{
    ompl::RNG rng(52);
    solver_.restarts = 20;
    solver_.stallIterations = 0;  // an attempt runs all its iterations
    const Eigen::Isometry3d far(Eigen::Translation3d(3.0, 0.0, 0.5));
    std::vector<double> q = middle();
    EXPECT_FALSE(solver_.solve(far, IkTask::Position3D, q.data(), rng, IkScope::NearSeed));
    EXPECT_EQ(solver_.lastIterations(), solver_.iterations) << "one attempt, from the seed";
    // a target near the seed is found from it, close to it
    std::vector<double> seed = middle();
    seed[chain().variable(1)] += 0.3;
    const Eigen::Isometry3d near = chain().toolPose(seed.data(), base_);
    seed[chain().variable(3)] += 0.05;  // start a little off the answer
    std::vector<double> found = seed;
    ASSERT_TRUE(solver_.solve(near, IkTask::Pose6D, found.data(), rng, IkScope::NearSeed));
    EXPECT_LE(solver_.error(near, IkTask::Pose6D, found.data()), solver_.tolerance);
    EXPECT_LE(solver_.lastIterations(), solver_.iterations);
}

TEST_F(LwrIk, ParametersAreDeclaredWithRanges)
{
    ompl::base::ParamSet &params = solver_.params();
    EXPECT_TRUE(params.setParam("ik_tolerance", "0.0001"));
    EXPECT_EQ(solver_.tolerance, 1e-4);
    EXPECT_TRUE(params.setParam("ik_iterations", "40"));
    EXPECT_EQ(solver_.iterations, 40u);
    EXPECT_TRUE(params.setParam("ik_restarts", "3"));
    EXPECT_EQ(solver_.restarts, 3u);
    EXPECT_TRUE(params.setParam("ik_damping", "0.05"));
    EXPECT_EQ(solver_.damping, 0.05);
    EXPECT_TRUE(params.setParam("ik_time_limit", "0.002"));
    EXPECT_EQ(solver_.timeLimit, 0.002);
    EXPECT_FALSE(solver_.anyYaw);
    EXPECT_TRUE(params.setParam("ik_any_yaw", "1"));
    EXPECT_TRUE(solver_.anyYaw);
    EXPECT_TRUE(params.setParam("ik_stall_iterations", "12"));
    EXPECT_EQ(solver_.stallIterations, 12u);
    for (const char *name : {"ik_tolerance", "ik_iterations", "ik_restarts", "ik_damping", "ik_time_limit",
                             "ik_any_yaw", "ik_stall_iterations"})
        EXPECT_FALSE(params.getParam(name)->getRangeSuggestion().empty()) << name;
}
