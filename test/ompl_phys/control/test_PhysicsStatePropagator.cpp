// Tests for PhysicsStatePropagator: the manipulation knowledge enforced while simulating (fixed bodies,
// push strips and axes, free bodies, regions, speeds), at every sub-step, and bit-identical repetition.
#include "ompl_phys/control/PhysicsStatePropagator.h"

#include "ompl_phys/base/PhysicsValidityChecker.h"
#include "ompl_phys/common/PhysicsTestSupport.h"
#include "ompl_phys/control/PhysicsSetup.h"

#include <ompl/base/ScopedState.h>
#include <ompl/control/spaces/RealVectorControlSpace.h>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

using namespace ompl_phys;
using namespace ompl_phys::test;

namespace
{
    const double PI = std::acos(-1.0);

    /** The result of simulating from a state. */
    struct Outcome
    {
        BodyStates states;
        Violation violation{Violation::None};
        bool valid{false};  ///< what the setup's validity checker says of the result
    };

    /** A PhysicsSetup of a scene (the small scene unless given), with helpers to write states and
        propagate them under a constant force. */
    class Propagation : public ::testing::Test
    {
    protected:
        explicit Propagation(const PhysicsScene &scene = smallScene())
            : setup_(scene), si_(setup_.getSpaceInformation()), space_(setup_.physicsSpace())
        {
        }

        const PhysicsScene &scene() const { return setup_.scene(); }

        /** The start with the robot at (x, y) on the floor moving with velocity (vx, vy). */
        BodyStates robotAt(double x, double y, double vx = 0.0, double vy = 0.0) const
        {
            BodyStates states = setup_.world().startStates();
            states[0].position = Eigen::Vector3d(x, y, scene().robot.radius);
            states[0].linearVelocity = Eigen::Vector3d(vx, vy, 0.0);
            return states;
        }

        /** Simulates states under force for `steps` propagation steps with one propagate() call. */
        Outcome propagate(const BodyStates &states, const Eigen::Vector2d &force, unsigned int steps)
        {
            ompl::base::ScopedState<> from(si_->getStateSpace());
            ompl::base::ScopedState<> to(si_->getStateSpace());
            space_.writeState(states, from.get());
            const auto control = makeControl(force);
            setup_.getStatePropagator()->propagate(from.get(), control.get(),
                                                   steps * si_->getPropagationStepSize(), to.get());
            return outcome(to.get());
        }

        /** Reads a state with its violation and validity. */
        Outcome outcome(const ompl::base::State *state) const
        {
            Outcome result;
            space_.readState(state, result.states);
            result.violation = state->as<PhysicsStateSpace::StateType>()->violation;
            result.valid = si_->isValid(state);
            return result;
        }

        std::shared_ptr<ompl::control::Control> makeControl(const Eigen::Vector2d &force) const
        {
            ompl::control::Control *control = si_->allocControl();
            double *values = control->as<ompl::control::RealVectorControlSpace::ControlType>()->values;
            values[0] = force.x();
            values[1] = force.y();
            const ompl::control::SpaceInformationPtr si = si_;
            return {control, [si](ompl::control::Control *c) { si->freeControl(c); }};
        }

        /** Moving index of the scene body with this name. */
        std::size_t moving(const std::string &name) const
        {
            for (std::size_t i = 1; i < setup_.world().movingBodyCount(); ++i)
                if (setup_.world().movingBodyName(i) == name)
                    return i;
            ADD_FAILURE() << "no moving body " << name;
            return 0;
        }

        PhysicsSetup setup_;
        const ompl::control::SpaceInformationPtr si_;
        const PhysicsStateSpace &space_;
    };

    /** The same on benchmark scene 1. */
    class SceneOnePropagation : public Propagation
    {
    protected:
        SceneOnePropagation() : Propagation(benchmarkScene(1)) {}
    };
}  // namespace

// --- fixed bodies -------------------------------------------------------------------------------------

TEST_F(Propagation, DrivingIntoAFixedWallIsRejected)
{
    // the wall spans y in [0.7, 0.9]; the robot coasts north at 0.4 m/s from y = 0.5 (no force, no
    // friction: y(t) = 0.5 + 0.4 t) and touches the wall once y >= 0.7 - 0.08 = 0.62
    const Outcome hit = propagate(robotAt(0.0, 0.5, 0.0, 0.4), Eigen::Vector2d::Zero(), 10);
    EXPECT_EQ(hit.violation, Violation::TouchedFixedBody);
    EXPECT_FALSE(hit.valid);

    // the validity checker reports the stored violation
    ompl::base::ScopedState<> state(si_->getStateSpace());
    space_.writeState(hit.states, state.get());
    state->as<PhysicsStateSpace::StateType>()->violation = hit.violation;
    const auto checker = std::dynamic_pointer_cast<PhysicsValidityChecker>(si_->getStateValidityChecker());
    ASSERT_TRUE(checker);
    EXPECT_EQ(checker->violation(state.get()), Violation::TouchedFixedBody);
    EXPECT_FALSE(checker->isValid(state.get()));
}

TEST_F(Propagation, PropagateWhileValidStopsBeforeTheWall)
{
    // as above: contact at t = 0.3 s, inside the 5th step (0.28 s to 0.35 s), so exactly 4 whole steps
    // are free of contact
    const double step = si_->getPropagationStepSize();
    const unsigned int freeSteps = static_cast<unsigned int>(std::floor((0.62 - 0.5) / (0.4 * step)));
    ASSERT_EQ(freeSteps, 4u);
    ompl::base::ScopedState<> from(si_->getStateSpace());
    ompl::base::ScopedState<> to(si_->getStateSpace());
    space_.writeState(robotAt(0.0, 0.5, 0.0, 0.4), from.get());
    const auto control = makeControl(Eigen::Vector2d::Zero());
    const unsigned int steps = si_->propagateWhileValid(from.get(), control.get(), 10, to.get());
    EXPECT_EQ(steps, freeSteps);
    const Outcome last = outcome(to.get());
    EXPECT_TRUE(last.valid);
    EXPECT_EQ(last.violation, Violation::None);
    EXPECT_NEAR(last.states[0].position.y(), 0.5 + 0.4 * freeSteps * step, 1e-9);
    EXPECT_GE(distanceToStartFootprint(scene(), scene().bodyIndex("wall"), last.states[0].position.head<2>()),
              scene().robot.radius);
}

TEST_F(Propagation, EverySubStepIsChecked)
{
    // The robot passes the wall's south-east corner c = (0.5, 0.7) diagonally (north-east at 0.35 m/s per
    // axis, 0.495 m/s) within one 0.07 s step: its path c + d (1, -1)/sqrt2 + s (1, 1)/sqrt2 comes within
    // d of the corner at s = 0 and ends at s = +-0.0173 m, sqrt(d^2 + s^2) from it. With d = 0.0788 both
    // ends are clear of the robot's radius 0.08, but the sub-step poses near s = +-0.0025 overlap the
    // corner.
    const double r = scene().robot.radius;
    const double v = 0.35;
    const double step = si_->getPropagationStepSize();
    const Eigen::Vector2d corner(0.5, 0.7);
    const Eigen::Vector2d normal = Eigen::Vector2d(1.0, -1.0).normalized();
    const Eigen::Vector2d along = Eigen::Vector2d(1.0, 1.0).normalized();
    const double half = 0.5 * std::sqrt(2.0) * v * step;  // half the distance covered in one step
    const std::size_t wall = scene().bodyIndex("wall");
    auto pass = [&](double d)
    {
        const Eigen::Vector2d from = corner + d * normal - half * along;
        return std::make_pair(from, propagate(robotAt(from.x(), from.y(), v, v), Eigen::Vector2d::Zero(), 1));
    };

    const double grazing = 0.0788;
    const auto [from, grazed] = pass(grazing);
    const Eigen::Vector2d to = corner + grazing * normal + half * along;
    // both ends are clear, so a check of the final state alone would accept this step
    ASSERT_GT(distanceToStartFootprint(scene(), wall, from), r);
    ASSERT_GT(distanceToStartFootprint(scene(), wall, to), r);
    ASSERT_LT(distanceToStartFootprint(scene(), wall, corner + grazing * normal), r);
    BodyStates straight = robotAt(to.x(), to.y(), v, v);
    ManipulationKnowledge knowledge(shared(scene()));
    ASSERT_EQ(knowledge.checkStates(straight), Violation::None);
    EXPECT_EQ(grazed.violation, Violation::TouchedFixedBody);
    EXPECT_FALSE(grazed.valid);

    // the same pass 1.5 mm further out never touches: valid, and it ends where it was going
    const auto [farFrom, clear] = pass(0.0815);
    EXPECT_EQ(clear.violation, Violation::None);
    EXPECT_TRUE(clear.valid);
    const Eigen::Vector2d farTo = farFrom + 2.0 * half * along;
    EXPECT_NEAR((clear.states[0].position.head<2>() - farTo).norm(), 0.0, 1e-9);
}

// --- constraint-oriented bodies ------------------------------------------------------------------------

TEST_F(Propagation, PushingTheConstrainedCubeAlongItsAxisFromItsStrip)
{
    // slider: 0.2 m cube at the origin, push axis = world y, strip |x| <= 0.06. The robot starts 2 mm
    // south of it, within the strip, and pushes north with 4 N: more than the cube's floor friction,
    // 0.7 * 0.5 kg * 9.81 = 3.4 N, so both speed up by about (4 - 3.4) / 1.5 = 0.4 m/s^2 and stay below the
    // speed limit (0.5 m/s) for the 0.42 s of the push
    const std::size_t slider = moving("slider");
    const PushConstraint &push = scene().bodies[scene().bodyIndex("slider")].push;
    for (double x : {0.0, 0.03})
    {
        SCOPED_TRACE("robot x " + std::to_string(x));
        const Outcome pushed =
            propagate(robotAt(x, -0.1 - 0.08 - 0.002, 0.0, 0.1), Eigen::Vector2d(0.0, 4.0), 6);
        EXPECT_EQ(pushed.violation, Violation::None) << violationName(pushed.violation);
        EXPECT_TRUE(pushed.valid);
        const BodyState &cube = pushed.states[slider];
        EXPECT_GT(cube.position.y(), 0.01) << "the cube did not move along its axis";
        EXPECT_LE(std::abs(cube.position.x()), push.lateralTolerance);
        EXPECT_LE(cube.orientation.angularDistance(setup_.world().startStates()[slider].orientation),
                  push.angleTolerance);
        // the robot followed it
        EXPECT_GT(pushed.states[0].position.y(), -0.18 + 0.01);
    }
}

TEST_F(Propagation, TouchingTheConstrainedCubeOutsideItsStrip)
{
    // from the side (west, moving east) and on its pushable face but outside the strip (|x| = 0.08)
    const Outcome side = propagate(robotAt(-0.1 - 0.08 - 0.002, 0.0, 0.2, 0.0), Eigen::Vector2d(2.0, 0.0), 3);
    EXPECT_EQ(side.violation, Violation::TouchedOutsideRegion) << violationName(side.violation);
    EXPECT_FALSE(side.valid);
    const Outcome offStrip =
        propagate(robotAt(0.08, -0.1 - 0.08 - 0.002, 0.0, 0.2), Eigen::Vector2d(0.0, 2.0), 3);
    EXPECT_EQ(offStrip.violation, Violation::TouchedOutsideRegion) << violationName(offStrip.violation);
    EXPECT_FALSE(offStrip.valid);
}

TEST_F(Propagation, ConstrainedCubeLeavingItsAxis)
{
    // the slider slides sideways at 1 m/s with the robot far away; floor friction decelerates it by
    // 0.7 g = 6.9 m/s^2, so it would slide 1 / (2 * 6.9) = 0.073 m, beyond the lateral tolerance 0.03 m
    const std::size_t slider = moving("slider");
    BodyStates states = setup_.world().startStates();
    states[slider].linearVelocity = Eigen::Vector3d(1.0, 0.0, 0.0);
    const Outcome sideways = propagate(states, Eigen::Vector2d::Zero(), 5);
    EXPECT_EQ(sideways.violation, Violation::LeftPushAxis) << violationName(sideways.violation);
    EXPECT_FALSE(sideways.valid);
    // the same speed along its axis is fine
    states[slider].linearVelocity = Eigen::Vector3d(0.0, 1.0, 0.0);
    const Outcome along = propagate(states, Eigen::Vector2d::Zero(), 5);
    EXPECT_EQ(along.violation, Violation::None) << violationName(along.violation);
    EXPECT_GT(along.states[slider].position.y(), 0.03);
    EXPECT_LE(std::abs(along.states[slider].position.x()), 1e-3);
}

// --- free bodies --------------------------------------------------------------------------------------

TEST_F(Propagation, FreeCubeMayBePushedFromAnySide)
{
    // loose: 0.2 m cube at (0.6, -0.4); the robot starts 2 mm off a face (or a corner) and pushes towards
    // the cube's centre with 4 N
    const std::size_t loose = moving("loose");
    const Eigen::Vector2d centre = setup_.world().startStates()[loose].position.head<2>();
    for (int k = 0; k < 8; ++k)
    {
        const double angle = k * PI / 4.0;
        const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
        // distance from the centre to the cube's outline along direction, plus radius and 2 mm
        const double reach = 0.1 / std::max(std::abs(direction.x()), std::abs(direction.y())) + 0.08 + 0.002;
        const Eigen::Vector2d robot = centre + reach * direction;
        const Eigen::Vector2d force = -4.0 * direction;
        SCOPED_TRACE("from angle " + std::to_string(angle));
        const Outcome pushed =
            propagate(robotAt(robot.x(), robot.y(), -0.1 * direction.x(), -0.1 * direction.y()), force, 5);
        EXPECT_EQ(pushed.violation, Violation::None) << violationName(pushed.violation);
        EXPECT_TRUE(pushed.valid);
        const Eigen::Vector2d moved = pushed.states[loose].position.head<2>() - centre;
        EXPECT_GT(moved.dot(-direction), 0.005) << "the cube was not pushed";
    }
}

TEST_F(Propagation, ABodySinkingIntoTheFloorOrAWallIsRejected)
{
    // the free cube 1 cm into the floor, then 1 cm into the wall (y from 0.7 to 0.9): deeper than the
    // sink tolerance, found by the first sub-step's collision check
    const std::size_t loose = moving("loose");
    BodyStates sunk = robotAt(-0.8, -0.8);
    sunk[loose].position.z() -= 0.01;
    const Outcome floor = propagate(sunk, Eigen::Vector2d::Zero(), 1);
    EXPECT_EQ(floor.violation, Violation::SankIn) << violationName(floor.violation);
    EXPECT_FALSE(floor.valid);
    BodyStates inWall = robotAt(-0.8, -0.8);
    inWall[loose].position = Eigen::Vector3d(-0.2, 0.7 - 0.1 + 0.01, 0.1);
    EXPECT_EQ(propagate(inWall, Eigen::Vector2d::Zero(), 1).violation, Violation::SankIn);
    // resting on the floor and 2 mm from the wall, it stays valid
    inWall[loose].position.y() = 0.7 - 0.1 - 0.002;
    EXPECT_EQ(propagate(inWall, Eigen::Vector2d::Zero(), 1).violation, Violation::None);
}

// --- regions and speeds -------------------------------------------------------------------------------

TEST_F(Propagation, RobotLeavingItsRegion)
{
    // the robot region ends at x = 1; from x = 0.95 at 0.4 m/s the robot crosses it after 0.125 s
    const Outcome out = propagate(robotAt(0.95, 0.0, 0.4, 0.0), Eigen::Vector2d::Zero(), 3);
    EXPECT_EQ(out.violation, Violation::OutsideRegion) << violationName(out.violation);
    EXPECT_FALSE(out.valid);
    // stopped at the first sub-step beyond the edge (sub-steps of 0.01 s move it 4 mm)
    EXPECT_GT(out.states[0].position.x(), 1.0);
    EXPECT_LT(out.states[0].position.x(), 1.0 + 0.004 + 1e-9);
    // one step (0.028 m) stays inside
    const Outcome in = propagate(robotAt(0.95, 0.0, 0.4, 0.0), Eigen::Vector2d::Zero(), 1);
    EXPECT_EQ(in.violation, Violation::None);
}

TEST_F(Propagation, TheDriveHoldsTheSpeedLimit)
{
    // at 0.45 m/s, 10 N on 1 kg would add 0.1 m/s in the first 0.01 s sub-step: beyond 0.5 m/s. The
    // drive applies only what keeps the speed at 0.99 of the limit, so the robot cruises there.
    const double limit = scene().limits.maxRobotSpeed;
    const Outcome held = propagate(robotAt(-0.5, -0.5, 0.45, 0.0), Eigen::Vector2d(10.0, 0.0), 3);
    EXPECT_EQ(held.violation, Violation::None) << violationName(held.violation);
    EXPECT_TRUE(held.valid);
    EXPECT_NEAR(held.states[0].linearVelocity.head<2>().norm(), SpeedGovernor::SPEED_MARGIN * limit, 1e-9);
    // the full force from rest along the diagonal: within the limit at every step
    BodyStates states = robotAt(-0.7, -0.7);
    for (int step = 0; step < 10; ++step)
    {
        const Outcome next = propagate(states, Eigen::Vector2d(10.0, 10.0), 1);
        ASSERT_EQ(next.violation, Violation::None) << step;
        EXPECT_LE(next.states[0].linearVelocity.head<2>().norm(), limit) << step;
        states = next.states;
    }
    EXPECT_NEAR(states[0].linearVelocity.x(), states[0].linearVelocity.y(), 1e-9) << "the direction is kept";
}

TEST_F(Propagation, RobotTooFast)
{
    // a robot a little over the limit (after a bounce, say) is braked back below it by the drive
    const double limit = scene().limits.maxRobotSpeed;
    const Outcome braked = propagate(robotAt(-0.5, -0.5, 0.42, 0.3), Eigen::Vector2d::Zero(), 1);
    EXPECT_EQ(braked.violation, Violation::None) << violationName(braked.violation);
    EXPECT_LE(braked.states[0].linearVelocity.head<2>().norm(), limit);
    // one far over it cannot be braked within a sub-step (10 N take 0.1 m/s off): it breaks the limit
    const Outcome fast = propagate(robotAt(-0.5, -0.5, 1.0, 0.0), Eigen::Vector2d::Zero(), 1);
    EXPECT_EQ(fast.violation, Violation::TooFast) << violationName(fast.violation);
    EXPECT_FALSE(fast.valid);
    EXPECT_NEAR(fast.states[0].linearVelocity.x(), 0.9, 1e-9);
    // coasting just below the limit is fine
    const Outcome coasting = propagate(robotAt(-0.5, -0.5, 0.35, -0.35), Eigen::Vector2d::Zero(), 3);
    EXPECT_EQ(coasting.violation, Violation::None);
}

TEST_F(Propagation, BrokenStateStaysBroken)
{
    ompl::base::ScopedState<> from(si_->getStateSpace());
    ompl::base::ScopedState<> to(si_->getStateSpace());
    space_.writeState(robotAt(0.0, -0.5), from.get());
    from->as<PhysicsStateSpace::StateType>()->violation = Violation::TooFast;
    const auto control = makeControl(Eigen::Vector2d(1.0, 0.0));
    setup_.getStatePropagator()->propagate(from.get(), control.get(), si_->getPropagationStepSize(),
                                           to.get());
    EXPECT_EQ(to->as<PhysicsStateSpace::StateType>()->violation, Violation::TooFast);
    EXPECT_TRUE(si_->equalStates(from.get(), to.get()));
}

TEST_F(Propagation, CountersCountPropagationsSubStepsAndStops)
{
    const PhysicsStatePropagator::Counters before = setup_.propagator().counters();
    propagate(robotAt(-0.5, -0.5), Eigen::Vector2d(1.0, 0.0), 3);          // 3 x 7 sub-steps
    propagate(robotAt(-0.5, -0.5, 1.0, 0.0), Eigen::Vector2d::Zero(), 1);  // stops after 1
    const PhysicsStatePropagator::Counters &after = setup_.propagator().counters();
    EXPECT_EQ(after.propagations - before.propagations, 2u);
    EXPECT_EQ(after.substeps - before.substeps, 3u * scene().contact.substeps + 1u);
    const auto tooFast = static_cast<std::size_t>(Violation::TooFast);
    EXPECT_EQ(after.stops[tooFast] - before.stops[tooFast], 1u);
    EXPECT_EQ(after.stops[0], before.stops[0]);
}

// --- determinism --------------------------------------------------------------------------------------

TEST_F(SceneOnePropagation, SameStateAndControlGiveBitIdenticalResults)
{
    // robot pushing cube1 (contacts with the cube and the floor), and coasting alone
    const std::size_t cube1 = moving("cube1");
    const Eigen::Vector3d cube = setup_.world().startStates()[cube1].position;
    const BodyStates pushing = robotAt(cube.x() - 0.1 - 0.08 - 0.002, cube.y() + 0.03, 0.1, 0.0);
    const BodyStates coasting = robotAt(-0.84, 0.97, 0.2, -0.1);
    const Eigen::Vector2d force(4.0, -0.3);

    const Outcome first = propagate(pushing, force, 6);
    ASSERT_EQ(first.violation, Violation::None) << violationName(first.violation);
    ASSERT_GT(first.states[cube1].position.x() - cube.x(), 0.005) << "the cube was not pushed";
    const Outcome firstCoast = propagate(coasting, Eigen::Vector2d(-3.0, 2.0), 4);

    // other propagations in between, then the same ones again
    propagate(robotAt(0.5, 1.0, -0.3, 0.0), Eigen::Vector2d(-2.0, 1.0), 5);
    propagate(pushing, Eigen::Vector2d(3.0, 3.0), 2);
    const Outcome second = propagate(pushing, force, 6);
    const Outcome secondCoast = propagate(coasting, Eigen::Vector2d(-3.0, 2.0), 4);
    EXPECT_TRUE(sameBits(first.states, second.states));
    EXPECT_EQ(first.violation, second.violation);
    EXPECT_TRUE(sameBits(firstCoast.states, secondCoast.states));

    // the same through a second setup of the same scene
    PhysicsSetup other(benchmarkScene(1));
    ompl::base::ScopedState<> from(other.getStateSpace());
    ompl::base::ScopedState<> to(other.getStateSpace());
    other.physicsSpace().writeState(pushing, from.get());
    other.getStatePropagator()->propagate(from.get(), makeControl(force).get(),
                                          6 * si_->getPropagationStepSize(), to.get());
    BodyStates third;
    other.physicsSpace().readState(to.get(), third);
    EXPECT_TRUE(sameBits(first.states, third));
}

TEST_F(SceneOnePropagation, StepByStepEqualsOneLongPropagation)
{
    // propagateWhileValid (one propagate() per step) and one propagate() over the whole duration take the
    // same 0.01 s sub-steps; the robot coasts alone, touching only the floor, whose contact acts on its
    // vertical motion only, so its horizontal position agrees to rounding
    const BodyStates start = robotAt(-0.84, 0.97, 0.1, -0.1);
    const Eigen::Vector2d force(1.0, -0.5);
    const Outcome whole = propagate(start, force, 5);
    ompl::base::ScopedState<> from(si_->getStateSpace());
    ompl::base::ScopedState<> to(si_->getStateSpace());
    space_.writeState(start, from.get());
    const auto control = makeControl(force);
    ASSERT_EQ(si_->propagateWhileValid(from.get(), control.get(), 5, to.get()), 5u);
    BodyStates stepwise;
    space_.readState(to.get(), stepwise);
    EXPECT_TRUE(stepwise[0].position.isApprox(whole.states[0].position, 1e-12));
    // and both agree with the frictionless free-mass motion: x = x0 + v0 T + F T^2 / (2 m) up to the
    // integrator's first-order bias F T dt / (2 m) (see test_PhysicsWorld)
    const double T = 5 * si_->getPropagationStepSize();
    const double dt = si_->getPropagationStepSize() / scene().contact.substeps;
    const Eigen::Vector2d expected = start[0].position.head<2>() + start[0].linearVelocity.head<2>() * T +
                                     force * T * T / (2.0 * scene().robot.mass);
    EXPECT_LE((whole.states[0].position.head<2>() - expected).norm(),
              force.norm() * T * dt / (2.0 * scene().robot.mass) + 1e-9);
}
