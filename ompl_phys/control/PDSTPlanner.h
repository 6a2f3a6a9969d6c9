#pragma once

#include "ompl_phys/control/PhysicsStatePropagator.h"

#include <ompl/control/planners/pdst/PDST.h>

#include <cstddef>

namespace ompl_phys
{
    /** OMPL's PDST, whose tree can be measured and listed without counting as planning:
        PDST::getPlannerData propagates every split motion again, which on a physics scene takes
        tens of milliseconds and would add to the propagator's counters. */
    class PDSTPlanner : public ompl::control::PDST
    {
    public:
        using ompl::control::PDST::PDST;

        /** Motions in the tree; each piece of a motion split at a cell boundary counts once. Read
            without simulating anything. */
        std::size_t motionCount() const { return priorityQueue_.size(); }

        /** PDST's planner data; the propagations it makes are not counted (when the propagator is a
            PhysicsStatePropagator). */
        void getPlannerData(ompl::base::PlannerData &data) const override
        {
            const auto *propagator =
                dynamic_cast<const PhysicsStatePropagator *>(siC_->getStatePropagator().get());
            if (!propagator)
                return PDST::getPlannerData(data);
            const PhysicsStatePropagator::Counters planning = propagator->counters();
            PDST::getPlannerData(data);
            propagator->restoreCounters(planning);
        }
    };
}  // namespace ompl_phys
