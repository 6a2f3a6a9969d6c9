#pragma once

#include "ompl_mm/base/ManipulationStateSpace.h"
#include "ompl_mm/collision/CollisionWorld.h"

#include <ompl/base/StateValidityChecker.h>

#include <cstdint>
#include <string>

namespace ompl_mm
{
    /** State-based validity for manipulation: a configuration is valid when every value is finite,
        the robot is within its joint limits, at most one object is held (off every support
        surface), and nothing collides under the contact rules of CollisionWorld. Because validity
        depends on the state alone, OMPL's motion validator and PathGeometric::check() are
        meaningful for manipulation paths. Counts its queries (total and collision-free) for
        planner statistics. Not thread-safe. */
    class ManipulationValidityChecker : public ompl::base::StateValidityChecker
    {
    public:
        /** Builds the collision world of the space's model.
            @pre si's state space is a ManipulationStateSpace.
            @throws ompl_core::InputError when a surface names an unknown obstacle or an allowed
            collision pair an unknown link (see CollisionWorld). */
        explicit ManipulationValidityChecker(const ompl::base::SpaceInformationPtr &si);

        /** OMPL's hook: true when the state is valid; counts the query. */
        bool isValid(const ompl::base::State *state) const override;

        /** Why a state is invalid, in words naming the bodies involved; empty when it is valid.
            Does not count as a query. */
        std::string explain(const ompl::base::State *state) const;

        /** Number of isValid() calls since construction or resetCounters(). */
        std::uint64_t queryCount() const { return queries_; }
        /** Number of those calls that found the state valid. */
        std::uint64_t freeQueryCount() const { return freeQueries_; }
        /** Sets both counters to 0. */
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
