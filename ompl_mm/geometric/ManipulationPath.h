#pragma once

#include "ompl_mm/primitives/Trajectory.h"

#include <ompl/geometric/PathGeometric.h>

#include <map>
#include <string>
#include <vector>

namespace ompl_mm
{
    /** A manipulation plan as an OMPL geometric path: the waypoints, plus one label per segment
        saying which primitive moved which object. Consecutive waypoints interpolate with the
        manipulation state space, so PathGeometric::check() and OMPL's benchmark re-check it as is.
        The labels describe the states they were given with. When anything else changes the states
        (OMPL's PathSimplifier, PathGeometric::interpolate, subdivide, reverse, …), the next
        call that reads labels relabels every segment from its motion with the space
        information's ManipulationMotionValidator (the first primitive that explains it); a
        segment no primitive explains, or a space information without that validator, makes it
        throw rather than answer with labels that do not fit. Owns copies of its states, as
        PathGeometric does. */
    class ManipulationPath : public ompl::geometric::PathGeometric
    {
    public:
        /** An empty path. @pre si's state space is a ManipulationStateSpace. */
        explicit ManipulationPath(const ompl::base::SpaceInformationPtr &si);

        /** Appends a copy of a state reached from the last one by a labelled segment.
            @throws ompl::Exception when the path is empty (the first state has no label: use
            appendFirst()). */
        void appendLabelled(const ompl::base::State *state, SegmentLabel label);
        /** Appends a copy of the first state. @throws ompl::Exception when the path has states. */
        void appendFirst(const ompl::base::State *state);

        /** Label of the segment from state i to state i + 1. @throws as labels(). */
        const SegmentLabel &label(std::size_t i) const { return labels()[i]; }
        /** All labels, one per segment (getStateCount() - 1 of them for a non-empty path),
            relabelled from the motions when the states changed since they were labelled.
            @throws ompl::Exception naming the first segment that no primitive explains, or when
            relabelling is needed and the space information has no ManipulationMotionValidator. */
        const std::vector<SegmentLabel> &labels() const;

        /** Replaces states first + 1 … last and their segments' labels with the trajectory's
            waypoints after its first, which must equal state first, and its labels. The
            trajectory's last waypoint becomes the new state in last's place (it may differ, e.g.
            at the end of the path).
            @throws ompl::Exception unless first < last < getStateCount() and the trajectory has
            two waypoints or more and starts at state first. */
        void replace(std::size_t first, std::size_t last, const Trajectory &trajectory);
        /** Removes states equal to their predecessor. */
        void removeRepeatedStates();

        /** Length of the path the tool point travels, metres (straight lines between waypoints
            sampled at the space's segment resolution). @pre the path has states. */
        double toolPathLength() const;
        /** Length of the path the tool point travels from state first to state last, metres. */
        double toolPathLength(std::size_t first, std::size_t last) const;

        /** Number of primitive applications by kind (a run of segments with the same label
            counts once; a run of transit segments counts as one transit). */
        std::map<std::string, unsigned int> primitiveCounts() const;

        /** A push that moves an object back against the push of it just before. */
        struct PushReversal
        {
            unsigned int object;  ///< the object pushed back
            std::size_t earlier;  ///< the segment (from state `earlier` to the next) of the push before
            std::size_t later;    ///< the segment that pushes the object back
        };
        /** How far a push must move an object back along the push before it to be a reversal,
            metres: more than rounding, less than any push worth making. */
        static constexpr double REVERSAL_TOLERANCE = 1e-3;
        /** The push reversals of the path, in the order of their earlier segments: pairs of push
            segments of one object, the object not moved between them, where the later moves it
            back along the earlier's direction by more than REVERSAL_TOLERANCE (the earlier push
            carried it past a point the later one brings it back towards; a round trip is one).
            @throws as labels(). */
        std::vector<PushReversal> pushReversals() const;

        /** Checks that every segment is one its label allows: transit moves no object, a push or
            transfer moves only its object, and that objects move only in such segments. Returns an
            empty string when consistent, else a description of the first fault (also when
            relabelling changed states fails). */
        std::string checkLabels() const;

    private:
        /** True when the states are those the labels were given or found for. */
        bool labelsFitStates() const;
        /** Remembers the current states as the ones the labels describe. */
        void rememberLabelledStates() const;

        mutable std::vector<SegmentLabel> labels_;
        mutable std::vector<double> labelledValues_;  ///< the labelled states' values, one after another
        mutable std::vector<double> values_;          ///< scratch for one state's values
    };
}  // namespace ompl_mm
