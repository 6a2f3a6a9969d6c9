#include "ompl_mm/primitives/Transit.h"

namespace ompl_mm
{
    Transit::Transit(const ManipulationStateSpace *space)
        : Primitive(space, "transit", PrimitiveKind::Transit)
    {
    }

    bool Transit::isUseful(const ompl::base::State *from, const ompl::base::State *to) const
    {
        return space_->robotMoves(from, to) && !space_->anyObjectMoves(from, to) && allObjectsRest(from);
    }

    bool Transit::propagate(const ompl::base::State *from, const ompl::base::State *to,
                            Trajectory &trajectory) const
    {
        ompl::base::State *next = space_->cloneState(from);
        space_->copyRobot(next, to);
        trajectory.append(next, {PrimitiveKind::Transit, -1});
        space_->freeState(next);
        return true;
    }

    std::optional<SegmentLabel> Transit::explain(const ompl::base::State *from,
                                                 const ompl::base::State *to) const
    {
        if (space_->anyObjectMoves(from, to) || !allObjectsRest(from))
            return std::nullopt;
        return SegmentLabel{PrimitiveKind::Transit, -1};
    }
}  // namespace ompl_mm
