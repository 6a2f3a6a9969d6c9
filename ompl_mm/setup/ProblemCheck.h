#pragma once

#include "ompl_mm/collision/CollisionWorld.h"
#include "ompl_mm/primitives/EmptySpacePlanner.h"
#include "ompl_mm/primitives/Primitive.h"

#include <functional>
#include <vector>

namespace ompl_mm
{
    /** What can be decided about a manipulation problem before any planning, each fault reported
        as an ompl_core::InputError at the scene line it comes from, so that an impossible problem
        fails at once instead of running to the time limit:
        - the start: which object (or the robot) collides with what;
        - the goal: an object's goal pose, or the robot's goal (when every joint is given), in
          collision with obstacles; goal poses that overlap each other; an object whose goal is
          away from its start but that no primitive of the scene can move there (the empty-space
          planner, obstacles aside, cannot chain primitives that get it there, directly or picked
          up and set down again).
        Only fully given goal poses are checked for collisions (x and y given; z and yaw default to
        the start's); objects without a goal are left out, since they may be moved away. */
    class ProblemCheck
    {
    public:
        /** Checks for the problem of space's model. @pre space outlives the check. */
        explicit ProblemCheck(const ManipulationStateSpace &space);

        /** Throws when the start, found invalid for `reason`, has a collision: at the line of the
            object involved (the robot's start line for the robot alone), else at the robot's
            start line with reason. */
        [[noreturn]] void rejectStart(const ompl::base::State *start, const std::string &reason) const;

        /** Times the empty-space planner tries to move an object to its goal before the goal
            counts as impossible: its inverse kinematics is random, and a tight placement may need
            many tries; a reachable goal takes a few, an impossible one all (about 1.5 ms each on
            MEKA CLEAN-UP). 100 tries declared MEKA CLEAN-UP's reachable goal impossible for 10 of
            3000 seeds; 400 for none. */
        static constexpr unsigned int REACH_ATTEMPTS = 400;

        /** How far above its goal an object is held on the way there when the primitives cannot
            move it there directly (carriesThere()), metres: off its surface, below most shelves. */
        static constexpr double CARRY_HEIGHT = 0.1;

        /** Throws at the goal's line when the goal is impossible in one of the ways above. */
        void checkGoal(const ompl::base::State *start, const std::vector<PrimitivePtr> &primitives) const;

    private:
        /** Whether the planner, in one of REACH_ATTEMPTS tries from `from` towards `to`, ends
            where `arrived` says; trajectory holds the last try. */
        bool tries(EmptySpacePlanner &planner, const ompl::base::State *from, const ompl::base::State *to,
                   ompl::RNG &rng, Trajectory &trajectory,
                   const std::function<bool(const ompl::base::State *)> &arrived) const;
        /** Whether the planner, in one of REACH_ATTEMPTS tries from `from` towards `to`, leaves
            `object` at its pose in `to` (the robot may end elsewhere); trajectory holds the last
            try. */
        bool movesThere(EmptySpacePlanner &planner, const ompl::base::State *from,
                        const ompl::base::State *to, unsigned int object, ompl::RNG &rng,
                        Trajectory &trajectory) const;
        /** Whether the object reaches its pose in `to` picked up (the pickups of `lifting` heading
            for the object CARRY_HEIGHT above it, until it is off its surface) and set down there
            (the planner). A slide shorter than a pickup's min_plane_distance is for pushes alone
            (Pickup::mustRise), so a robot whose pushes cannot make it would be found unable to
            move the object, which picking it up and putting it down again does. */
        bool carriesThere(EmptySpacePlanner &lifting, EmptySpacePlanner &planner,
                          const ompl::base::State *from, const ompl::base::State *to, unsigned int object,
                          ompl::RNG &rng, Trajectory &trajectory) const;
        /** The goal pose of an object whose goal gives x and y (z and yaw from start where not
            given), or nothing. */
        std::optional<ObjectPose> goalPose(const ObjectGoal &goal, const ompl::base::State *start) const;
        /** The first collision among the robot (at joints, or left out when null) and the given
            object poses, checked alone, in pairs and with the robot; throws it at its line with
            the message's beginning. */
        void rejectCollisions(const double *joints, const ompl_core::SourceLocation &robotWhere,
                              const std::vector<std::optional<ObjectPose>> &poses,
                              const std::vector<ompl_core::SourceLocation> &wheres, const std::string &what,
                              const std::string &when) const;

        const ManipulationStateSpace &space_;
        CollisionWorld world_;
    };
}  // namespace ompl_mm
