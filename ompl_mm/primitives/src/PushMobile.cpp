#include "ompl_mm/primitives/PushMobile.h"

#include <ompl/util/Exception.h>

#include <cmath>
#include <sstream>

namespace ompl_mm
{
    namespace
    {
        // pushes made by other code than propagate (OMPL's shortcuts, paths read back) hold the
        // standoff only up to rounding
        constexpr double ON_LINE = 1e-6;
    }  // namespace

    PushMobile::PushMobile(const ManipulationStateSpace *space, std::optional<double> standoff)
        : Primitive(space, "push_mobile", PrimitiveKind::Push), base_(*space->model())
    {
        if (!base_.exists())
            throw ompl::Exception(
                "push_mobile needs a robot whose base moves along world x and y "
                "(two prismatic joints)");
        if (standoff && !(*standoff > 0.0))
            throw ompl::Exception("push_mobile standoff must be positive, got " + std::to_string(*standoff));
        const Scene &scene = space->model()->scene();
        if (scene.robotStart.size() != space->robotDimension())
            throw ompl::Exception("push_mobile needs the scene's robot start to measure the robot");
        const double robotRadius = base_.footprintRadius(scene.robotStart.data());
        for (const MovableObject &object : scene.objects)
        {
            const double touching = robotRadius + object.shape.footprintRadius();
            if (standoff && *standoff < touching)
            {
                std::ostringstream message;
                message << "push_mobile standoff " << *standoff << " leaves the robot overlapping object '"
                        << object.name << "' while pushing it: it must be at least " << touching
                        << " (robot footprint radius " << robotRadius << " + object footprint radius "
                        << object.shape.footprintRadius() << "); leave it out for " << touching + CLEARANCE;
                throw ompl::Exception(message.str());
            }
            standoffs_.push_back(standoff ? *standoff : touching + CLEARANCE);
        }
    }

    bool PushMobile::isUseful(const ompl::base::State *from, const ompl::base::State *to) const
    {
        return pushable(from, to);
    }

    bool PushMobile::propagate(const ompl::base::State *from, const ompl::base::State *to,
                               Trajectory &trajectory) const
    {
        const int object = nearestSlidingObject(from, to);
        if (object < 0)
            return false;
        const ObjectPose start = space_->objectPose(from, object);
        ObjectPose target = start;
        target.position.head<2>() = space_->objectPosition(to, object).head<2>();
        const Eigen::Vector2d direction = (target.position - start.position).head<2>().normalized();
        const double standoff = standoffs_[object];
        // transit behind the object, then push it to its target
        ompl::base::State *waypoint = space_->cloneState(from);
        base_.placeTool(start.position.head<2>() - standoff * direction, space_->robotValues(waypoint));
        if (space_->robotMoves(from, waypoint))
            trajectory.append(waypoint, {PrimitiveKind::Transit, -1});
        base_.placeTool(target.position.head<2>() - standoff * direction, space_->robotValues(waypoint));
        space_->setObjectPose(waypoint, object, target);
        trajectory.append(waypoint, {PrimitiveKind::Push, object});
        space_->freeState(waypoint);
        return true;
    }

    std::optional<SegmentLabel> PushMobile::explain(const ompl::base::State *from,
                                                    const ompl::base::State *to) const
    {
        if (!base_.onlyBaseMoves(space_->robotValues(from), space_->robotValues(to)))
            return std::nullopt;
        const int pushed = onlySlidingObject(from, to);
        if (pushed < 0)
            return std::nullopt;
        const Eigen::Vector2d a = space_->objectPosition(from, pushed).head<2>();
        const Eigen::Vector2d b = space_->objectPosition(to, pushed).head<2>();
        const Eigen::Vector2d behind = standoffs_[pushed] * (b - a).normalized();
        if ((space_->toolPosition(from).head<2>() - (a - behind)).norm() > ON_LINE ||
            (space_->toolPosition(to).head<2>() - (b - behind)).norm() > ON_LINE)
            return std::nullopt;
        return SegmentLabel{PrimitiveKind::Push, pushed};
    }
}  // namespace ompl_mm
