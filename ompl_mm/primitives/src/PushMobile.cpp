#include "ompl_mm/primitives/PushMobile.h"

#include <ompl/util/Exception.h>

#include <cmath>
#include <limits>

namespace ompl_mm
{
    namespace
    {
        constexpr double SAME = 1e-9;
    }

    PushMobile::PushMobile(const ManipulationStateSpace *space, double standoff)
        : Primitive(space, "push_mobile", PrimitiveKind::Push), base_(*space->model()), standoff_(standoff)
    {
        if (!base_.exists())
            throw ompl::Exception(
                "push_mobile needs a robot whose base moves along world x and y "
                "(two prismatic joints)");
        if (!(standoff > 0.0))
            throw ompl::Exception("push_mobile standoff must be positive, got " + std::to_string(standoff));
    }

    bool PushMobile::slides(const ompl::base::State *a, const ompl::base::State *b, unsigned int object) const
    {
        const Eigen::Vector3d pa = space_->objectPosition(a, object);
        const Eigen::Vector3d pb = space_->objectPosition(b, object);
        return std::abs(pa.z() - pb.z()) < SAME && (pa - pb).head<2>().norm() > SAME;
    }

    bool PushMobile::isUseful(const ompl::base::State *from, const ompl::base::State *to) const
    {
        if (!allObjectsRest(from) || !allObjectsRest(to))
            return false;
        for (unsigned int i = 0; i < space_->objectCount(); ++i)
            if (slides(from, to, i))
                return true;
        return false;
    }

    bool PushMobile::propagate(const ompl::base::State *from, const ompl::base::State *to,
                               Trajectory &trajectory) const
    {
        // the sliding object nearest to the tool
        const Eigen::Vector2d tool = space_->toolPosition(from).head<2>();
        int object = -1;
        double nearest = std::numeric_limits<double>::infinity();
        for (unsigned int i = 0; i < space_->objectCount(); ++i)
        {
            const double d = (space_->objectPosition(from, i).head<2>() - tool).norm();
            if (slides(from, to, i) && d < nearest)
            {
                nearest = d;
                object = static_cast<int>(i);
            }
        }
        if (object < 0)
            return false;

        const ObjectPose start = space_->objectPose(from, object);
        ObjectPose target = start;
        target.position.head<2>() = space_->objectPosition(to, object).head<2>();
        const Eigen::Vector2d direction = (target.position - start.position).head<2>().normalized();

        // transit behind the object, then push it to its target
        ompl::base::State *waypoint = space_->cloneState(from);
        base_.placeTool(start.position.head<2>() - standoff_ * direction, space_->robotValues(waypoint));
        if (space_->robotMoves(from, waypoint))
            trajectory.append(waypoint, {PrimitiveKind::Transit, -1});
        base_.placeTool(target.position.head<2>() - standoff_ * direction, space_->robotValues(waypoint));
        space_->setObjectPose(waypoint, object, target);
        trajectory.append(waypoint, {PrimitiveKind::Push, object});
        space_->freeState(waypoint);
        return true;
    }
}  // namespace ompl_mm
