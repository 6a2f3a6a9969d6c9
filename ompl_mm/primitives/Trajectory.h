/* A sequence of waypoints produced by manipulation primitives, with one label per segment saying
   which primitive moved which object. Consecutive waypoints interpolate with
   ManipulationStateSpace::interpolate, which reproduces the primitive's motion. */
#pragma once

#include "ompl_mm/base/ManipulationStateSpace.h"

#include <string>
#include <vector>

namespace ompl_mm
{
    /** The kinds of manipulation action, as counted in results. */
    enum class PrimitiveKind
    {
        Transit,
        Push,
        Pickup,
        Transfer
    };

    /** Lower-case name of a kind: "transit", "push", "pickup", "transfer". */
    const char *primitiveKindName(PrimitiveKind kind);

    /** What moved along one segment: the primitive kind and the object (-1 for transit). */
    struct SegmentLabel
    {
        PrimitiveKind kind{PrimitiveKind::Transit};
        int object{-1};

        bool operator==(const SegmentLabel &other) const
        {
            return kind == other.kind && object == other.object;
        }
        bool operator!=(const SegmentLabel &other) const { return !(*this == other); }
    };

    /** Owns its states. Move-only. */
    class Trajectory
    {
    public:
        explicit Trajectory(const ManipulationStateSpace *space);
        ~Trajectory();
        Trajectory(const Trajectory &) = delete;
        Trajectory &operator=(const Trajectory &) = delete;
        Trajectory(Trajectory &&other) noexcept;

        /** Drops all waypoints and starts again at state. */
        void reset(const ompl::base::State *state);
        /** Adds a waypoint reached from the last one by the labelled motion. @pre not empty. */
        void append(const ompl::base::State *state, SegmentLabel label);
        /** Removes waypoints after the first `count`. */
        void truncate(std::size_t count);

        std::size_t size() const { return states_.size(); }
        bool empty() const { return states_.empty(); }
        const ompl::base::State *state(std::size_t i) const { return states_[i]; }
        const ompl::base::State *back() const { return states_.back(); }
        /** Label of the segment from waypoint i to i + 1. */
        const SegmentLabel &label(std::size_t i) const { return labels_[i]; }
        const ManipulationStateSpace *space() const { return space_; }

    private:
        const ManipulationStateSpace *space_;
        std::vector<ompl::base::State *> states_;
        std::vector<SegmentLabel> labels_;
    };
}  // namespace ompl_mm
