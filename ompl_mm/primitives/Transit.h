#pragma once

#include "ompl_mm/primitives/Primitive.h"

namespace ompl_mm
{
    /** Transit (MOPL paper, section III-A; cited at MOPL): the robot moves along a straight line in
        joint space while every object rests where it is. */
    class Transit : public Primitive
    {
    public:
        /** A transit primitive in space. @pre space outlives the primitive. */
        explicit Transit(const ManipulationStateSpace *space);

        /** Primitive's hook: useful when no object moves, all objects rest, and the robot moves. */
        bool isUseful(const ompl::base::State *from, const ompl::base::State *to) const override;
        /** Primitive's hook: appends the target robot pose with the objects of from, as one transit
            segment; always succeeds. */
        bool propagate(const ompl::base::State *from, const ompl::base::State *to,
                       Trajectory &trajectory) const override;
        /** Primitive's hook: a transit segment when every object rests and none moves. */
        std::optional<SegmentLabel> explain(const ompl::base::State *from,
                                            const ompl::base::State *to) const override;
    };
}  // namespace ompl_mm
