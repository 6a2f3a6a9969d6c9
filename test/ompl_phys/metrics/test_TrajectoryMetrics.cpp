// Tests for TrajectoryMetrics: action, power and smoothness against closed forms of analytic motions.
#include "ompl_phys/metrics/TrajectoryMetrics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

using namespace ompl_phys;

namespace
{
    constexpr double STEP = 0.07;  // s, the default propagation step
    constexpr double MASS = 1.0;   // kg
    const double PI = std::acos(-1.0);

    using Motion = std::function<Eigen::Vector3d(double)>;

    /** The trajectory of the given moves whose centre follows x(t), sampled every h seconds. */
    RobotTrajectory sample(double h, const std::vector<RobotMove> &moves, const Motion &x)
    {
        RobotTrajectory trajectory;
        trajectory.stepDuration = h;
        trajectory.moves = moves;
        std::size_t steps = 0;
        for (const RobotMove &move : moves)
            steps += move.steps;
        for (std::size_t k = 0; k <= steps; ++k)
            trajectory.positions.push_back(x(static_cast<double>(k) * h));
        return trajectory;
    }

    /** Moves with the same force and the given step counts. */
    std::vector<RobotMove> split(const Eigen::Vector3d &force, const std::vector<std::size_t> &steps)
    {
        std::vector<RobotMove> moves;
        for (std::size_t s : steps)
            moves.push_back({force, s});
        return moves;
    }

    /** Relative tolerance for quantities that should agree to round-off. */
    double near(double expected)
    {
        return 1e-12 * std::max(1.0, std::abs(expected));
    }

    /** The message of the std::invalid_argument thrown for trajectory ("" when none is thrown). */
    std::string rejection(const RobotTrajectory &trajectory)
    {
        try
        {
            computeTrajectoryMetrics(trajectory);
        }
        catch (const std::invalid_argument &e)
        {
            return e.what();
        }
        return "";
    }

    /** A valid trajectory to spoil: constant force along x from rest, 2 + 3 steps. */
    RobotTrajectory valid()
    {
        const Eigen::Vector3d force(2.0, 0.0, 0.0);
        return sample(STEP, split(force, {2, 3}),
                      [&](double t) -> Eigen::Vector3d { return force * t * t / (2.0 * MASS); });
    }

    // constant force F along a diagonal on a unit mass from rest: x(t) = F t² / (2m)
    const Eigen::Vector3d DIAGONAL_FORCE(1.2, 1.6, 0.0);  // |F| = 2 N
    Eigen::Vector3d fromRest(double t)
    {
        return DIAGONAL_FORCE * t * t / (2.0 * MASS);
    }
    /** Distance covered from rest after t seconds. */
    double fromRestDistance(double t)
    {
        return DIAGONAL_FORCE.norm() * t * t / (2.0 * MASS);
    }
}  // namespace

TEST(TrajectoryMetrics, ConstantForceOneMoveMatchesClosedForm)
{
    const std::size_t n = 30;
    const double duration = n * STEP;
    const double force = DIAGONAL_FORCE.norm();
    const TrajectoryMetrics m = computeTrajectoryMetrics(sample(STEP, split(DIAGONAL_FORCE, {n}), fromRest));

    // A = |F| T x(T), P = F · x(T) / T = |F|² T / (2m)
    const double action = force * duration * fromRestDistance(duration);
    const double power = force * force * duration / (2.0 * MASS);
    EXPECT_NEAR(m.action, action, near(action));
    EXPECT_NEAR(m.power, power, near(power));
}

TEST(TrajectoryMetrics, ActionAndPowerDependOnMoveSplit)
{
    // the same motion as one move of 30 steps, split into moves of 10, 5 and 15 steps
    const std::vector<std::size_t> steps{10, 5, 15};
    const double force = DIAGONAL_FORCE.norm();
    const TrajectoryMetrics whole =
        computeTrajectoryMetrics(sample(STEP, split(DIAGONAL_FORCE, {30}), fromRest));
    const TrajectoryMetrics parts =
        computeTrajectoryMetrics(sample(STEP, split(DIAGONAL_FORCE, steps), fromRest));

    // A = Σ |F| Δt_i (x(t_{i+1}) − x(t_i)), P = Σ |F| (x(t_{i+1}) − x(t_i)) / Δt_i = Σ |F|² (t_i + t_{i+1}) /
    // 2m
    double action = 0.0;
    double power = 0.0;
    double begin = 0.0;
    for (std::size_t s : steps)
    {
        const double end = begin + s * STEP;
        action += force * (end - begin) * (fromRestDistance(end) - fromRestDistance(begin));
        power += force * force * (begin + end) / (2.0 * MASS);
        begin = end;
    }
    EXPECT_NEAR(parts.action, action, near(action));
    EXPECT_NEAR(parts.power, power, near(power));

    // splitting shortens each Δt_i, so the same motion has less action; the summed power grows
    EXPECT_LT(parts.action, 0.5 * whole.action);
    EXPECT_GT(parts.power, 2.0 * whole.power);
    // the motion itself is unchanged
    EXPECT_DOUBLE_EQ(parts.smoothness, whole.smoothness);
}

TEST(TrajectoryMetrics, ActionUsesCoveredDistanceNotDisplacement)
{
    // braking force from v0: x(t) = v0 t − a t² / 2 stops at t* = v0 / a (a sample) and comes back
    const double force = 1.5;
    const double a = force / MASS;
    const double stop = 10 * STEP;
    const double v0 = a * stop;
    const double duration = 16 * STEP;
    const auto x = [&](double t) { return v0 * t - a * t * t / 2.0; };
    const TrajectoryMetrics m = computeTrajectoryMetrics(
        sample(STEP, split(Eigen::Vector3d(-force, 0.0, 0.0), {16}),
               [&](double t) -> Eigen::Vector3d { return Eigen::Vector3d(x(t), 0.0, 0.0); }));

    const double covered = x(stop) + (x(stop) - x(duration));
    const double action = force * duration * covered;
    const double power = -force * x(duration) / duration;
    EXPECT_NEAR(m.action, action, near(action));
    EXPECT_NEAR(m.power, power, near(power));
    EXPECT_GT(covered, x(duration));
}

TEST(TrajectoryMetrics, PowerOfOrthogonalForceIsZero)
{
    // the centre slides along x at constant speed while the force pushes along y
    const double speed = 0.3;
    const Eigen::Vector3d force(0.0, 4.0, 0.0);
    const TrajectoryMetrics m = computeTrajectoryMetrics(
        sample(STEP, split(force, {7, 4}),
               [&](double t) -> Eigen::Vector3d { return Eigen::Vector3d(speed * t, 0.0, 0.0); }));

    EXPECT_EQ(m.power, 0.0);
    // A = |F| (Δt_1 v Δt_1 + Δt_2 v Δt_2)
    const double action = 4.0 * speed * (std::pow(7 * STEP, 2) + std::pow(4 * STEP, 2));
    EXPECT_NEAR(m.action, action, near(action));
}

TEST(TrajectoryMetrics, PowerOfOpposingForceIsNegative)
{
    // braking from v0 to rest in T = v0 / a: displacement v0² / (2a) against the force
    const double force = 3.0;
    const double a = force / MASS;
    const double duration = 12 * STEP;
    const double v0 = a * duration;
    const TrajectoryMetrics m = computeTrajectoryMetrics(sample(
        STEP, split(Eigen::Vector3d(0.0, -force, 0.0), {12}),
        [&](double t) -> Eigen::Vector3d { return Eigen::Vector3d(0.0, v0 * t - a * t * t / 2.0, 0.0); }));

    const double power = -force * (v0 * v0 / (2.0 * a)) / duration;
    EXPECT_LT(m.power, 0.0);
    EXPECT_NEAR(m.power, power, near(power));
}

TEST(TrajectoryMetrics, SmoothnessOfConstantAccelerationIsZero)
{
    const TrajectoryMetrics m =
        computeTrajectoryMetrics(sample(STEP, split(DIAGONAL_FORCE, {10, 5, 15}), fromRest));
    EXPECT_NEAR(m.smoothness, 0.0, 1e-12);
}

TEST(TrajectoryMetrics, SmoothnessOfCubicIsJerkSquaredTimesDuration)
{
    // x(t) = c t³ + b t² + v t + x0 has constant jerk 6c, so S = 36 |c|² T
    const Eigen::Vector3d c(0.5, -0.25, 0.0);
    const Eigen::Vector3d b(0.1, 0.2, 0.0);
    const Eigen::Vector3d v(-0.3, 0.05, 0.0);
    const Eigen::Vector3d x0(1.0, -2.0, 0.1);
    const Motion cubic = [&](double t) -> Eigen::Vector3d { return c * t * t * t + b * t * t + v * t + x0; };

    for (std::size_t n : {3u, 4u, 25u, 40u})
    {
        const double duration = n * STEP;
        const TrajectoryMetrics m =
            computeTrajectoryMetrics(sample(STEP, split(Eigen::Vector3d::Zero(), {n}), cubic));
        const double expected = 36.0 * c.squaredNorm() * duration;
        EXPECT_NEAR(m.smoothness, expected, 1e-9 * expected) << n << " steps";
    }
}

TEST(TrajectoryMetrics, SmoothnessOfSinusoidConvergesAsStepShrinks)
{
    // x(t) = r sin(ωt): j = −r ω³ cos(ωt), S = r² ω⁶ (T/2 + sin(2ωT) / (4ω))
    // the differences are centred in [1.5h, T − 1.5h], so the error is first order in h
    const double r = 0.2;
    const double omega = 3.0;
    const double duration = 2.1;
    const double exact =
        r * r * std::pow(omega, 6) * (duration / 2.0 + std::sin(2.0 * omega * duration) / (4.0 * omega));
    const Motion wave = [&](double t) -> Eigen::Vector3d
    { return Eigen::Vector3d(r * std::sin(omega * t), 0.0, 0.0); };

    double previousError = std::numeric_limits<double>::infinity();
    for (std::size_t n : {30u, 60u, 120u, 240u})
    {
        const double h = duration / n;
        const double error = std::abs(
            computeTrajectoryMetrics(sample(h, split(Eigen::Vector3d::Zero(), {n}), wave)).smoothness -
            exact);
        EXPECT_LT(error, 0.6 * previousError) << n << " steps";
        previousError = error;
    }
    EXPECT_LT(previousError, 0.02 * exact);
}

TEST(TrajectoryMetrics, SmoothnessOfForceStepGrowsAsInverseStep)
{
    // at rest for T/3, then F from t0 = T/3: x(t) = F (t − t0)₊² / (2m). Two third differences
    // straddle the jump, each a jerk of F / (2m h), so S = (n / (n − 2)) · (F/m)² / (2h): the
    // discrete image of a Dirac impulse, infinite as h → 0.
    const double force = 2.0;
    const double duration = 42 * STEP;
    const double t0 = duration / 3.0;
    const Motion kick = [&](double t) -> Eigen::Vector3d
    {
        const double late = std::max(0.0, t - t0);
        return Eigen::Vector3d(force * late * late / (2.0 * MASS), 0.0, 0.0);
    };

    double previous = 0.0;
    for (std::size_t n : {42u, 84u, 168u})
    {
        const double h = duration / n;
        const std::vector<RobotMove> moves{{Eigen::Vector3d::Zero(), n / 3},
                                           {Eigen::Vector3d(force, 0, 0), 2 * n / 3}};
        const double s = computeTrajectoryMetrics(sample(h, moves, kick)).smoothness;
        const double a = force / MASS;
        const double expected = static_cast<double>(n) / (n - 2) * a * a / (2.0 * h);
        EXPECT_NEAR(s, expected, 1e-6 * expected) << n << " steps";
        if (previous > 0.0)
        {
            EXPECT_GT(s, 1.9 * previous) << "halving the step about doubles S";
        }
        previous = s;
    }
}

TEST(TrajectoryMetrics, FewerThanFourSamplesHaveNoSmoothness)
{
    // two steps of a cubic: jerk is not measurable, action and power still are
    const Motion cubic = [](double t) -> Eigen::Vector3d { return Eigen::Vector3d(t * t * t, 0.0, 0.0); };
    const TrajectoryMetrics m =
        computeTrajectoryMetrics(sample(STEP, split(Eigen::Vector3d(1.0, 0, 0), {2}), cubic));
    EXPECT_EQ(m.smoothness, 0.0);
    const double end = std::pow(2 * STEP, 3);
    EXPECT_NEAR(m.action, 2 * STEP * end, near(end));
    EXPECT_NEAR(m.power, end / (2 * STEP), near(end));
}

TEST(TrajectoryMetrics, StartAloneHasZeroMetrics)
{
    RobotTrajectory trajectory;
    trajectory.stepDuration = STEP;
    trajectory.positions.push_back(Eigen::Vector3d(1.0, 2.0, 0.1));
    const TrajectoryMetrics m = computeTrajectoryMetrics(trajectory);
    EXPECT_EQ(m.action, 0.0);
    EXPECT_EQ(m.power, 0.0);
    EXPECT_EQ(m.smoothness, 0.0);
}

TEST(TrajectoryMetrics, RejectsNonPositiveStepDuration)
{
    for (double h : {0.0, -STEP})
    {
        RobotTrajectory t = valid();
        t.stepDuration = h;
        EXPECT_NE(rejection(t).find("stepDuration"), std::string::npos) << h;
    }
}

TEST(TrajectoryMetrics, RejectsNonFiniteStepDuration)
{
    for (double h : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    {
        RobotTrajectory t = valid();
        t.stepDuration = h;
        EXPECT_NE(rejection(t).find("stepDuration"), std::string::npos) << h;
    }
}

TEST(TrajectoryMetrics, RejectsEmptyPositions)
{
    RobotTrajectory t = valid();
    t.positions.clear();
    EXPECT_NE(rejection(t).find("positions is empty"), std::string::npos);
}

TEST(TrajectoryMetrics, RejectsMoveWithoutSteps)
{
    RobotTrajectory t = valid();
    t.moves.insert(t.moves.begin() + 1, RobotMove{Eigen::Vector3d(1.0, 0.0, 0.0), 0});
    EXPECT_NE(rejection(t).find("moves[1].steps is 0"), std::string::npos);
}

TEST(TrajectoryMetrics, RejectsStepsThatDoNotAddUp)
{
    RobotTrajectory tooFew = valid();
    tooFew.moves.back().steps -= 1;
    EXPECT_NE(rejection(tooFew).find("add up to 4"), std::string::npos) << rejection(tooFew);

    RobotTrajectory tooMany = valid();
    tooMany.moves.back().steps += 1;
    EXPECT_NE(rejection(tooMany).find("moves[1].steps is 4"), std::string::npos) << rejection(tooMany);

    RobotTrajectory noMoves = valid();
    noMoves.moves.clear();
    EXPECT_NE(rejection(noMoves).find("add up to 0"), std::string::npos) << rejection(noMoves);
}

TEST(TrajectoryMetrics, RejectsNonFinitePosition)
{
    RobotTrajectory t = valid();
    t.positions[3].y() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_NE(rejection(t).find("positions[3]"), std::string::npos);
    t.positions[3].y() = -std::numeric_limits<double>::infinity();
    EXPECT_NE(rejection(t).find("positions[3]"), std::string::npos);
}

TEST(TrajectoryMetrics, RejectsNonFiniteForce)
{
    RobotTrajectory t = valid();
    t.moves[1].force.x() = std::numeric_limits<double>::infinity();
    EXPECT_NE(rejection(t).find("moves[1].force"), std::string::npos);
    t.moves[1].force.x() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_NE(rejection(t).find("moves[1].force"), std::string::npos);
}

TEST(TrajectoryMetrics, RejectionsNameTheValue)
{
    RobotTrajectory t = valid();
    t.stepDuration = -0.5;
    EXPECT_EQ(rejection(t),
              "computeTrajectoryMetrics: trajectory.stepDuration is -0.5, must be finite and > 0");
    t = valid();
    t.positions[2] = Eigen::Vector3d(1.5, std::numeric_limits<double>::infinity(), 0.25);
    EXPECT_EQ(rejection(t),
              "computeTrajectoryMetrics: trajectory.positions[2] is (1.5, inf, 0.25), must be finite");
    t = valid();
    t.moves[0].force = Eigen::Vector3d(std::numeric_limits<double>::quiet_NaN(), 2.0, 0.0);
    EXPECT_EQ(rejection(t),
              "computeTrajectoryMetrics: trajectory.moves[0].force is (nan, 2, 0), must be finite");
    t = valid();
    t.moves[0].steps = 6;
    EXPECT_EQ(rejection(t),
              "computeTrajectoryMetrics: trajectory.moves[0].steps is 6: the moves' steps exceed "
              "positions.size() - 1 = 5");
    t = valid();
    t.moves[1].steps = 2;
    EXPECT_EQ(rejection(t),
              "computeTrajectoryMetrics: the moves' steps add up to 4, but positions.size() - 1 is 5");
}

TEST(TrajectoryMetrics, AcceptsValuesJustInsideTheChecks)
{
    EXPECT_EQ(rejection(valid()), "");
    // the smallest positive step
    RobotTrajectory t = valid();
    t.stepDuration = std::numeric_limits<double>::denorm_min();
    EXPECT_EQ(rejection(t), "");
    // the largest finite positions and forces
    t = valid();
    t.positions[1].x() = std::numeric_limits<double>::max();
    t.moves[0].force.y() = -std::numeric_limits<double>::max();
    EXPECT_EQ(rejection(t), "");
    // moves of one step each, adding up exactly
    t = valid();
    t.moves = split(Eigen::Vector3d(2.0, 0.0, 0.0), {1, 1, 1, 1, 1});
    EXPECT_EQ(rejection(t), "");
}
