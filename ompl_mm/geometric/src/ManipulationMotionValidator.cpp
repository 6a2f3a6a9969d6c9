#include "ompl_mm/geometric/ManipulationMotionValidator.h"

#include "ompl_core/run/Fnv1aHash.h"

#include <chrono>
#include <cstring>
#include <string_view>

namespace ompl_mm
{

    ManipulationMotionValidator::ManipulationMotionValidator(const ompl::base::SpaceInformationPtr &si,
                                                             std::vector<PrimitivePtr> primitives)
        : ompl::base::MotionValidator(si),
          primitives_(std::move(primitives)),
          space_(manipulationSpaceOf(si->getStateSpace().get(), "ManipulationMotionValidator")),
          world_(space_->model()),
          along_(space_->allocState())
    {
    }

    ManipulationMotionValidator::~ManipulationMotionValidator()
    {
        space_->freeState(along_);
    }

    CollisionWorld::Configuration ManipulationMotionValidator::ConfigurationOf::read(
        const ManipulationStateSpace &space, const ompl::base::State *state)
    {
        poses.resize(space.objectCount());
        resting.resize(space.objectCount());
        for (unsigned int i = 0; i < space.objectCount(); ++i)
        {
            poses[i] = space.objectPose(state, i);
            resting[i] = space.model()->scene().restingSurface(poses[i].position);
        }
        return {space.robotValues(state), &poses, &resting};
    }

    std::optional<SegmentLabel> ManipulationMotionValidator::explain(const ompl::base::State *s1,
                                                                     const ompl::base::State *s2) const
    {
        for (const PrimitivePtr &primitive : primitives_)
            if (std::optional<SegmentLabel> label = primitive->explain(s1, s2))
                return label;
        return std::nullopt;
    }

    ManipulationMotionValidator::TerminationScope::TerminationScope(
        ManipulationMotionValidator &validator, const ompl::base::PlannerTerminationCondition &ptc)
        : validator_(validator)
    {
        validator_.scopedConditions_.push_back(ptc);
    }

    ManipulationMotionValidator::TerminationScope::~TerminationScope()
    {
        validator_.scopedConditions_.pop_back();
    }

    bool ManipulationMotionValidator::stopped(const ompl::base::PlannerTerminationCondition *ptc) const
    {
        if (ptc && (*ptc)())
            return true;
        for (const ompl::base::PlannerTerminationCondition &condition : scopedConditions_)
            if (condition())
                return true;
        return false;
    }

    CollisionWorld::SweepCheck ManipulationMotionValidator::sweep(
        const ompl::base::State *s1, const ompl::base::State *s2,
        const ompl::base::PlannerTerminationCondition *ptc) const
    {
        // stopped: nothing of the motion is shown free
        if (stopped(ptc))
            return {false, 0.0, -1, {}, true};
        const ManipulationStateSpace::MotionEnds ends = space_->motionEnds(s1, s2);
        return world_.checkSweep(
            from_.read(*space_, s1), to_.read(*space_, s2),
            [&](double t)
            {
                space_->interpolate(s1, s2, t, along_, ends);
                return alongConfiguration_.read(*space_, along_);
            },
            [&] { return stopped(ptc); });
    }

    std::size_t ManipulationMotionValidator::ValuesHash::operator()(const std::vector<double> &values) const
    {
        return static_cast<std::size_t>(ompl_core::fnv1a64(
            std::string_view(reinterpret_cast<const char *>(values.data()), values.size() * sizeof(double))));
    }

    bool ManipulationMotionValidator::SameBits::operator()(const std::vector<double> &a,
                                                           const std::vector<double> &b) const
    {
        return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
    }

    CollisionWorld::SweepCheck ManipulationMotionValidator::rememberedSweep(
        const ompl::base::State *s1, const ompl::base::State *s2,
        const ompl::base::PlannerTerminationCondition *ptc, bool lookUp) const
    {
        // stopped is stopped, remembered or not: no check passes after the end
        if (stopped(ptc))
            return {false, 0.0};
        // a motion and its reverse pass through the same configurations: one key for both, the
        // lesser state's values first
        const auto motionValues = [&]
        {
            space_->copyToReals(motionValues_, s1);
            space_->copyToReals(stateValues_, s2);
            if (std::memcmp(stateValues_.data(), motionValues_.data(),
                            motionValues_.size() * sizeof(double)) < 0)
                motionValues_.swap(stateValues_);
            motionValues_.insert(motionValues_.end(), stateValues_.begin(), stateValues_.end());
        };
        if (lookUp)
        {
            motionValues();
            if (freeSweeps_.count(motionValues_) > 0)
                return {true, 1.0};
        }
        const auto start = std::chrono::steady_clock::now();
        const CollisionWorld::SweepCheck check = sweep(s1, s2, ptc);
        // a quick sweep is cheaper to repeat than to remember
        if (!check.free || std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() <
                               shortestRemembered_)
            return check;
        if (!lookUp)
            motionValues();
        if (freeSweepOrder_.size() >= SWEEP_MEMORY)
        {
            freeSweeps_.erase(freeSweeps_.find(*freeSweepOrder_.front()));
            freeSweepOrder_.pop_front();
        }
        const auto [remembered, added] = freeSweeps_.insert(motionValues_);
        if (added)
            freeSweepOrder_.push_back(&*remembered);
        return check;
    }

    CollisionWorld::SweepCheck ManipulationMotionValidator::checkSweep(const ompl::base::State *s1,
                                                                       const ompl::base::State *s2) const
    {
        return rememberedSweep(s1, s2, nullptr, false);
    }

    CollisionWorld::SweepCheck ManipulationMotionValidator::checkSweep(
        const ompl::base::State *s1, const ompl::base::State *s2,
        const ompl::base::PlannerTerminationCondition &ptc) const
    {
        return rememberedSweep(s1, s2, &ptc, false);
    }

    CollisionWorld::SweepCheck ManipulationMotionValidator::judge(const ompl::base::State *s1,
                                                                  const ompl::base::State *s2,
                                                                  bool probe) const
    {
        CollisionWorld::SweepCheck check{false, 0.0};
        // stopped: the motion is not checked at all, so it is not shown valid
        if (explain(s1, s2) && !stopped(nullptr))
        {
            check.free = true;
            for (unsigned int k = 1; probe && check.free && k <= PROBES; ++k)
            {
                space_->interpolate(s1, s2, static_cast<double>(k) / (PROBES + 1), along_);
                check.free = si_->isValid(along_);
            }
            if (check.free)
                check = rememberedSweep(s1, s2, nullptr, true);
            // the end's other rules (joint limits, support): short of it, stay where the sweep began
            if (check.free && !si_->isValid(s2))
                check = {false, 0.0};
        }
        ++(check.free ? valid_ : invalid_);
        return check;
    }

    bool ManipulationMotionValidator::checkMotion(const ompl::base::State *s1,
                                                  const ompl::base::State *s2) const
    {
        return judge(s1, s2, true).free;
    }

    bool ManipulationMotionValidator::checkMotion(const ompl::base::State *s1, const ompl::base::State *s2,
                                                  std::pair<ompl::base::State *, double> &lastValid) const
    {
        const CollisionWorld::SweepCheck check = judge(s1, s2, false);
        if (!check.free)
        {
            lastValid.second = check.safeFraction;
            if (lastValid.first)
                space_->interpolate(s1, s2, lastValid.second, lastValid.first);
        }
        return check.free;
    }
}  // namespace ompl_mm
