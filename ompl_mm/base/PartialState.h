#pragma once

#include "ompl_mm/base/ManipulationStateSpace.h"

#include <vector>

namespace ompl_mm
{
    /** A partially defined configuration, as MOPL samples them: each part (the robot, or one
        object) is either defined or "don't care". Undefined parts are resolved later by copying
        them from the nearest tree vertex (or, for goal roots, by ManipulationGoal::complete).
        Owns its state. Part 0 is the robot, part 1 + i is object i. Not copyable. */
    class PartialState
    {
    public:
        /** Allocates a state of space with every part defined.
            @pre space outlives this object. */
        explicit PartialState(const ManipulationStateSpace *space);
        /** Frees the state. */
        ~PartialState();
        PartialState(const PartialState &) = delete;             ///< not copyable
        PartialState &operator=(const PartialState &) = delete;  ///< not copyable

        /** The values; undefined parts may hold anything. */
        ompl::base::State *state() { return state_; }
        /** The values; undefined parts may hold anything. */
        const ompl::base::State *state() const { return state_; }

        /** True when the robot's joints are defined. */
        bool robotDefined() const { return defined_[0] != 0; }
        /** True when the object's pose is defined. */
        bool objectDefined(unsigned int object) const { return defined_[1 + object] != 0; }
        /** Marks the robot's joints defined or "don't care". */
        void setRobotDefined(bool defined) { defined_[0] = defined; }
        /** Marks the object's pose defined or "don't care". */
        void setObjectDefined(unsigned int object, bool defined) { defined_[1 + object] = defined; }
        /** Marks every part defined (and no robot to grasp an object). */
        void defineAll();

        /** The object the robot must grasp, or -1: a sample of an object "in the air" leaves the
            robot undefined until inverse kinematics finds a grasp of it (MOPL seeds it from the
            nearest vertex). */
        int graspedObject() const { return graspedObject_; }
        /** Sets the object the robot must grasp (-1: none). */
        void setGraspedObject(int object) { graspedObject_ = object; }

        /** Writes into out the defined parts of this state and the other parts of fill; out may be
            state(). */
        void complete(const ompl::base::State *fill, ompl::base::State *out) const;

    private:
        const ManipulationStateSpace *space_;
        ompl::base::State *state_;
        std::vector<char> defined_;
        int graspedObject_{-1};
    };
}  // namespace ompl_mm
