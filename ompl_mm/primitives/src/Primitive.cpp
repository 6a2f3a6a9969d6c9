#include "ompl_mm/primitives/Primitive.h"

#include <limits>

namespace ompl_mm
{
    Primitive::Primitive(const ManipulationStateSpace *space, std::string name, PrimitiveKind kind)
        : space_(space), name_(std::move(name)), kind_(kind)
    {
    }

    bool Primitive::allObjectsRest(const ompl::base::State *state) const
    {
        for (unsigned int i = 0; i < space_->objectCount(); ++i)
            if (space_->restingSurface(state, i) < 0)
                return false;
        return true;
    }

    bool Primitive::anyObject(const std::function<bool(unsigned int)> &holds) const
    {
        for (unsigned int i = 0; i < space_->objectCount(); ++i)
            if (holds(i))
                return true;
        return false;
    }

    int Primitive::nearestToTool(const ompl::base::State *state,
                                 const std::function<bool(unsigned int)> &qualifies) const
    {
        const Eigen::Vector3d tool = space_->toolPosition(state);
        int object = -1;
        double nearest = std::numeric_limits<double>::infinity();
        for (unsigned int i = 0; i < space_->objectCount(); ++i)
        {
            const double d = (space_->objectPosition(state, i) - tool).norm();
            if (d < nearest && qualifies(i))
            {
                nearest = d;
                object = static_cast<int>(i);
            }
        }
        return object;
    }
}  // namespace ompl_mm
