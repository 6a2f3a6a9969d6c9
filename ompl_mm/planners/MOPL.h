#pragma once

#include "ompl_mm/base/ManipulationGoal.h"
#include "ompl_mm/geometric/ManipulationPath.h"
#include "ompl_mm/geometric/ManipulationSimplifier.h"
#include "ompl_mm/geometric/TransitConnector.h"
#include "ompl_mm/planners/ManipulationTree.h"
#include "ompl_mm/planners/ModalSampler.h"
#include "ompl_mm/primitives/EmptySpacePlanner.h"
#include "ompl_mm/primitives/Pickup.h"

#include <ompl/base/Planner.h>

#include <cstdint>
#include <memory>

namespace ompl_mm
{
    /** connect_step's lowest value (metres or radians): every interpolation and tool-path
        measurement takes length / step steps, so a finer step would only cost time. */
    constexpr double MIN_CONNECT_STEP = 0.001;
    /** connect_step's highest value: continuous motion checks make a coarser step safe, but a walk
        blocked short of a contact would rarely have that much to keep. */
    constexpr double MAX_CONNECT_STEP = 1.0;
    /** vertex_step's lowest value (metres or radians): tree vertices come at least this far apart. */
    constexpr double MIN_VERTEX_STEP = 0.01;
    /** vertex_step's highest value. */
    constexpr double MAX_VERTEX_STEP = 10.0;
    /** any_object_probability's lowest value: objects out of play must keep a chance to be sampled,
        or the planner would lose its completeness. */
    constexpr double MIN_ANY_OBJECT_PROBABILITY = 0.01;
    /** clear_radius's lowest value (metres): a shorter push would rarely clear a way. */
    constexpr double MIN_CLEAR_RADIUS = 0.01;
    /** clear_radius's highest value (metres). */
    constexpr double MAX_CLEAR_RADIUS = 100.0;

    /** Where the planner spent its effort (times in seconds). Times, iterations and restarts add
        up over the solve() calls since the last clear(); the collision query counts are those of
        the last solve(). */
    struct MOPLStatistics
    {
        double samplingTime{0.0};   ///< drawing partial samples (and goal completion for the goal tree)
        double nearestTime{0.0};    ///< nearest-neighbour search in the trees
        double propagateTime{0.0};  ///< empty-space planning (primitives' propagate)
        double connectTime{0.0};    ///< collision-checked walks along propagated trajectories
        double smoothingTime{0.0};  ///< simplifying the solution (ManipulationSimplifier)
        double ikTime{0.0};  ///< inverse kinematics of primitives and grasp samples (part of the times above)
        std::uint64_t iterations{0};  ///< iterations of the search loop, one sample each
        std::uint64_t restarts{0};    ///< times the trees were cleared (see MOPL::setRestartIterations)
        /** objects in the way the start tree tried to push aside (clear_probability) */
        std::uint64_t clearings{0};
        std::uint64_t collisionQueries{0};      ///< state validity queries (of a ManipulationValidityChecker)
        std::uint64_t freeCollisionQueries{0};  ///< those that found the state valid
    };

    /** MOPL, the multi-modal path planner: a bidirectional RRT over robot × object configurations
        whose extensions chain manipulation primitives through an empty-space planner, whose samples
        leave parts undefined (resolved by the nearest neighbour), and whose goal tree gets its
        roots lazily by completing partial goals (PROJSAMP). Solutions are ManipulationPath objects
        simplified by ManipulationSimplifier (carries that only slide pushed, pointless pushes
        removed, windows replanned).

        Use with a ManipulationStateSpace, a ManipulationValidityChecker and a ManipulationGoal
        (ManipulationSetup wires them). Requires primitives (setPrimitives) before setup(). Declared
        parameters: connect_step, vertex_step, restart_iterations, smoothing_attempts, the metric's
        weights (robot_weight, joint_weight, base_joint_weight, tool_weight, rotation_weight,
       moving_object_penalty, move_to_object_penalty, move_to_object_factor, contact_distance) and the
       sampler's probabilities (object_sample_probability, undefined_probability, start_value_probability,
        random_robot_probability, each in [0, 1], and any_object_probability, in
        [MIN_ANY_OBJECT_PROBABILITY, 1]; see ModalSampler) and the clearing of
        objects in the way (clear_probability, clear_radius, clear_min_free_objects).

        Clearing: when an object stops a motion of the start tree, the planner pushes it, with probability
        clear_probability, to a random place at most clear_radius away on its surface (robot back where it
        was), as an extension from where the motion stopped, and then tries the motion's target again from
        there. It is used when the goal leaves at least clear_min_free_objects objects free: among
        many objects the sampler rarely picks the one in the way, and clearing is what gets through;
        among few it picks each often, and clearing only scatters the objects that the goal tree's
        layouts must match.

        Simulated primitives (Primitive::endsWhereAsked() false, e.g. physics-aware pushes): the goal
        tree leaves them out, and once a start-tree vertex holds every object where the goal wants it,
        the robot's transit to the goal is planned from there (transitToGoal()).

        @par External documentation
        S. Jentzsch, A. Gaschler, O. Khatib, A. Knoll, "MOPL: A multi-modal path planner for generic
        manipulation tasks", IEEE/RSJ International Conference on Intelligent Robots and Systems
        (IROS), 2015, pp. 6208–6214. DOI 10.1109/IROS.2015.7354263,
        https://doi.org/10.1109/IROS.2015.7354263 */
    class MOPL : public ompl::base::Planner
    {
    public:
        /** A planner on si with the given primitives (shared); sets the state space's segment
            resolution to the default connect step.
            @throws ompl::Exception when si's state space is not a ManipulationStateSpace. */
        MOPL(const ompl::base::SpaceInformationPtr &si, std::vector<PrimitivePtr> primitives = {});
        /** Frees the trees and their states. */
        ~MOPL() override;

        /** Replaces the primitives (shared with the caller); the planner must be set up again. */
        void setPrimitives(std::vector<PrimitivePtr> primitives);
        /** The primitives the empty-space planner chains. */
        const std::vector<PrimitivePtr> &getPrimitives() const { return primitives_; }

        /** Seeds this planner's own random numbers, so several planners in one process are each
            reproducible (ompl::RNG::setSeed seeds only generators made afterwards). */
        void setSeed(std::uint_fast32_t seed) { rng_.setLocalSeed(seed); }

        /** The shortest stretch a walk blocked short of a contact keeps as a new vertex (metres or
            radians); 0.05 by default. Motions are checked continuously whatever it is. Also sets
            the state space's segment resolution (ManipulationStateSpace::setSegmentResolution).
            @throws ompl::Exception when step is outside [MIN_CONNECT_STEP, MAX_CONNECT_STEP]. */
        void setConnectStep(double step);
        /** The shortest stretch a blocked walk keeps (metres or radians). */
        double getConnectStep() const { return connectStep_; }
        /** A tree vertex is added every this much motion along an extension (metres or radians:
            the larger of the joint-space distance and any object's displacement); 0.35 by default.
            @throws ompl::Exception when step is outside [MIN_VERTEX_STEP, MAX_VERTEX_STEP]. */
        void setVertexStep(double step);
        /** Motion between tree vertices along an extension (metres or radians). */
        double getVertexStep() const { return vertexStep_; }
        /** Iterations after which the search starts again from the start state with empty trees;
            each later run may last twice as long, so the planner stays probabilistically
            complete while the heavy tail of its run time is cut. 0 never restarts; 10000 by
            default. */
        void setRestartIterations(unsigned int iterations) { restartIterations_ = iterations; }
        /** Iterations of the first run before a restart; 0 when the planner never restarts. */
        unsigned int getRestartIterations() const { return restartIterations_; }
        /** Probability of pushing aside an object that stops a motion of the start tree (see the
            class); 1 by default (0 never clears).
            @throws ompl::Exception outside [0, 1]. */
        void setClearProbability(double probability);
        /** Probability of pushing aside an object in the way. */
        double getClearProbability() const { return clearProbability_; }
        /** Farthest an object in the way is pushed aside (metres); 1 by default.
            @throws ompl::Exception outside [MIN_CLEAR_RADIUS, MAX_CLEAR_RADIUS]. */
        void setClearRadius(double radius);
        /** Farthest an object in the way is pushed aside (metres). */
        double getClearRadius() const { return clearRadius_; }
        /** Clearing is used only when the goal leaves at least this many objects free (see the
            class); 4 by default, 0 clears in every scene. */
        void setClearMinFreeObjects(unsigned int objects) { clearMinFreeObjects_ = objects; }
        /** Objects the goal must leave free for clearing to be used. */
        unsigned int getClearMinFreeObjects() const { return clearMinFreeObjects_; }
        /** Random windows of the solution that ManipulationSimplifier tries to replan; 30 by default. */
        void setSmoothingAttempts(unsigned int attempts) { smoothingAttempts_ = attempts; }
        /** Random windows of the solution that ManipulationSimplifier tries to replan. */
        unsigned int getSmoothingAttempts() const { return smoothingAttempts_; }

        /** The metric's weights (each also a declared parameter). */
        const ManipulationMetric::Weights &metricWeights() const { return metric_->weights(); }
        /** Sets the metric's weights. */
        void setMetricWeights(const ManipulationMetric::Weights &weights) { metric_->setWeights(weights); }

        /** OMPL's hook: grows the start and goal trees in turn until the start tree reaches the goal
            or the trees connect (EXACT_SOLUTION, a ManipulationPath added to the problem
            definition) or ptc ends (TIMEOUT). Returns UNRECOGNIZED_GOAL_TYPE when the goal is not a
            ManipulationGoal and INVALID_START without a valid start state. A later call goes on
            with the same trees. ptc is evaluated once per iteration, as OMPL's planners do, and
            within the iteration's steps through a StepTermination view of it (which evaluates it
            again only once a step has lasted a millisecond, so an iteration-counting condition
            counts iterations): the empty-space planner between primitives and their inverse
            kinematics attempts, the walks between pieces and within each continuous collision
            check, and the smoothing of a solution found (which shares the time limit: it stops
            when ptc is true, keeping the valid path smoothed so far). So the call returns within
            milliseconds of a time limit (one distance round of a collision check, one inverse
            kinematics solve or one nearest-neighbour search) whatever the robot's meshes. */
        ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;
        /** OMPL's hook: empties both trees and resets the statistics. */
        void clear() override;
        /** OMPL's hook: makes the empty-space planner, the simplifier and empty trees.
            @throws ompl::Exception without primitives, when checkParameters() does, or without a
            ManipulationMotionValidator on the space information (ManipulationSetup installs one). */
        void setup() override;
        /** The rules between parameters, which no single parameter's range can state.
            @throws ompl::Exception when undefined_probability + start_value_probability exceeds 1. */
        void checkParameters() const;
        /** True when checkParameters() reads the parameter called name (a rule it breaks is that
            parameter's to report). */
        static bool checksParameter(const std::string &name);
        /** OMPL's hook: the vertices and edges of both trees (tag 1: start tree, tag 2: goal tree;
            edges point in the direction of motion) and the statistics as properties. */
        void getPlannerData(ompl::base::PlannerData &data) const override;

        /** Where the planner spent its effort. */
        const MOPLStatistics &statistics() const { return statistics_; }

        /** How its primitives fared since the last clear(): attempts, motions found, motions the
            walks found stopped and by which contact (empty before setup()). A solve that finds no
            solution logs the kinds that never succeeded (PrimitiveTally::failureSummary()). */
        const PrimitiveTally &primitiveTally() const;

    private:
        /** Outcome of one tree extension. */
        struct Extension
        {
            int last{-1};            ///< last vertex added, or the vertex equal to the target
            bool reached{false};     ///< the tree now contains the target state
            int blockingObject{-1};  ///< the object that stopped the walk (SweepCheck::blockingObject)
        };
        /** Iterations of the robot's transit planning to the goal from a layout of the objects
            that meets it (transitToGoal). */
        static constexpr unsigned int GOAL_TRANSIT_ITERATIONS = 2000;
        /** Random places tried for an object pushed aside before giving up (off its surface). */
        static constexpr unsigned int CLEAR_PLACE_ATTEMPTS = 20;

        void declareParameters();
        /** Nearest vertex of tree to sample; for the goal tree a completed goal state competes and
            is added as a root when it wins. Sets *newRoot when it added one. */
        int nearest(ManipulationTree &tree, PartialState &sample, bool *newRoot);
        /** Extends tree from vertex near towards target: the empty-space planner's trajectory,
            walked with continuous checks. Both stop where they are once ptc is true. */
        Extension extend(ManipulationTree &tree, int near, const ompl::base::State *target,
                         const ompl::base::PlannerTerminationCondition &ptc);
        /** The primitive kind a walk's contact on segment of trajectory counts against: the
            segment's own, or for a transit, that of the next segment that is no transit (it
            approaches it), or transit when none follows. */
        static PrimitiveKind blamedKind(const Trajectory &trajectory, std::size_t segment);
        /** Walks the trajectory away from vertex near, adding vertices, until it ends, a motion
            collides or ptc is true (then not reached). */
        Extension walk(ManipulationTree &tree, int near, const Trajectory &trajectory,
                       const ompl::base::PlannerTerminationCondition &ptc);
        /** True when a primitive explains the motion between walk states `from` and `to` in the
            path's direction: from to to in the start tree, to to from in the goal tree. */
        bool isMotion(const ompl::base::State *from, const ompl::base::State *to, bool forward) const;
        /** True when the sample defines every object and state has each where the sample does. */
        bool keepsSampleObjects(const PartialState &sample, const ompl::base::State *state) const;
        /** Extends tree from vertex from towards the object pushed to a random place within the
            clear radius (target: scratch space); an empty extension when no place fits. */
        Extension clearWay(ManipulationTree &tree, int from, unsigned int object, ompl::base::State *target,
                           const ompl::base::PlannerTerminationCondition &ptc);
        /** With simulated primitives: when start-tree vertex `vertex` holds every object where the
            goal wants it and only the robot is elsewhere, plans the robot's transit to the goal
            (TransitConnector, GOAL_TRANSIT_ITERATIONS) and walks it. The goal tree cannot do this
            itself, since its roots would need the objects exactly where physics left them. Each
            layout of the objects is tried once: every vertex with the same layout lies in the same
            free space of the robot. Returns the vertex where the walk ends in the goal, or -1. */
        int transitToGoal(int vertex, const ompl::base::PlannerTerminationCondition &ptc);
        /** Objects the goal leaves free (clear_min_free_objects compares with it). */
        unsigned int freeObjectCount() const;
        /** After an extension from near that an object stopped: clears the object out of the way and
            extends towards target again; the extension that got farthest. */
        Extension clearAndRetry(ManipulationTree &tree, int near, const Extension &stopped,
                                const ompl::base::State *target, ompl::base::State *scratch,
                                const ompl::base::PlannerTerminationCondition &ptc);
        double segmentLength(const ompl::base::State *a, const ompl::base::State *b) const;
        /** Builds, smooths (until ptc is true: the smoothing shares the planner's time limit) and
            records the solution through forward vertex f and goal vertex g. */
        void addSolution(int f, int g, const ompl::base::PlannerTerminationCondition &ptc);
        /** Clears both trees but the start. */
        void restart();
        /** Gives a sample of an object in the air its robot joints: a grasp of the object found by
            inverse kinematics seeded from vertex near of tree. False when there is none. */
        bool graspSample(PartialState &sample, const ManipulationTree &tree, int near);
        /** True when more than one object rests on no surface in state (no robot holds two). */
        bool holdsTwo(const ompl::base::State *state) const;
        /** Total inverse kinematics time of the primitives, seconds. */
        double ikTimeSoFar() const;

        std::vector<PrimitivePtr> primitives_;
        const Pickup *pickup_{nullptr};  ///< grasps the objects of samples in the air; null: no such samples
        double ikTimeAtClear_{0.0};      ///< ikTimeSoFar() when the statistics were last reset
        const ManipulationStateSpace *space_{nullptr};
        std::unique_ptr<ManipulationMetric> metric_;
        std::unique_ptr<EmptySpacePlanner> esp_;
        bool simulatedPrimitives_{false};  ///< some primitive does not end where asked
        /** checks the walks' motions continuously: the space information's validator */
        std::shared_ptr<ManipulationMotionValidator> motions_;
        std::unique_ptr<ManipulationSimplifier> simplifier_;
        std::unique_ptr<TransitConnector> goalTransit_;  ///< plans transitToGoal()'s motions
        /** the layouts of the objects (x, y, z, yaw of each) transitToGoal() has tried */
        std::vector<std::vector<double>> goalLayoutsTried_;
        std::unique_ptr<ModalSampler> sampler_;
        ModalSampler::Probabilities probabilities_;
        std::unique_ptr<ManipulationTree> startTree_;
        std::unique_ptr<ManipulationTree> goalTree_;
        const ManipulationGoal *goal_{nullptr};
        ManipulationMetric::Query query_;  ///< reused by nearest() to avoid allocations
        ompl::RNG rng_;
        double connectStep_{0.05};
        double vertexStep_{0.35};
        unsigned int smoothingAttempts_{30};
        unsigned int restartIterations_{10000};
        double clearProbability_{1.0};
        double clearRadius_{1.0};
        unsigned int clearMinFreeObjects_{4};
        MOPLStatistics statistics_;
    };
}  // namespace ompl_mm
