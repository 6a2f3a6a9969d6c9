#include "ompl_phys/knowledge/ManipulationKnowledge.h"

#include <ompl/util/Exception.h>

#include "ompl_phys/knowledge/Footprint.h"

#include <cmath>

namespace ompl_phys
{
    namespace
    {
        /** Granularity of the search for a place that clears the goal, metres. */
        constexpr double CLEARING_STEP = 0.01;

        /** Speed limits bound the norm of a velocity: a bound per component would let a diagonal
            motion go √3 times as fast. */
        template <typename Velocity>
        bool withinSpeed(const Velocity &velocity, double limit)
        {
            return velocity.norm() <= limit;
        }

        PhysicsScenePtr requireScene(PhysicsScenePtr scene)
        {
            if (!scene)
                throw ompl::Exception("ManipulationKnowledge", "needs a scene, got none");
            return scene;
        }
    }  // namespace

    ManipulationKnowledge::ManipulationKnowledge(PhysicsScenePtr scene)
        : scene_(requireScene(std::move(scene))),
          movable_(scene_->movableBodies()),
          movingIndex_(scene_->bodies.size(), 0)
    {
        for (std::size_t i = 0; i < scene_->bodies.size(); ++i)
            if (scene_->bodies[i].kind == BodyKind::Fixed)
                fixed_.push_back({i, scene_->bodies[i].start.translation().head<2>(),
                                  yawOf(Eigen::Quaterniond(scene_->bodies[i].start.linear()))});
        for (std::size_t i = 0; i < movable_.size(); ++i)
        {
            const PhysicsBody &body = scene_->bodies[movable_[i]];
            movingIndex_[movable_[i]] = i + 1;
            const Eigen::Quaterniond start(body.start.linear());
            startAxes_.push_back({start, (start * body.push.axis).head<2>().normalized()});
        }
    }

    bool ManipulationKnowledge::touchAllowed(std::size_t body, const Eigen::Vector3d &robotCentre,
                                             const BodyState &bodyState) const
    {
        const PhysicsBody &b = scene_->bodies[body];
        if (b.kind == BodyKind::Fixed)
            return false;
        if (b.kind == BodyKind::Free)
            return true;
        // the push region: a strip about the push axis, measured on the floor in the body's frame
        const Eigen::Vector3d local = bodyState.orientation.inverse() * (robotCentre - bodyState.position);
        const Eigen::Vector2d axis = b.push.axis.head<2>().normalized();
        return std::abs(cross(axis, local.head<2>())) <= b.push.stripHalfWidth;
    }

    Violation ManipulationKnowledge::checkTouches(const std::vector<std::size_t> &touches,
                                                  const BodyStates &states) const
    {
        for (std::size_t body : touches)
        {
            const BodyKind kind = scene_->bodies[body].kind;
            if (kind == BodyKind::Fixed)
                return Violation::TouchedFixedBody;
            if (kind != BodyKind::Constrained)
                continue;
            if (!touchAllowed(body, states[0].position, states[movingIndex_[body]]))
                return Violation::TouchedOutsideRegion;
        }
        return Violation::None;
    }

    Violation ManipulationKnowledge::checkPenetration(double deepest)
    {
        return deepest > SINK_TOLERANCE ? Violation::SankIn : Violation::None;
    }

    Violation ManipulationKnowledge::checkStates(const BodyStates &states) const
    {
        const PlanningLimits &limits = scene_->limits;
        for (const BodyState &s : states)
            if (!s.isFinite())
                return Violation::NotFinite;
        const BodyState &robot = states[0];
        if (!limits.robotRegion.contains(robot.position.head<2>()))
            return Violation::OutsideRegion;
        // the robot inside a fixed body (a sampled state, never a simulated one: ODE pushes it out)
        for (const FixedFootprint &f : fixed_)
            if (footprintDistance(scene_->bodies[f.body].shape, f.position, f.yaw, robot.position.head<2>()) <
                scene_->robot.radius)
                return Violation::TouchedFixedBody;
        if (!withinSpeed(robot.linearVelocity.head<2>(), limits.maxRobotSpeed) ||
            !withinSpeed(robot.angularVelocity, limits.maxAngularSpeed))
            return Violation::TooFast;
        for (std::size_t i = 0; i < movable_.size(); ++i)
        {
            const BodyState &s = states[i + 1];
            const PhysicsBody &body = scene_->bodies[movable_[i]];
            if (!limits.bodyRegion.contains(s.position.head<2>()))
                return Violation::OutsideRegion;
            if (!withinSpeed(s.linearVelocity, limits.maxBodySpeed) ||
                !withinSpeed(s.angularVelocity, limits.maxAngularSpeed))
                return Violation::TooFast;
            if (body.shape.kind != PhysicsShape::Kind::Sphere &&
                (s.orientation * Eigen::Vector3d::UnitZ()).z() < std::cos(TIP_TOLERANCE))
                return Violation::TippedOver;
            if (body.kind != BodyKind::Constrained)
                continue;
            const StartAxis &start = startAxes_[i];
            const Eigen::Vector2d offset = (s.position - body.start.translation()).head<2>();
            if (std::abs(cross(start.axis, offset)) > body.push.lateralTolerance ||
                start.orientation.angularDistance(s.orientation) > body.push.angleTolerance)
                return Violation::LeftPushAxis;
        }
        return Violation::None;
    }

    std::vector<std::size_t> ManipulationKnowledge::goalOccupants(const BodyStates &states) const
    {
        std::vector<std::size_t> occupants;
        const double reachOfGoal = scene_->goal.radius + scene_->robot.radius;
        for (std::size_t i = 0; i < movable_.size(); ++i)
        {
            const BodyState &s = states[i + 1];
            if (footprintDistance(scene_->bodies[movable_[i]].shape, s.position.head<2>(),
                                  yawOf(s.orientation), scene_->goal.centre) < reachOfGoal)
                occupants.push_back(i + 1);
        }
        return occupants;
    }

    std::vector<std::size_t> ManipulationKnowledge::fixedBodiesOnGoal() const
    {
        std::vector<std::size_t> blocking;
        for (const FixedFootprint &f : fixed_)
            if (footprintDistance(scene_->bodies[f.body].shape, f.position, f.yaw, scene_->goal.centre) <
                scene_->robot.radius)
                blocking.push_back(f.body);
        return blocking;
    }

    void ManipulationKnowledge::clearGoal(BodyStates &states, const Eigen::Vector2d &robotGoal,
                                          double clearance) const
    {
        const double needed = scene_->robot.radius + clearance;
        for (std::size_t i = 0; i < movable_.size(); ++i)
        {
            BodyState &s = states[i + 1];
            const PhysicsBody &body = scene_->bodies[movable_[i]];
            const double yaw = yawOf(s.orientation);
            const Eigen::Vector2d from = s.position.head<2>();
            auto clearAlong = [&](const Eigen::Vector2d &direction)
            {
                for (double shift = 0.0; shift < scene_->limits.bodyRegion.diagonal().norm();
                     shift += CLEARING_STEP)
                {
                    const Eigen::Vector2d at = from + shift * direction;
                    if (!scene_->limits.bodyRegion.contains(at))
                        return std::numeric_limits<double>::infinity();
                    if (footprintDistance(body.shape, at, yaw, robotGoal) >= needed)
                        return shift;
                }
                return std::numeric_limits<double>::infinity();
            };
            if (footprintDistance(body.shape, from, yaw, robotGoal) >= needed)
                continue;
            Eigen::Vector2d direction = (from - robotGoal).normalized();
            if (body.kind == BodyKind::Constrained)
                direction = (s.orientation * body.push.axis).head<2>().normalized();
            else if (!direction.allFinite())
                direction = Eigen::Vector2d::UnitX();
            double shift = clearAlong(direction);
            if (body.kind == BodyKind::Constrained)
            {
                const double back = clearAlong(-direction);
                if (back < shift)
                    shift = back, direction = -direction;
            }
            if (std::isfinite(shift))
                s.position.head<2>() = from + shift * direction;
        }
    }
}  // namespace ompl_phys
