#include "ompl_mm/planners/MOPL.h"

#include "ompl_core/io/TextFormat.h"
#include "ompl_mm/base/ManipulationValidityChecker.h"
#include "ompl_mm/base/StepTermination.h"
#include "ompl_mm/geometric/ManipulationMotionValidator.h"

#include <ompl/base/PlannerData.h>
#include <ompl/base/goals/GoalState.h>
#include <ompl/util/String.h>
#include <ompl/util/Time.h>

#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace ob = ompl::base;

namespace ompl_mm
{
    namespace
    {
        /** Adds the time from construction to destruction to an accumulator, in seconds. */
        class ScopedTimer
        {
        public:
            explicit ScopedTimer(double &total) : total_(total), start_(std::chrono::steady_clock::now()) {}
            ~ScopedTimer()
            {
                total_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
            }
            ScopedTimer(const ScopedTimer &) = delete;
            ScopedTimer &operator=(const ScopedTimer &) = delete;

        private:
            double &total_;
            std::chrono::steady_clock::time_point start_;
        };

        /** OMPL's range suggestion "LOW:STEP:HIGH" for a parameter stepped by its lowest value. */
        std::string rangeSuggestion(double low, double high)
        {
            return ompl_core::formatNumber(low) + ":" + ompl_core::formatNumber(low) + ":" +
                   ompl_core::formatNumber(high);
        }

        /** The objects' poses in state: x, y, z, yaw of each. */
        std::vector<double> objectLayout(const ManipulationStateSpace &space, const ob::State *state)
        {
            std::vector<double> layout;
            for (unsigned int i = 0; i < space.objectCount(); ++i)
            {
                const ObjectPose pose = space.objectPose(state, i);
                layout.insert(layout.end(),
                              {pose.position.x(), pose.position.y(), pose.position.z(), pose.yaw});
            }
            return layout;
        }

        /** @throws ompl::Exception naming the parameter, its range and the value when value is outside
            [low, high] (NaN is). */
        void checkWithin(const std::string &name, double value, double low, double high)
        {
            if (!(value >= low && value <= high))
                throw ompl::Exception("MOPL", name + " must be in [" + ompl_core::formatNumber(low) + ", " +
                                                  ompl_core::formatNumber(high) + "], got " +
                                                  ompl_core::formatNumber(value));
        }
    }  // namespace

    MOPL::MOPL(const ob::SpaceInformationPtr &si, std::vector<PrimitivePtr> primitives)
        : ob::Planner(si, "MOPL"),
          primitives_(std::move(primitives)),
          space_(manipulationSpaceOf(si->getStateSpace().get(), "MOPL")),
          metric_(std::make_unique<ManipulationMetric>(space_))
    {
        specs_.recognizedGoal = ob::GOAL_SAMPLEABLE_REGION;
        specs_.approximateSolutions = false;
        specs_.directed = true;
        declareParameters();
        setConnectStep(connectStep_);
        addPlannerProgressProperty("iterations INTEGER",
                                   [this] { return std::to_string(statistics_.iterations); });
        addPlannerProgressProperty("start tree vertices INTEGER",
                                   [this] { return std::to_string(startTree_ ? startTree_->size() : 0); });
        addPlannerProgressProperty("goal tree vertices INTEGER",
                                   [this] { return std::to_string(goalTree_ ? goalTree_->size() : 0); });
    }

    MOPL::~MOPL() = default;

    void MOPL::declareParameters()
    {
        declareParam<double>("connect_step", this, &MOPL::setConnectStep, &MOPL::getConnectStep,
                             rangeSuggestion(MIN_CONNECT_STEP, MAX_CONNECT_STEP));
        declareParam<double>("vertex_step", this, &MOPL::setVertexStep, &MOPL::getVertexStep,
                             rangeSuggestion(MIN_VERTEX_STEP, MAX_VERTEX_STEP));
        declareParam<unsigned int>("restart_iterations", this, &MOPL::setRestartIterations,
                                   &MOPL::getRestartIterations, "0:1000:1000000");
        declareParam<unsigned int>("smoothing_attempts", this, &MOPL::setSmoothingAttempts,
                                   &MOPL::getSmoothingAttempts, "0:1:10000");
        // weights below 0 would let the nearest-neighbour search's lower bounds prune the nearest
        // vertex: a weight must lie in its range "0.:STEP:HIGH."
        auto weight =
            [this](const std::string &name, double ManipulationMetric::Weights::*field, const char *range)
        {
            const std::string suggestion = range;
            const double high = std::stod(suggestion.substr(suggestion.rfind(':') + 1));
            params().declareParam<double>(
                name,
                [this, name, field, high](double v)
                {
                    checkWithin(name, v, 0.0, high);
                    ManipulationMetric::Weights weights = metric_->weights();
                    weights.*field = v;
                    metric_->setWeights(weights);
                },
                [this, field]() { return metric_->weights().*field; });
            params()[name].setRangeSuggestion(suggestion);
        };
        weight("robot_weight", &ManipulationMetric::Weights::robotWeight, "0.:0.1:100.");
        weight("joint_weight", &ManipulationMetric::Weights::jointWeight, "0.:0.1:100.");
        weight("base_joint_weight", &ManipulationMetric::Weights::baseWeight, "0.:0.1:100.");
        weight("tool_weight", &ManipulationMetric::Weights::toolWeight, "0.:0.1:100.");
        weight("rotation_weight", &ManipulationMetric::Weights::rotationWeight, "0.:0.1:100.");
        weight("moving_object_penalty", &ManipulationMetric::Weights::movingObjectPenalty, "0.:0.1:100.");
        weight("move_to_object_penalty", &ManipulationMetric::Weights::moveToObjectPenalty, "0.:0.1:100.");
        weight("move_to_object_factor", &ManipulationMetric::Weights::moveToObjectFactor, "0.:0.1:100.");
        weight("contact_distance", &ManipulationMetric::Weights::contactDistance, "0.:0.01:10.");
        auto probability =
            [this](const std::string &name, double ModalSampler::Probabilities::*field, double low = 0.0)
        {
            params().declareParam<double>(
                name,
                [this, name, field, low](double v)
                {
                    checkWithin(name, v, low, 1.0);
                    probabilities_.*field = v;
                },
                [this, field]() { return probabilities_.*field; });
            params()[name].setRangeSuggestion(low == 0.0 ? "0.:0.05:1." : rangeSuggestion(low, 1.0));
        };
        probability("object_sample_probability", &ModalSampler::Probabilities::object);
        probability("undefined_probability", &ModalSampler::Probabilities::undefined);
        probability("start_value_probability", &ModalSampler::Probabilities::startValue);
        probability("random_robot_probability", &ModalSampler::Probabilities::randomRobot);
        probability("any_object_probability", &ModalSampler::Probabilities::anyObject,
                    MIN_ANY_OBJECT_PROBABILITY);
        declareParam<double>("clear_probability", this, &MOPL::setClearProbability,
                             &MOPL::getClearProbability, "0.:0.05:1.");
        declareParam<double>("clear_radius", this, &MOPL::setClearRadius, &MOPL::getClearRadius,
                             rangeSuggestion(MIN_CLEAR_RADIUS, MAX_CLEAR_RADIUS));
        declareParam<unsigned int>("clear_min_free_objects", this, &MOPL::setClearMinFreeObjects,
                                   &MOPL::getClearMinFreeObjects, "0:1:100");
    }

    void MOPL::setConnectStep(double step)
    {
        checkWithin("connect_step", step, MIN_CONNECT_STEP, MAX_CONNECT_STEP);
        // OMPL's discretisations and the tool path's measure step as finely
        std::static_pointer_cast<ManipulationStateSpace>(si_->getStateSpace())->setSegmentResolution(step);
        connectStep_ = step;
    }

    void MOPL::setVertexStep(double step)
    {
        checkWithin("vertex_step", step, MIN_VERTEX_STEP, MAX_VERTEX_STEP);
        vertexStep_ = step;
    }

    void MOPL::setClearProbability(double probability)
    {
        checkWithin("clear_probability", probability, 0.0, 1.0);
        clearProbability_ = probability;
    }

    void MOPL::setClearRadius(double radius)
    {
        checkWithin("clear_radius", radius, MIN_CLEAR_RADIUS, MAX_CLEAR_RADIUS);
        clearRadius_ = radius;
    }

    void MOPL::setPrimitives(std::vector<PrimitivePtr> primitives)
    {
        primitives_ = std::move(primitives);
        setup_ = false;
    }

    void MOPL::setup()
    {
        ob::Planner::setup();
        if (primitives_.empty())
            throw ompl::Exception(getName(), "has no primitives: call setPrimitives() first");
        checkParameters();
        esp_ = std::make_unique<EmptySpacePlanner>(space_, primitives_);
        simulatedPrimitives_ = std::any_of(primitives_.begin(), primitives_.end(),
                                           [](const PrimitivePtr &p) { return !p->endsWhereAsked(); });
        simplifier_ = std::make_unique<ManipulationSimplifier>(si_);  // throws without the validator
        goalTransit_ = std::make_unique<TransitConnector>(si_);
        // the space information's own validator, so that the sweeps the walks found free are
        // remembered for the path's re-check
        motions_ = std::dynamic_pointer_cast<ManipulationMotionValidator>(si_->getMotionValidator());
        startTree_ = std::make_unique<ManipulationTree>(space_, metric_.get(), true);
        goalTree_ = std::make_unique<ManipulationTree>(space_, metric_.get(), false);
        pickup_ = nullptr;
        for (const PrimitivePtr &primitive : primitives_)
            if (!pickup_)
                pickup_ = dynamic_cast<const Pickup *>(primitive.get());
        ikTimeAtClear_ = ikTimeSoFar();
    }

    double MOPL::ikTimeSoFar() const
    {
        double total = 0.0;
        for (const PrimitivePtr &primitive : primitives_)
            total += primitive->inverseKinematicsTime();
        return total + (simplifier_ ? simplifier_->inverseKinematicsTime() : 0.0);
    }

    bool MOPL::holdsTwo(const ob::State *state) const
    {
        unsigned int held = 0;
        for (unsigned int i = 0; i < space_->objectCount(); ++i)
            held += space_->restingSurface(state, i) < 0 ? 1 : 0;
        return held > 1;
    }

    bool MOPL::graspSample(PartialState &sample, const ManipulationTree &tree, int near)
    {
        ScopedTimer timer(statistics_.samplingTime);
        space_->copyRobot(sample.state(), tree.vertex(near).state);
        if (!pickup_->grasp(sample.state(), static_cast<unsigned int>(sample.graspedObject())))
            return false;
        sample.setRobotDefined(true);
        return true;
    }

    void MOPL::checkParameters() const
    {
        if (probabilities_.undefined + probabilities_.startValue > 1.0)
            throw ompl::Exception(getName(), "undefined_probability + start_value_probability exceeds 1");
    }

    bool MOPL::checksParameter(const std::string &name)
    {
        return name == "undefined_probability" || name == "start_value_probability";
    }

    void MOPL::clear()
    {
        ob::Planner::clear();
        if (startTree_)
            startTree_->clear();
        if (goalTree_)
            goalTree_->clear();
        sampler_.reset();
        goalLayoutsTried_.clear();
        statistics_ = MOPLStatistics();
        if (esp_)
            esp_->tally().clear();
        ikTimeAtClear_ = ikTimeSoFar();
    }

    void MOPL::restart()
    {
        ob::State *start = space_->cloneState(startTree_->vertex(0).state);
        startTree_->clear();
        goalTree_->clear();
        startTree_->add(start, -1, {});
        space_->freeState(start);
        goalLayoutsTried_.clear();
        ++statistics_.restarts;
    }

    double MOPL::segmentLength(const ob::State *a, const ob::State *b) const
    {
        double length = 0.0;
        const double *qa = space_->robotValues(a);
        const double *qb = space_->robotValues(b);
        for (unsigned int j = 0; j < space_->robotDimension(); ++j)
            length += (qa[j] - qb[j]) * (qa[j] - qb[j]);
        length = std::sqrt(length);
        for (unsigned int i = 0; i < space_->objectCount(); ++i)
            length = std::max(length, (space_->objectPosition(a, i) - space_->objectPosition(b, i)).norm());
        return length;
    }

    int MOPL::nearest(ManipulationTree &tree, PartialState &sample, bool *newRoot)
    {
        *newRoot = false;
        if (tree.forward())
        {
            ScopedTimer timer(statistics_.nearestTime);
            metric_->makeQuery(sample, true, query_);
            return tree.nearest(query_, nullptr);
        }

        // PROJSAMP: the goal state nearest to the sample competes with the goal tree's vertices,
        // and its distance bounds their search; making it is sample generation
        ob::State *root = space_->allocState();
        double rootDistance = 0.0;
        {
            ScopedTimer timer(statistics_.samplingTime);
            goal_->complete(sample, root, rng_, simulatedPrimitives_);
            metric_->makeQuery(sample, false, query_);
            MetricPoint rootPoint;
            metric_->makePoint(root, rootPoint);
            rootDistance = metric_->distance(rootPoint, query_, metric_->objectCost(rootPoint, query_));
        }
        // an invalid root cannot compete: then the tree alone answers
        const bool rootValid = si_->isValid(root);
        int index = -1;
        // with simulated primitives, which leave objects near their goals, a root that keeps every
        // object where the sample has it is the one the sample can reach by exact motions
        if (!(simulatedPrimitives_ && rootValid && keepsSampleObjects(sample, root)))
        {
            ScopedTimer timer(statistics_.nearestTime);
            index = tree.nearest(query_, nullptr,
                                 rootValid ? rootDistance : std::numeric_limits<double>::infinity());
        }
        if (index < 0 && rootValid)
        {
            index = tree.add(root, -1, {});
            sampler_->noteVertex(root);
            *newRoot = true;
        }
        space_->freeState(root);
        return index;
    }

    bool MOPL::keepsSampleObjects(const PartialState &sample, const ob::State *state) const
    {
        for (unsigned int i = 0; i < space_->objectCount(); ++i)
            if (!sample.objectDefined(i) || space_->objectMoves(sample.state(), state, i))
                return false;
        return true;
    }

    MOPL::Extension MOPL::extend(ManipulationTree &tree, int near, const ob::State *target,
                                 const ob::PlannerTerminationCondition &ptc)
    {
        Trajectory trajectory(space_);
        EmptySpacePlanner::Outcome outcome;
        {
            ScopedTimer timer(statistics_.propagateTime);
            // the backward tree needs a motion that ends exactly at its vertex: no simulated
            // primitives there
            outcome = tree.forward()
                          ? esp_->plan(tree.vertex(near).state, target, trajectory, rng_, ptc)
                          : esp_->plan(target, tree.vertex(near).state, trajectory, rng_, ptc, true);
        }
        if (outcome == EmptySpacePlanner::Outcome::AlreadyThere)
            return {near, true};
        if (outcome == EmptySpacePlanner::Outcome::Failed ||
            (!tree.forward() && outcome != EmptySpacePlanner::Outcome::Reached))
            return {};
        ScopedTimer timer(statistics_.connectTime);
        Extension extension = walk(tree, near, trajectory, ptc);
        extension.reached = extension.reached && outcome == EmptySpacePlanner::Outcome::Reached;
        return extension;
    }

    MOPL::Extension MOPL::walk(ManipulationTree &tree, int near, const Trajectory &trajectory,
                               const ob::PlannerTerminationCondition &ptc)
    {
        // walk away from the tree: forward along the trajectory, or backward from its end, a vertex
        // at least every vertex step and at every waypoint (mode switches happen there)
        const bool forward = tree.forward();
        const std::size_t segments = trajectory.size() - 1;
        Extension extension;
        int parent = near;
        ob::State *from = space_->allocState();
        ob::State *to = space_->allocState();
        bool blocked = false;
        for (std::size_t s = 0; s < segments && !blocked; ++s)
        {
            const std::size_t i = forward ? s : segments - 1 - s;
            const ob::State *start = trajectory.state(forward ? i : i + 1);
            const ob::State *end = trajectory.state(forward ? i + 1 : i);
            const SegmentLabel label = trajectory.label(i);
            // on the way between waypoints, other motions may start only where both ends allow it
            const bool endBranchable = trajectory.branchable(forward ? i + 1 : i);
            const bool wayBranchable = endBranchable && trajectory.branchable(forward ? i : i + 1);
            // pieces a whole vertex step long, the last one the rest, which takes in a rest shorter
            // than a connect step: shorter pieces would grow the trees (and the nearest-neighbour
            // search) with no gain in reach
            const double length = segmentLength(start, end);
            // (a segment shorter than the connect step is one piece; the bound is taken before the
            // cast, since a negative double has no unsigned value)
            const auto pieces =
                static_cast<unsigned int>(std::max(1.0, std::ceil((length - connectStep_) / vertexStep_)));
            space_->copyState(from, start);
            for (unsigned int k = 1; k <= pieces && !blocked; ++k)
            {
                if (k == pieces)
                    space_->copyState(to, end);
                else
                {
                    space_->interpolate(start, end, k * vertexStep_ / length, to);
                    // a vertex on the way keeps the segment's mode (a carried object passing
                    // within the rest tolerance of a surface would seem put down there): else the
                    // piece goes on to the next one
                    if (!isMotion(from, to, forward) || !isMotion(to, end, forward))
                        continue;
                }
                // a check stopped by ptc reports nothing of the piece free: the walk ends here
                const CollisionWorld::SweepCheck check = motions_->checkSweep(from, to, ptc);
                if (!check.interrupted)
                    esp_->tally().motion(blamedKind(trajectory, i), label.kind, check.free, check.contact[0],
                                         check.contact[1]);
                blocked = !check.free || !si_->isValid(to);
                if (blocked && check.free)
                    break;  // the piece's end breaks a rule other than collision: stay
                if (blocked)
                {
                    extension.blockingObject = check.blockingObject;
                    // keep the way to a contact only when it is worth a vertex: a connect step
                    space_->interpolate(from, to, check.safeFraction, to);
                    if (segmentLength(from, to) < connectStep_ || !isMotion(from, to, forward))
                        break;
                }
                extension.last = parent =
                    tree.add(to, parent, label, k == pieces && !blocked ? endBranchable : wayBranchable);
                sampler_->noteVertex(to);
                std::swap(from, to);
            }
        }
        extension.reached = !blocked;
        space_->freeState(from);
        space_->freeState(to);
        return extension;
    }

    bool MOPL::isMotion(const ob::State *from, const ob::State *to, bool forward) const
    {
        return forward ? motions_->explain(from, to).has_value() : motions_->explain(to, from).has_value();
    }

    PrimitiveKind MOPL::blamedKind(const Trajectory &trajectory, std::size_t segment)
    {
        // a transit that leads to another primitive is that primitive's approach (a pickup's to
        // its approach pose): its contacts are what keeps that primitive from acting
        for (std::size_t k = segment; k + 1 < trajectory.size(); ++k)
            if (trajectory.label(k).kind != PrimitiveKind::Transit)
                return trajectory.label(k).kind;
        return PrimitiveKind::Transit;
    }

    MOPL::Extension MOPL::clearWay(ManipulationTree &tree, int from, unsigned int object, ob::State *target,
                                   const ob::PlannerTerminationCondition &ptc)
    {
        space_->copyState(target, tree.vertex(from).state);
        ObjectPose pose = space_->objectPose(target, object);
        const Scene &scene = space_->model()->scene();
        const int surface = scene.restingSurface(pose.position);
        if (surface < 0)
            return {};
        const SupportSurface &onto = scene.surfaces[static_cast<std::size_t>(surface)];
        for (unsigned int attempt = 0; attempt < CLEAR_PLACE_ATTEMPTS; ++attempt)
        {
            // uniform in the disc of the clear radius about the object
            const double r = clearRadius_ * std::sqrt(rng_.uniform01());
            const double angle =
                rng_.uniformReal(-boost::math::constants::pi<double>(), boost::math::constants::pi<double>());
            const double x = pose.position.x() + r * std::cos(angle);
            const double y = pose.position.y() + r * std::sin(angle);
            if (!onto.contains(x, y))
                continue;
            pose.position.x() = x;
            pose.position.y() = y;
            space_->setObjectPose(target, object, pose);
            return extend(tree, from, target, ptc);
        }
        return {};
    }

    MOPL::Extension MOPL::clearAndRetry(ManipulationTree &tree, int near, const Extension &stopped,
                                        const ob::State *target, ob::State *scratch,
                                        const ob::PlannerTerminationCondition &ptc)
    {
        ++statistics_.clearings;
        const int from = stopped.last >= 0 ? stopped.last : near;
        const Extension cleared =
            clearWay(tree, from, static_cast<unsigned int>(stopped.blockingObject), scratch, ptc);
        if (cleared.last < 0 || cleared.last == from)
            return stopped;
        if (!cleared.reached)
            return cleared;
        const Extension retried = extend(tree, cleared.last, target, ptc);
        return retried.last >= 0 && retried.last != cleared.last ? retried : cleared;
    }

    int MOPL::transitToGoal(int vertex, const ob::PlannerTerminationCondition &ptc)
    {
        const ob::State *from = startTree_->vertex(vertex).state;
        std::vector<double> layout = objectLayout(*space_, from);
        // called after every forward extension: the cheap checks before the goal's completion
        if (startTree_->vertex(vertex).group == ManipulationTree::NO_GROUP ||
            std::find(goalLayoutsTried_.begin(), goalLayoutsTried_.end(), layout) != goalLayoutsTried_.end())
            return -1;
        PartialState here(space_);
        space_->copyState(here.state(), from);
        here.defineAll();
        ob::State *goal = space_->allocState();
        goal_->complete(here, goal, rng_, true);
        int reached = -1;
        if (!space_->anyObjectMoves(from, goal) && si_->isValid(goal))
        {
            goalLayoutsTried_.push_back(std::move(layout));
            Trajectory transit(space_);
            transit.reset(from);
            bool planned = false;
            {
                ScopedTimer timer(statistics_.propagateTime);
                planned = goalTransit_->connect(transit, goal, GOAL_TRANSIT_ITERATIONS, rng_, ptc);
            }
            if (planned)
            {
                ScopedTimer timer(statistics_.connectTime);
                const Extension walked = walk(*startTree_, vertex, transit, ptc);
                if (walked.reached && goal_->isSatisfied(startTree_->vertex(walked.last).state))
                    reached = walked.last;
            }
        }
        space_->freeState(goal);
        return reached;
    }

    unsigned int MOPL::freeObjectCount() const
    {
        unsigned int free = 0;
        for (unsigned int i = 0; i < space_->objectCount(); ++i)
            free += goal_->constrainsObject(i) ? 0 : 1;
        return free;
    }

    ob::PlannerStatus MOPL::solve(const ob::PlannerTerminationCondition &ptc)
    {
        checkValidity();
        goal_ = dynamic_cast<const ManipulationGoal *>(pdef_->getGoal().get());
        if (!goal_)
        {
            OMPL_ERROR("%s: the goal must be a ManipulationGoal", getName().c_str());
            return ob::PlannerStatus::UNRECOGNIZED_GOAL_TYPE;
        }
        if (startTree_->empty())
        {
            const ob::State *start = pis_.nextStart();
            if (!start)
            {
                OMPL_ERROR("%s: no valid start state", getName().c_str());
                return ob::PlannerStatus::INVALID_START;
            }
            startTree_->add(start, -1, {});
            // goal values of the sampler: the goal's coordinates, the start's elsewhere
            PartialState fromStart(space_);
            space_->copyState(fromStart.state(), start);
            ob::State *goalState = space_->allocState();
            goal_->complete(fromStart, goalState, rng_);
            sampler_ = std::make_unique<ModalSampler>(space_, goal_, start, goalState);
            sampler_->probabilities() = probabilities_;
            sampler_->setSampleInAir(pickup_ != nullptr);
            space_->freeState(goalState);
        }
        auto *checker = dynamic_cast<ManipulationValidityChecker *>(si_->getStateValidityChecker().get());
        const std::uint64_t queriesBefore = checker ? checker->queryCount() : 0;
        const std::uint64_t freeBefore = checker ? checker->freeQueryCount() : 0;
        const auto countQueries = [&]
        {
            statistics_.ikTime = ikTimeSoFar() - ikTimeAtClear_;
            if (checker)
            {
                statistics_.collisionQueries = checker->queryCount() - queriesBefore;
                statistics_.freeCollisionQueries = checker->freeQueryCount() - freeBefore;
            }
        };

        if (goal_->isSatisfied(startTree_->vertex(0).state))
        {
            addSolution(0, -1, ptc);
            return ob::PlannerStatus::EXACT_SOLUTION;
        }

        PartialState sample(space_);
        PartialState connectTarget(space_);
        PartialState clearing(space_);
        const bool clears = clearProbability_ > 0.0 && freeObjectCount() >= clearMinFreeObjects_;
        bool forward = true;
        // restarts cut the heavy tail of the search time; each run may last twice as long as the last
        std::uint64_t allowance = restartIterations_;
        std::uint64_t runStart = statistics_.iterations;
        // ptc once per iteration, as OMPL's planners poll it (a condition may count iterations);
        // within the iteration's steps a view of it that asks again only when a step takes long
        StepTermination step(ptc);
        const ob::PlannerTerminationCondition &inner = step.condition();
        while (!ptc)
        {
            step.startStep();
            if (restartIterations_ > 0 && statistics_.iterations - runStart >= allowance)
            {
                restart();
                runStart = statistics_.iterations;
                allowance *= 2;
            }
            ++statistics_.iterations;
            ManipulationTree &a = forward ? *startTree_ : *goalTree_;
            ManipulationTree &b = forward ? *goalTree_ : *startTree_;
            forward = !forward;
            {
                ScopedTimer timer(statistics_.samplingTime);
                sampler_->sample(sample, a.forward(), rng_);
            }
            bool newRoot = false;
            const int near = nearest(a, sample, &newRoot);
            if (near < 0)
                continue;
            const bool graspFound = sample.graspedObject() < 0 || graspSample(sample, a, near);
            if (graspFound)
                sample.complete(a.vertex(near).state, sample.state());
            if (!graspFound || holdsTwo(sample.state()))
            {
                if (newRoot)
                    a.removeLast();
                continue;
            }
            Extension grown = extend(a, near, sample.state(), inner);
            // an object stopped the start tree: push it aside, then go on
            if (clears && a.forward() && grown.blockingObject >= 0 && rng_.uniform01() < clearProbability_)
                grown = clearAndRetry(a, near, grown, sample.state(), clearing.state(), inner);
            if (grown.last < 0 || grown.last == near)
            {
                if (newRoot)
                    a.removeLast();
                continue;
            }
            if (a.forward() && goal_->isSatisfied(a.vertex(grown.last).state))
            {
                addSolution(grown.last, -1, ptc);
                countQueries();
                return ob::PlannerStatus::EXACT_SOLUTION;
            }
            if (a.forward() && simulatedPrimitives_)
            {
                const int reached = transitToGoal(grown.last, inner);
                if (reached >= 0)
                {
                    addSolution(reached, -1, ptc);
                    countQueries();
                    return ob::PlannerStatus::EXACT_SOLUTION;
                }
            }

            // try to connect the other tree to the new vertex, unless no motion may start there
            if (a.vertex(grown.last).group == ManipulationTree::NO_GROUP)
                continue;
            space_->copyState(connectTarget.state(), a.vertex(grown.last).state);
            connectTarget.defineAll();
            const int nearB = nearest(b, connectTarget, &newRoot);
            if (nearB < 0)
                continue;
            const Extension joined = extend(b, nearB, connectTarget.state(), inner);
            if (newRoot && !joined.reached && (joined.last < 0 || joined.last == nearB))
                b.removeLast();
            if (joined.reached)
            {
                if (a.forward())
                    addSolution(grown.last, joined.last, ptc);
                else
                    addSolution(joined.last, grown.last, ptc);
                countQueries();
                return ob::PlannerStatus::EXACT_SOLUTION;
            }
        }
        countQueries();
        OMPL_INFORM("%s: no solution after %llu iterations (%zu + %zu vertices)", getName().c_str(),
                    static_cast<unsigned long long>(statistics_.iterations), startTree_->size(),
                    goalTree_->size());
        std::istringstream never(esp_->tally().failureSummary());
        for (std::string line; std::getline(never, line);)
            OMPL_WARN("%s: %s", getName().c_str(), line.c_str());
        return ob::PlannerStatus::TIMEOUT;
    }

    const PrimitiveTally &MOPL::primitiveTally() const
    {
        static const PrimitiveTally NONE;
        return esp_ ? esp_->tally() : NONE;
    }

    void MOPL::addSolution(int f, int g, const ob::PlannerTerminationCondition &ptc)
    {
        auto path = std::make_shared<ManipulationPath>(si_);
        for (int index : startTree_->branch(f))
        {
            const ManipulationTree::Vertex &v = startTree_->vertex(index);
            if (path->getStateCount() == 0)
                path->appendFirst(v.state);
            else
                path->appendLabelled(v.state, v.label);
        }
        if (g >= 0)
        {
            // the goal tree's branch starts at a copy of f's state; its labels sit on the child side
            const std::vector<int> branch = goalTree_->branch(g);
            for (std::size_t k = 1; k < branch.size(); ++k)
                path->appendLabelled(goalTree_->vertex(branch[k]).state,
                                     goalTree_->vertex(branch[k - 1]).label);
        }
        {
            ScopedTimer timer(statistics_.smoothingTime);
            simplifier_->simplify(*path, smoothingAttempts_, rng_, pdef_->getGoal().get(), ptc);
        }
        pdef_->addSolutionPath(path, false, 0.0, getName());
    }

    void MOPL::getPlannerData(ob::PlannerData &data) const
    {
        ob::Planner::getPlannerData(data);
        for (const ManipulationTree *tree : {startTree_.get(), goalTree_.get()})
        {
            if (!tree)
                continue;
            for (std::size_t i = 0; i < tree->size(); ++i)
            {
                const ManipulationTree::Vertex &v = tree->vertex(i);
                const ob::PlannerDataVertex vertex(v.state, tree->forward() ? 1 : 2);
                if (v.parent < 0)
                {
                    if (tree->forward())
                        data.addStartVertex(vertex);
                    else
                        data.addGoalVertex(vertex);
                    continue;
                }
                const ob::PlannerDataVertex parent(tree->vertex(v.parent).state, tree->forward() ? 1 : 2);
                if (tree->forward())
                    data.addEdge(parent, vertex);
                else
                    data.addEdge(vertex, parent);
            }
        }
        // named as in the run record (ManipulationRunResult), so logs and JSON agree
        data.properties["time_sampling_s REAL"] = ompl_core::exactText(statistics_.samplingTime);
        data.properties["time_nearest_s REAL"] = ompl_core::exactText(statistics_.nearestTime);
        data.properties["time_propagate_s REAL"] = ompl_core::exactText(statistics_.propagateTime);
        data.properties["time_connect_s REAL"] = ompl_core::exactText(statistics_.connectTime);
        data.properties["time_smoothing_s REAL"] = ompl_core::exactText(statistics_.smoothingTime);
        data.properties["time_ik_s REAL"] = ompl_core::exactText(statistics_.ikTime);
        data.properties["iterations INTEGER"] = std::to_string(statistics_.iterations);
        data.properties["restarts INTEGER"] = std::to_string(statistics_.restarts);
        data.properties["clearings INTEGER"] = std::to_string(statistics_.clearings);
        data.properties["collision_queries INTEGER"] = std::to_string(statistics_.collisionQueries);
        data.properties["collision_queries_free INTEGER"] = std::to_string(statistics_.freeCollisionQueries);
        // what users mean by a plan's length and size; Benchmark's own "solution length" is the
        // length in the whole state space
        const auto *solution =
            pdef_ ? dynamic_cast<const ManipulationPath *>(pdef_->getSolutionPath().get()) : nullptr;
        // a path that something changed into motions no primitive makes has no counts to give
        if (solution && solution->checkLabels().empty())
        {
            data.properties["path_length_m REAL"] = ompl_core::exactText(solution->toolPathLength());
            data.properties["path_vertices INTEGER"] = std::to_string(solution->getStateCount());
            data.properties["push_reversals INTEGER"] = std::to_string(solution->pushReversals().size());
            for (const auto &[kind, count] : solution->primitiveCounts())
                data.properties["primitives_" + kind + " INTEGER"] = std::to_string(count);
        }
    }
}  // namespace ompl_mm
