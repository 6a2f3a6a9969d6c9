#include "ompl_phys/base/PhysicsStateSampler.h"

#include <cmath>

namespace ompl_phys
{
    namespace
    {
        constexpr double PI = 3.14159265358979323846;

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
            const PhysicsBody &body = scene.bodies[movable_[i]];
            BodyState &s = scratch_[i + 1];
            const Eigen::Vector3d start = body.start.translation();
            if (body.kind == BodyKind::Constrained)
            {
                // a point of the axis line through the start, inside the body region
                const Eigen::Quaterniond orientation(body.start.linear());
                const Eigen::Vector2d axis = (orientation * body.push.axis).head<2>().normalized();
                const double reach = limits.bodyRegion.diagonal().norm();
                Eigen::Vector2d at;
                do
                    at = start.head<2>() + rng_.uniformReal(-reach, reach) * axis;
                while (!limits.bodyRegion.contains(at));
                s.position << at, start.z();
                s.orientation = orientation;
                continue;
            }
            s.position << uniformIn(rng_, limits.bodyRegion), start.z();
            s.orientation = Eigen::AngleAxisd(rng_.uniformReal(-PI, PI), Eigen::Vector3d::UnitZ()) *
                            Eigen::Quaterniond(body.start.linear());
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
