#pragma once

#include "ompl_mm/base/ManipulationGoal.h"
#include "ompl_mm/base/PartialState.h"

#include <ompl/util/RandomNumbers.h>

#include <vector>

namespace ompl_mm
{
    /** MOPL's sampling of partially defined configurations (paper, section III-B.2; cited at
        MOPL). With probability Probabilities::object one object is sampled on a support surface (at
        its start yaw) or, when enabled (setSampleInAir), in a sampling region "in the air" (the
        place chosen uniformly among surfaces and regions; the robot then left undefined until a
        grasp of the object is found, PartialState::graspedObject), and the robot and every other
        object are each left undefined, set to their start value, or set to their goal value;
        otherwise the robot is sampled (uniformly, or at the far end of the search: the goal pose
        for the forward tree, the start pose for the backward tree) and the objects are chosen the
        same way. A goal value the goal does not define is left undefined.

        Objects the goal leaves free are always left undefined in samples for the forward tree (an
        object sample still places them anywhere): they take the nearest vertex's values, so the
        metric does not charge the vertices that have pushed them out of the way.

        Objects in play: those the goal constrains and those a tree vertex has moved from their
        start (noteVertex). An object sample picks among the objects in play, or with
        Probabilities::anyObject among all objects (always, while every object is in play or none
        is); an object not in play stands at its start in every vertex, so samples for the backward
        tree set it there (and so do the goal roots made from them, which would otherwise scatter
        it). So objects that do not matter to the task cost the search little, and every object
        keeps a chance to be sampled. */
    class ModalSampler
    {
    public:
        /** Probabilities of the sampling choices; defaults are the paper's. undefined + startValue
            must not exceed 1 (MOPL::setup() checks). */
        struct Probabilities
        {
            double object{0.6};       ///< sample one object (else the robot)
            double undefined{0.4};    ///< leave a part undefined
            double startValue{0.3};   ///< set a part to its start value (the rest: goal value)
            double randomRobot{0.8};  ///< a sampled robot is uniform (else the far end's pose)
            /** an object sample picks among all objects (else among those in play); > 0 */
            double anyObject{1.0};
        };

        /** A sampler for the problem of goal, with the paper's probabilities. It copies start (the
            start state) and goalState (a goal state whose goal-constrained parts are the goal
            values). @pre space and goal outlive the sampler; the scene has a support surface when
            it has objects. */
        ModalSampler(const ManipulationStateSpace *space, const ManipulationGoal *goal,
                     const ompl::base::State *start, const ompl::base::State *goalState);
        /** Frees its copies of the states. */
        ~ModalSampler();
        ModalSampler(const ModalSampler &) = delete;             ///< not copyable
        ModalSampler &operator=(const ModalSampler &) = delete;  ///< not copyable

        /** The probabilities in use, to change. */
        Probabilities &probabilities() { return probabilities_; }
        /** Lets objects be sampled in the scene's sampling regions (for robots that can grasp them). */
        void setSampleInAir(bool sampleInAir) { sampleInAir_ = sampleInAir; }

        /** Draws a partial sample for the forward (start) or backward (goal) tree into out. */
        void sample(PartialState &out, bool forwardTree, ompl::RNG &rng) const;

        /** Puts in play the objects that state (a new tree vertex) has moved from their start. */
        void noteVertex(const ompl::base::State *state);
        /** True when the object is in play. */
        bool inPlay(unsigned int object) const { return inPlay_[object] != 0; }

    private:
        void putInPlay(unsigned int object);
        /** The object of an object sample. */
        unsigned int chooseObject(ompl::RNG &rng) const;
        /** Sets one part (0 robot, 1 + i object i) of a sample for the forward or backward tree to
            undefined, its start or its goal value. */
        void chooseFixedValue(PartialState &out, unsigned int part, bool forwardTree, ompl::RNG &rng) const;
        /** Samples the object on a surface or, when enabled, in a region; true when in a region. */
        bool sampleObject(PartialState &out, unsigned int object, ompl::RNG &rng) const;
        void sampleRobot(PartialState &out, bool forwardTree, ompl::RNG &rng) const;

        const ManipulationStateSpace *space_;
        const ManipulationGoal *goal_;
        ompl::base::State *start_;
        ompl::base::State *goalState_;
        Probabilities probabilities_;
        bool sampleInAir_{false};
        std::vector<char> inPlay_;                 ///< per object
        std::vector<unsigned int> inPlayObjects_;  ///< the objects in play, in the order put in play
    };
}  // namespace ompl_mm
