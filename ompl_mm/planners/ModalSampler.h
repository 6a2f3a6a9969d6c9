/* MOPL's sampling of partially defined configurations (paper, section III-B.2). With probability
   objectProbability one object is sampled on a support surface and the robot and every other
   object are each left undefined, set to their start value, or set to their goal value; otherwise
   the robot is sampled (uniformly, or at the far end of the search: the goal pose for the forward
   tree, the start pose for the backward tree) and the objects are chosen the same way. */
#pragma once

#include "ompl_mm/base/ManipulationGoal.h"
#include "ompl_mm/base/PartialState.h"

#include <ompl/util/RandomNumbers.h>

namespace ompl_mm
{
    class ModalSampler
    {
    public:
        /** Probabilities of the sampling choices; defaults are the paper's. */
        struct Probabilities
        {
            double object{0.6};       ///< sample one object (else the robot)
            double undefined{0.4};    ///< leave a part undefined
            double startValue{0.3};   ///< set a part to its start value (the rest: goal value)
            double randomRobot{0.8};  ///< a sampled robot is uniform (else the far end's pose)
        };

        /** @param start the start state; @param goalState a goal state whose goal-constrained parts
            are the goal values. */
        ModalSampler(const ManipulationStateSpace *space, const ManipulationGoal *goal,
                     const ompl::base::State *start, const ompl::base::State *goalState);
        ~ModalSampler();
        ModalSampler(const ModalSampler &) = delete;
        ModalSampler &operator=(const ModalSampler &) = delete;

        Probabilities &probabilities() { return probabilities_; }

        /** Draws a partial sample for the forward (start) or backward (goal) tree. */
        void sample(PartialState &out, bool forwardTree, ompl::RNG &rng) const;

    private:
        /** Sets one part (0 robot, 1 + i object i) to undefined, its start or its goal value. */
        void chooseFixedValue(PartialState &out, unsigned int part, ompl::RNG &rng) const;
        void sampleObjectOnSurface(PartialState &out, unsigned int object, ompl::RNG &rng) const;
        void sampleRobot(PartialState &out, bool forwardTree, ompl::RNG &rng) const;

        const ManipulationStateSpace *space_;
        const ManipulationGoal *goal_;
        ompl::base::State *start_;
        ompl::base::State *goalState_;
        Probabilities probabilities_;
    };
}  // namespace ompl_mm
