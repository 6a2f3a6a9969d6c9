/* A manipulation primitive in the sense of the MOPL paper (Definition III.1): given a start and a
   target configuration it says whether it applies (isUseful, cheap, no inverse kinematics) and,
   if so, produces waypoints from the start towards the target (propagate), ignoring obstacles.
   The empty-space planner chains primitives; collisions are checked afterwards. */
#pragma once

#include "ompl_mm/primitives/Trajectory.h"

#include <memory>
#include <string>

namespace ompl_mm
{
    class Primitive
    {
    public:
        Primitive(const ManipulationStateSpace *space, std::string name, PrimitiveKind kind);
        virtual ~Primitive() = default;
        Primitive(const Primitive &) = delete;
        Primitive &operator=(const Primitive &) = delete;

        const std::string &name() const { return name_; }
        PrimitiveKind kind() const { return kind_; }

        /** True when the primitive can move from `from` towards `to`. */
        virtual bool isUseful(const ompl::base::State *from, const ompl::base::State *to) const = 0;

        /** Appends waypoints that move from trajectory.back() (which equals from) towards `to`.
            Returns false, appending nothing, when the primitive cannot act (e.g. no IK). */
        virtual bool propagate(const ompl::base::State *from, const ompl::base::State *to,
                               Trajectory &trajectory) const = 0;

    protected:
        /** True when every object rests on a support surface in state. */
        bool allObjectsRest(const ompl::base::State *state) const;

        const ManipulationStateSpace *space_;

    private:
        std::string name_;
        PrimitiveKind kind_;
    };

    using PrimitivePtr = std::shared_ptr<Primitive>;
}  // namespace ompl_mm
