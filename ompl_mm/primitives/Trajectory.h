#pragma once

#include "ompl_mm/base/ManipulationStateSpace.h"

#include <string>
#include <vector>

namespace ompl_mm
{
    /** The kinds of manipulation action, as counted in results. */
    enum class PrimitiveKind
    {
        Transit,  ///< the robot moves alone; every object rests where it is
        Push,     ///< the robot pushes an object across its support surface
        Pickup,   ///< the robot lifts an object off its surface (no built-in primitive)
        Transfer  ///< the robot carries a held object (no built-in primitive)
    };

    /** Lower-case name of a kind: "transit", "push", "pickup", "transfer". */
    const char *primitiveKindName(PrimitiveKind kind);

    /** What moved along one segment: the primitive kind and the object (-1 for transit). */
    struct SegmentLabel
    {
        PrimitiveKind kind{PrimitiveKind::Transit};  ///< the kind of primitive that moved
        int object{-1};                              ///< index of the object it moved, -1 for none

        /** True when kind and object are the same. */
        bool operator==(const SegmentLabel &other) const
        {
            return kind == other.kind && object == other.object;
        }
        /** True when kind or object differ. */
        bool operator!=(const SegmentLabel &other) const { return !(*this == other); }
    };

    /** A sequence of waypoints produced by manipulation primitives, with one label per segment
        saying which primitive moved which object. Consecutive waypoints interpolate with
        ManipulationStateSpace::interpolate, which reproduces the primitive's motion. Owns copies of
        its states. Move-only (move construction; no assignment). */
    class Trajectory
    {
    public:
        /** An empty trajectory. @pre space outlives it. */
        explicit Trajectory(const ManipulationStateSpace *space);
        /** Frees the states. */
        ~Trajectory();
        Trajectory(const Trajectory &) = delete;             ///< not copyable
        Trajectory &operator=(const Trajectory &) = delete;  ///< not copyable
        /** Takes other's states; other is left empty. */
        Trajectory(Trajectory &&other) noexcept;

        /** Drops all waypoints and starts again at a copy of state. */
        void reset(const ompl::base::State *state);
        /** Adds a copy of a waypoint reached from the last one by the labelled motion. A planner may
            start other motions from it (and from the states on the way to it) only when it and
            the last waypoint are branchable; a simulated push's waypoints in contact with its object
            are not, since the robot would drag the object it touches. @pre not empty. */
        void append(const ompl::base::State *state, SegmentLabel label, bool branchable = true);
        /** Removes waypoints after the first `count` (and their labels). */
        void truncate(std::size_t count);

        /** Number of waypoints. */
        std::size_t size() const { return states_.size(); }
        /** True when there are no waypoints. */
        bool empty() const { return states_.empty(); }
        /** Waypoint i, owned by the trajectory. */
        const ompl::base::State *state(std::size_t i) const { return states_[i]; }
        /** The last waypoint. @pre not empty. */
        const ompl::base::State *back() const { return states_.back(); }
        /** Whether other motions may start at waypoint i (see append). */
        bool branchable(std::size_t i) const { return branchable_[i] != 0; }
        /** Label of the segment from waypoint i to i + 1. */
        const SegmentLabel &label(std::size_t i) const { return labels_[i]; }
        /** The space of the waypoints. */
        const ManipulationStateSpace *space() const { return space_; }

    private:
        const ManipulationStateSpace *space_;
        std::vector<ompl::base::State *> states_;
        std::vector<SegmentLabel> labels_;
        std::vector<char> branchable_;  ///< per waypoint
    };
}  // namespace ompl_mm
