#include "ompl_mm/primitives/Primitive.h"

#include "ompl_mm/base/ManipulationValidityChecker.h"

#include <cmath>
#include <limits>

namespace ompl_mm
{
    Primitive::Primitive(const ManipulationStateSpace *space, std::string name, PrimitiveKind kind)
        : space_(space), name_(std::move(name)), kind_(kind)
    {
    }

    bool Primitive::acceptable(const ompl::base::State *state) const
    {
        if (!checker_ || checker_->isValid(state))
            return true;
        // the words of a manipulation checker, which names the bodies; a generic one's verdict
        const auto *manipulation = dynamic_cast<const ManipulationValidityChecker *>(checker_.get());
        rejection_ =
            "a pose it needs is invalid: " +
            (manipulation ? manipulation->explain(state) : std::string("the state validity checker says so"));
        return false;
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

    bool Primitive::slides(const ompl::base::State *a, const ompl::base::State *b, unsigned int object) const
    {
        const Eigen::Vector3d pa = space_->objectPosition(a, object);
        const Eigen::Vector3d pb = space_->objectPosition(b, object);
        return std::abs(pa.z() - pb.z()) < SAME_COORDINATE && (pa - pb).head<2>().norm() > SAME_COORDINATE;
    }

    bool Primitive::pushable(const ompl::base::State *a, const ompl::base::State *b) const
    {
        return allObjectsRest(a) && allObjectsRest(b) &&
               anyObject([&](unsigned int i) { return slides(a, b, i); });
    }

    int Primitive::nearestSlidingObject(const ompl::base::State *a, const ompl::base::State *b) const
    {
        return nearestToTool(a, [&](unsigned int i) { return slides(a, b, i); });
    }

    int Primitive::onlySlidingObject(const ompl::base::State *a, const ompl::base::State *b) const
    {
        if (!allObjectsRest(a) || !allObjectsRest(b))
            return -1;
        int sliding = -1;
        for (unsigned int i = 0; i < space_->objectCount(); ++i)
        {
            if (!space_->objectMoves(a, b, i))
                continue;
            if (sliding >= 0 || !slides(a, b, i) ||
                std::abs(space_->objectYaw(a, i) - space_->objectYaw(b, i)) > SAME_COORDINATE)
                return -1;
            sliding = static_cast<int>(i);
        }
        return sliding;
    }
}  // namespace ompl_mm
