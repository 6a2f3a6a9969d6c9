#include "ompl_phys/base/PhysicsStateSampler.h"

namespace ompl_phys
{
    namespace
    {
        Eigen::Vector2d uniformIn(ompl::RNG &rng, const Eigen::AlignedBox2d &box)
        {
            return {rng.uniformReal(box.min().x(), box.max().x()),
                    rng.uniformReal(box.min().y(), box.max().y())};
        }
    }  // namespace

    PhysicsStateSampler::PhysicsStateSampler(const PhysicsStateSpace *space)
        : ompl::base::StateSampler(space), physics_(*space), movable_(space->scene().movableBodies())
    {
    }

    void PhysicsStateSampler::sampleUniform(ompl::base::State *state)
    {
        const PhysicsScene &scene = physics_.scene();
        const PlanningLimits &limits = scene.limits;
        scratch_.assign(physics_.movingBodyCount(), BodyState());
        BodyState &robot = scratch_[0];
        robot.position << uniformIn(rng_, limits.robotRegion), scene.robot.start.z();
        robot.linearVelocity << rng_.uniformReal(-limits.maxRobotSpeed, limits.maxRobotSpeed),
            rng_.uniformReal(-limits.maxRobotSpeed, limits.maxRobotSpeed), 0.0;
        for (std::size_t i = 0; i < movable_.size(); ++i)
        {
            const Eigen::Isometry3d &start = scene.bodies[movable_[i]].start;
            scratch_[i + 1].position = start.translation();
            scratch_[i + 1].orientation = Eigen::Quaterniond(start.linear());
        }
        physics_.writeState(scratch_, state);
    }

    void PhysicsStateSampler::sampleUniformNear(ompl::base::State *state, const ompl::base::State *near,
                                                double distance)
    {
        physics_.copyState(state, near);
        moveRobot(state, {rng_.uniformReal(-distance, distance), rng_.uniformReal(-distance, distance)});
    }

    void PhysicsStateSampler::sampleGaussian(ompl::base::State *state, const ompl::base::State *mean,
                                             double stdDev)
    {
        physics_.copyState(state, mean);
        moveRobot(state, {rng_.gaussian(0.0, stdDev), rng_.gaussian(0.0, stdDev)});
    }

    void PhysicsStateSampler::moveRobot(ompl::base::State *state, const Eigen::Vector2d &offset)
    {
        physics_.readState(state, scratch_);
        const Eigen::AlignedBox2d &region = physics_.scene().limits.robotRegion;
        const Eigen::Vector2d moved =
            (scratch_[0].position.head<2>() + offset).cwiseMax(region.min()).cwiseMin(region.max());
        scratch_[0].position.head<2>() = moved;
        physics_.writeState(scratch_, state);
    }
}  // namespace ompl_phys
