/* Transit (MOPL paper, section III-A): the robot moves along a straight line in joint space while
   every object rests where it is. */
#pragma once

#include "ompl_mm/primitives/Primitive.h"

namespace ompl_mm
{
    class Transit : public Primitive
    {
    public:
        explicit Transit(const ManipulationStateSpace *space);

        /** Useful when no object moves, all objects rest, and the robot moves. */
        bool isUseful(const ompl::base::State *from, const ompl::base::State *to) const override;
        /** Appends the target robot pose with the objects of from. */
        bool propagate(const ompl::base::State *from, const ompl::base::State *to,
                       Trajectory &trajectory) const override;
    };
}  // namespace ompl_mm
