#pragma once

#include <ompl/control/planners/pdst/PDST.h>

#include <cstddef>

namespace ompl_phys
{
    /** OMPL's PDST, whose tree size can be read without simulating anything: PDST::getPlannerData
        propagates every split motion again, which on a physics scene takes tens of milliseconds
        after the time limit. */
    class PDSTPlanner : public ompl::control::PDST
    {
    public:
        using ompl::control::PDST::PDST;

        /** Motions in the tree; each piece of a motion split at a cell boundary counts once. */
        std::size_t motionCount() const { return priorityQueue_.size(); }
    };
}  // namespace ompl_phys
