#pragma once

#include "ompl_mm/base/PartialState.h"

#include <ompl/base/goals/GoalSampleableRegion.h>
#include <ompl/util/RandomNumbers.h>

namespace ompl_mm
{
    /** The goal of a manipulation problem: targets for some robot joints and some object
        coordinates, every other coordinate "don't care", and every object resting on a surface.
        Besides testing states, it completes partial samples into goal states (MOPL's PROJSAMP),
        which is how the backward tree gets its roots lazily. Planners that sample goals (OMPL's
        RRTConnect, PRM) get goal states whose free objects stay at their start poses. */
    class ManipulationGoal : public ompl::base::GoalSampleableRegion
    {
    public:
        /** Reads the targets from the model's scene; sets the threshold to 0.
            @pre si's state space is a ManipulationStateSpace.
            @throws ompl_core::InputError naming the scene line when a target is impossible: wrong number
            of joints, a joint target outside its limits, an unknown object, or an object target on no
            support surface. */
        explicit ManipulationGoal(const ompl::base::SpaceInformationPtr &si);

        /** OMPL's hook: largest amount by which a defined coordinate misses its tolerance (metres or
            radians, 0 inside the goal), plus 1 for every object that rests on no surface; infinity
            for a state with a non-finite value. */
        double distanceGoal(const ompl::base::State *state) const override;

        /** OMPL's hook: true when every defined coordinate is within its tolerance and all objects
            rest (distanceGoal() is 0; the inherited threshold is not used). */
        bool isSatisfied(const ompl::base::State *state) const override;
        /** OMPL's hook: as isSatisfied(state), also writing distanceGoal() to *distance when
            distance is not null. */
        bool isSatisfied(const ompl::base::State *state, double *distance) const override;

        /** A goal state nearest to the sample (PROJSAMP), written to out: goal coordinates where
            defined, else the sample's defined parts (an object's only when it rests), else random
            values (joints within their limits; objects on a random surface their goal allows, with
            their start yaw). With keepNearValues, an object coordinate the goal defines keeps the
            sample's value when that is already within the goal's tolerance: where simulated
            primitives leave objects near, not on, their goal values, goal states can match them.
            @pre sample's undefined parts may hold anything. */
        void complete(const PartialState &sample, ompl::base::State *out, ompl::RNG &rng,
                      bool keepNearValues = false) const;

        /** OMPL's hook: a goal state in which every object the goal leaves free keeps its start
            pose (where the scene starts it) and free joints are random within their limits. */
        void sampleGoal(ompl::base::State *state) const override;
        /** OMPL's hook: goal states can be drawn without end. */
        unsigned int maxSampleCount() const override;

        /** True when the goal defines at least one coordinate of the object. */
        bool constrainsObject(unsigned int object) const;
        /** True when the goal defines at least one robot joint. */
        bool constrainsRobot() const;

        /** OMPL's hook: names what the goal constrains (robot joints, objects) on one line. */
        void print(std::ostream &out) const override;

    private:
        /** Fills the don't-care coordinates of an object whose goal defines only some. */
        void completeObject(unsigned int object, const ObjectPose *fromSample, ObjectPose &pose,
                            ompl::RNG &rng, bool keepNearValues) const;

        const ManipulationStateSpace *space_;
        mutable ompl::RNG rng_;  ///< draws sampleGoal()'s free joints
        RobotGoal robot_;
        std::vector<const ObjectGoal *> objects_;  ///< per object, its goal or nullptr
    };
}  // namespace ompl_mm
