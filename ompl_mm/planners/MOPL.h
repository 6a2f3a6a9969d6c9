/* MOPL, the multi-modal path planner: a bidirectional RRT over robot × object configurations
   whose extensions chain manipulation primitives through an empty-space planner, whose samples
   leave parts undefined (resolved by the nearest neighbour), and whose goal tree gets its roots
   lazily by completing partial goals (PROJSAMP). Solutions are ManipulationPath objects.
   S. Jentzsch, A. Gaschler, O. Khatib, A. Knoll, "MOPL: A multi-modal path planner for generic
   manipulation tasks", IEEE/RSJ IROS 2015. */
#pragma once

#include "ompl_mm/base/ManipulationGoal.h"
#include "ompl_mm/geometric/ManipulationPath.h"
#include "ompl_mm/planners/EmptySpacePlanner.h"
#include "ompl_mm/planners/ManipulationTree.h"
#include "ompl_mm/planners/ModalSampler.h"

#include <ompl/base/Planner.h>

#include <cstdint>
#include <memory>

namespace ompl_mm
{
    /** Where the planner spent its effort in the last solve() (times in seconds). */
    struct MOPLStatistics
    {
        double samplingTime{0.0};   ///< drawing partial samples
        double nearestTime{0.0};    ///< nearest-neighbour search (including goal completion)
        double propagateTime{0.0};  ///< empty-space planning (primitives' propagate)
        double connectTime{0.0};    ///< collision-checked walks along propagated trajectories
        double smoothingTime{0.0};  ///< shortcutting the solution
        std::uint64_t iterations{0};
        std::uint64_t restarts{0};          ///< times the trees were cleared (see MOPL::setRestartIterations)
        std::uint64_t collisionQueries{0};  ///< state validity queries
        std::uint64_t freeCollisionQueries{0};  ///< those that found the state valid
    };

    /** Use with a ManipulationStateSpace, a ManipulationValidityChecker and a ManipulationGoal
        (ManipulationSetup wires them). Requires primitives (setPrimitives) before setup(). */
    class MOPL : public ompl::base::Planner
    {
    public:
        MOPL(const ompl::base::SpaceInformationPtr &si, std::vector<PrimitivePtr> primitives = {});
        ~MOPL() override;

        void setPrimitives(std::vector<PrimitivePtr> primitives);
        const std::vector<PrimitivePtr> &getPrimitives() const { return primitives_; }

        /** Seeds this planner's own random numbers, so several planners in one process are each
            reproducible (ompl::RNG::setSeed seeds only generators made afterwards). */
        void setSeed(std::uint_fast32_t seed) { rng_.setLocalSeed(seed); }

        /** Collision-check step along propagated motions (metres or radians); 0.05 by default.
            Also sets the state space's collision resolution (OMPL's motion checks) to the same step. */
        void setConnectStep(double step);
        double getConnectStep() const { return connectStep_; }
        /** A tree vertex is added every this much motion along an extension; 0.35 by default. */
        void setVertexStep(double step);
        double getVertexStep() const { return vertexStep_; }
        /** Iterations after which the search starts again from the start state with empty trees;
            each later run may last twice as long, so the planner stays probabilistically
            complete while the heavy tail of its run time is cut. 0 never restarts; 10000 by
            default. */
        void setRestartIterations(unsigned int iterations) { restartIterations_ = iterations; }
        unsigned int getRestartIterations() const { return restartIterations_; }
        /** Shortcut attempts per run of transit segments of the solution; 100 by default. */
        void setSmoothingAttempts(unsigned int attempts) { smoothingAttempts_ = attempts; }
        unsigned int getSmoothingAttempts() const { return smoothingAttempts_; }

        /** The metric's weights (also declared parameters). */
        ManipulationMetric::Weights &metricWeights() { return metric_->weights(); }

        ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition &ptc) override;
        void clear() override;
        void setup() override;
        void getPlannerData(ompl::base::PlannerData &data) const override;

        const MOPLStatistics &statistics() const { return statistics_; }

    private:
        /** Outcome of one tree extension. */
        struct Extension
        {
            int last{-1};         ///< last vertex added, or the vertex equal to the target
            bool reached{false};  ///< the tree now contains the target state
        };

        void declareParameters();
        /** Nearest vertex of tree to sample; for the goal tree a completed goal state competes and
            is added as a root when it wins. Sets *newRoot when it added one. */
        int nearest(ManipulationTree &tree, PartialState &sample, bool *newRoot);
        Extension extend(ManipulationTree &tree, int near, const ompl::base::State *target);
        Extension walk(ManipulationTree &tree, int near, const Trajectory &trajectory);
        double segmentLength(const ompl::base::State *a, const ompl::base::State *b) const;
        /** Builds, smooths and records the solution through forward vertex f and goal vertex g. */
        void addSolution(int f, int g);
        void smooth(ManipulationPath &path);
        /** Clears both trees but the start. */
        void restart();

        std::vector<PrimitivePtr> primitives_;
        const ManipulationStateSpace *space_{nullptr};
        std::unique_ptr<ManipulationMetric> metric_;
        std::unique_ptr<EmptySpacePlanner> esp_;
        std::unique_ptr<ModalSampler> sampler_;
        ModalSampler::Probabilities probabilities_;
        std::unique_ptr<ManipulationTree> startTree_;
        std::unique_ptr<ManipulationTree> goalTree_;
        const ManipulationGoal *goal_{nullptr};
        ManipulationMetric::Query query_;  ///< reused by nearest() to avoid allocations
        ompl::RNG rng_;
        double connectStep_{0.05};
        double vertexStep_{0.35};
        unsigned int smoothingAttempts_{100};
        unsigned int restartIterations_{10000};
        MOPLStatistics statistics_;
    };
}  // namespace ompl_mm
