/* A partially defined configuration, as MOPL samples them: each part (the robot, or one
   object) is either defined or "don't care". Undefined parts are resolved later by copying them
   from the nearest tree vertex (or, for goal roots, by ManipulationGoal::complete). */
#pragma once

#include "ompl_mm/base/ManipulationStateSpace.h"

#include <vector>

namespace ompl_mm
{
    /** Owns its state. Part 0 is the robot, part 1 + i is object i. Not copyable. */
    class PartialState
    {
    public:
        explicit PartialState(const ManipulationStateSpace *space);
        ~PartialState();
        PartialState(const PartialState &) = delete;
        PartialState &operator=(const PartialState &) = delete;

        ompl::base::State *state() { return state_; }
        const ompl::base::State *state() const { return state_; }

        bool robotDefined() const { return defined_[0] != 0; }
        bool objectDefined(unsigned int object) const { return defined_[1 + object] != 0; }
        void setRobotDefined(bool defined) { defined_[0] = defined; }
        void setObjectDefined(unsigned int object, bool defined) { defined_[1 + object] = defined; }
        void defineAll();

        /** Writes into out the defined parts of this state and the other parts of fill. */
        void complete(const ompl::base::State *fill, ompl::base::State *out) const;

    private:
        const ManipulationStateSpace *space_;
        ompl::base::State *state_;
        std::vector<char> defined_;
    };
}  // namespace ompl_mm
