#pragma once

#include "ompl_mm/primitives/Trajectory.h"

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <string_view>

namespace ompl_mm
{
    /** How the primitives fared in a search, by kind ("transit", "push", "pickup", "transfer"):
        how often one was asked to move, found no motion (its inverse kinematics found none, or it
        turned every solution down, and the last reason why), and how often a motion it made was
        stopped in the planner's collision-checked walk (and by which contact). A search that solves
        nothing reports it, so that a user learns which contact keeps a primitive from ever
        succeeding ("pickup: 1240 attempts, none succeeded: motions stopped by robot link
        'panda_hand' and object 'cyl1' 1180 times"). Plain value; counts only grow until clear(). */
    class PrimitiveTally
    {
    public:
        /** One kind's counts. */
        struct Record
        {
            std::uint64_t attempts{0};  ///< propagate calls
            std::uint64_t noMotion{0};  ///< of those, the ones that found no motion
            std::uint64_t motions{0};   ///< segments the walks checked for it (its own, and transits to them)
            std::uint64_t stopped{0};   ///< of those, the ones a contact stopped
            std::uint64_t completed{0};  ///< segments of its own kind the walks found free
            /** Why: "no motion: REASON" and "stopped by A and B", each with its count. */
            std::map<std::string, std::uint64_t> reasons;

            /** True when it was tried and no segment of its own kind was ever found free. */
            bool neverSucceeded() const { return attempts > 0 && completed == 0; }
            /** The most frequent reason and its count, or ("", 0) when there is none (the first
                of equals in text order). */
            std::pair<std::string, std::uint64_t> mainReason() const;
        };

        /** Notes a propagate call of a primitive of kind: found, or not and why (reason may be
            empty: then it is taken as its inverse kinematics finding nothing). */
        void attempt(PrimitiveKind kind, bool found, const std::string &reason = "");
        /** Notes a segment checked by a walk, labelled own, counted against kind (its own, or the
            primitive a transit approaches): free, or stopped by the contact of two bodies (either
            may be empty when it was stopped otherwise, e.g. by grazing). */
        void motion(PrimitiveKind kind, PrimitiveKind own, bool free, std::string_view bodyA = {},
                    std::string_view bodyB = {});
        /** Forgets every count. */
        void clear() { records_.clear(); }

        /** The records by kind name (ordered, looked up by any string type), for the kinds noted so
            far. */
        using Records = std::map<std::string, Record, std::less<>>;
        /** The records by kind name, for the kinds noted so far. */
        const Records &records() const { return records_; }

        /** One line per kind that was tried and never succeeded, e.g. "pickup: 1240 attempts, none
            succeeded; motions stopped by robot link 'panda_hand' and object 'cyl1' (1180 of 1180)";
            empty when every tried kind succeeded at least once. */
        std::string failureSummary() const;

    private:
        /** The record of kind, made when it is first noted: the walks note every segment they
            check, so an existing record is found without building a key. */
        Record &recordOf(PrimitiveKind kind);

        Records records_;
    };
}  // namespace ompl_mm
