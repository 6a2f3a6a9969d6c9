/* State-based validity for manipulation: a configuration is valid when the robot is within its
   joint limits, at most one object is held (off every support surface), and nothing collides
   under the contact rules of CollisionWorld. Because validity depends on the state alone,
   OMPL's motion validator and PathGeometric::check() are meaningful for manipulation paths. */
#pragma once

#include "ompl_mm/base/ManipulationStateSpace.h"
#include "ompl_mm/collision/CollisionWorld.h"

#include <ompl/base/StateValidityChecker.h>

#include <cstdint>
#include <string>

namespace ompl_mm
{
    /** Counts its queries (total and collision-free) for planner statistics. Not thread-safe. */
    class ManipulationValidityChecker : public ompl::base::StateValidityChecker
    {
    public:
        explicit ManipulationValidityChecker(const ompl::base::SpaceInformationPtr &si);

        bool isValid(const ompl::base::State *state) const override;

        /** Why a state is invalid, in words naming the bodies involved; empty when it is valid.
            Does not count as a query. */
        std::string explain(const ompl::base::State *state) const;

        std::uint64_t queryCount() const { return queries_; }
        std::uint64_t freeQueryCount() const { return freeQueries_; }
        void resetCounters() { queries_ = freeQueries_ = 0; }

    private:
        /** Validity and, when reason is given and the state is invalid, the reason. */
        bool check(const ompl::base::State *state, std::string *reason) const;

        const ManipulationStateSpace *space_;
        CollisionWorld world_;
        mutable std::vector<ObjectPose> poses_;
        mutable std::vector<int> resting_;
        mutable std::uint64_t queries_{0};
        mutable std::uint64_t freeQueries_{0};
    };
}  // namespace ompl_mm
