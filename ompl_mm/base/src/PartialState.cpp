#include "ompl_mm/base/PartialState.h"

#include <algorithm>

namespace ompl_mm
{
    PartialState::PartialState(const ManipulationStateSpace *space)
        : space_(space), state_(space->allocState()), defined_(1 + space->objectCount(), 1)
    {
    }

    PartialState::~PartialState()
    {
        space_->freeState(state_);
    }

    void PartialState::defineAll()
    {
        std::fill(defined_.begin(), defined_.end(), 1);
        graspedObject_ = -1;
    }

    void PartialState::complete(const ompl::base::State *fill, ompl::base::State *out) const
    {
        space_->copyRobot(out, robotDefined() ? state_ : fill);
        for (unsigned int i = 0; i < space_->objectCount(); ++i)
            space_->copyObject(out, objectDefined(i) ? state_ : fill, i);
    }
}  // namespace ompl_mm
