/* The goal of a manipulation problem: targets for some robot joints and some object
   coordinates, every other coordinate "don't care", and every object resting on a surface.
   Besides testing states, it completes partial samples into goal states (MOPL's PROJSAMP),
   which is how the backward tree gets its roots lazily. */
#pragma once

#include "ompl_mm/base/PartialState.h"

#include <ompl/base/goals/GoalRegion.h>
#include <ompl/util/RandomNumbers.h>

namespace ompl_mm
{
    class ManipulationGoal : public ompl::base::GoalRegion
    {
    public:
        /** Reads the targets from the model's scene.
            @throws ompl_core::InputError naming the scene line when a target is impossible: wrong number of
            joints, a joint target outside its limits, or an object target on no support surface. */
        explicit ManipulationGoal(const ompl::base::SpaceInformationPtr &si);

        /** Largest amount by which a defined coordinate misses its tolerance (0 inside the goal),
            plus 1 for every object that rests on no surface. */
        double distanceGoal(const ompl::base::State *state) const override;

        /** True when every defined coordinate is within its tolerance and all objects rest
            (distanceGoal() is 0; the inherited threshold is not used). */
        bool isSatisfied(const ompl::base::State *state) const override;
        bool isSatisfied(const ompl::base::State *state, double *distance) const override;

        /** A goal state nearest to the sample (PROJSAMP): goal coordinates where defined, else the
            sample's defined parts, else random values (objects on a random surface).
            @pre sample's undefined parts may hold anything. */
        void complete(const PartialState &sample, ompl::base::State *out, ompl::RNG &rng) const;

        /** True when the goal defines at least one coordinate of the object. */
        bool constrainsObject(unsigned int object) const;
        /** True when the goal defines at least one robot joint. */
        bool constrainsRobot() const;

        void print(std::ostream &out) const override;

    private:
        /** Fills the don't-care coordinates of an object whose goal defines only some. */
        void completeObject(unsigned int object, const ObjectPose *fromSample, ObjectPose &pose,
                            ompl::RNG &rng) const;

        const ManipulationStateSpace *space_;
        RobotGoal robot_;
        std::vector<const ObjectGoal *> objects_;  ///< per object, its goal or nullptr
    };
}  // namespace ompl_mm
