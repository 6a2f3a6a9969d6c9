#pragma once

#include "ompl_mm/geometric/ManipulationMotionValidator.h"
#include "ompl_mm/geometric/ManipulationPath.h"
#include "ompl_mm/geometric/TransitConnector.h"

#include <ompl/base/Goal.h>
#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/util/RandomNumbers.h>

#include <memory>
#include <vector>

namespace ompl_mm
{
    /** Puts new states in place of a stretch of a manipulation path: an object kept elsewhere than
        the path had it, or new primitives' waypoints, each motion between the states kept as it
        is when valid, else the robot routed around what its old motion now meets (a seeded
        RRT-Connect in joint space, TransitConnector). The smoothing steps of
        ManipulationSimplifier and PushReversalRemover rest on it. */
    class PathRouter
    {
    public:
        /** RRT iterations to route the robot around an object it no longer pushes (after a round
            trip or a push reversal is removed). */
        static constexpr unsigned int CONNECT_ITERATIONS = 500;

        /** A router for paths in si whose motions validator checks (and explains). */
        PathRouter(const ompl::base::SpaceInformationPtr &si,
                   std::shared_ptr<ManipulationMotionValidator> validator);

        /** Keeps `object` at `pose` in states first … last (the path's states elsewhere unchanged):
            its pushes become the robot's transits, and where the robot's old motion meets the
            object it is routed around it (within routeIterations and until ptc is true). True when
            that gives valid motions and the end still satisfies goal (the path then changed). */
        bool holdObject(ManipulationPath &path, unsigned int object, const ObjectPose &pose,
                        std::size_t first, std::size_t last, const ompl::base::Goal *goal,
                        unsigned int routeIterations, ompl::RNG &rng,
                        const ompl::base::PlannerTerminationCondition &ptc) const;
        /** Appends copies of path's states first … last with `object` at pose to states. */
        void appendHeld(const ManipulationPath &path, std::size_t first, std::size_t last,
                        unsigned int object, const ObjectPose &pose,
                        std::vector<ompl::base::State *> &states) const;
        /** Appends copies of trajectory's states from first on to states. */
        void appendCopies(const Trajectory &trajectory, std::size_t first,
                          std::vector<ompl::base::State *> &states) const;
        /** Frees the states and empties the vector. */
        void freeAll(std::vector<ompl::base::State *> &states) const;
        /** Chains states (routeThrough) and, when that works, puts the result in place of path's
            states first … last; frees the states (and empties the vector) either way. */
        bool replaceRouted(ManipulationPath &path, std::size_t first, std::size_t last,
                           std::vector<ompl::base::State *> &states, unsigned int routeIterations,
                           ompl::RNG &rng, const ompl::base::PlannerTerminationCondition &ptc) const;
        /** Chains the motions between consecutive states into result (reset to the first state):
            each motion as it is when valid; else the robot routed (TransitConnector, within
            routeIterations and until ptc is true) to the next valid state that only the robot's
            motions lead to. False when neither works for some motion. */
        bool routeThrough(const std::vector<ompl::base::State *> &states, Trajectory &result,
                          unsigned int routeIterations, ompl::RNG &rng,
                          const ompl::base::PlannerTerminationCondition &ptc) const;

    private:
        ompl::base::SpaceInformationPtr si_;
        const ManipulationStateSpace *space_;
        std::shared_ptr<ManipulationMotionValidator> validator_;
        TransitConnector connector_;
    };
}  // namespace ompl_mm
