#include "ompl_mm/primitives/Primitive.h"

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
}  // namespace ompl_mm
