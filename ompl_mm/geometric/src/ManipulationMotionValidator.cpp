#include "ompl_mm/geometric/ManipulationMotionValidator.h"

#include <ompl/util/Exception.h>

#include <algorithm>
#include <queue>

namespace ompl_mm
{
    namespace
    {
        /** The number of check steps: the space's valid segment count rounded up to a power of two,
            so that the states checked along a motion include those of its halves, quarters, …
            (subdividing a valid motion, as OMPL's B-spline smoothing does, yields valid motions). */
        unsigned int dyadicSteps(const ompl::base::StateSpace &space, const ompl::base::State *s1,
                                 const ompl::base::State *s2)
        {
            const unsigned int needed = std::max(1u, space.validSegmentCount(s1, s2));
            unsigned int steps = 1;
            while (steps < needed)
                steps *= 2;
            return steps;
        }
    }  // namespace

    ManipulationMotionValidator::ManipulationMotionValidator(const ompl::base::SpaceInformationPtr &si,
                                                             std::vector<PrimitivePtr> primitives)
        : ompl::base::MotionValidator(si), primitives_(std::move(primitives))
    {
        if (!std::dynamic_pointer_cast<ManipulationStateSpace>(si->getStateSpace()))
            throw ompl::Exception("ManipulationMotionValidator needs a ManipulationStateSpace");
    }

    std::optional<SegmentLabel> ManipulationMotionValidator::explain(const ompl::base::State *s1,
                                                                     const ompl::base::State *s2) const
    {
        for (const PrimitivePtr &primitive : primitives_)
            if (std::optional<SegmentLabel> label = primitive->explain(s1, s2))
                return label;
        return std::nullopt;
    }

    ManipulationMotionValidator::StepCheck ManipulationMotionValidator::checkSteps(
        const ompl::base::State *s1, const ompl::base::State *s2) const
    {
        const ompl::base::StateSpace &space = *si_->getStateSpace();
        StepCheck check{dyadicSteps(space, s1, s2), 0};
        ompl::base::State *state = si_->allocState();
        while (check.valid < check.steps)
        {
            space.interpolate(s1, s2, static_cast<double>(check.valid + 1) / check.steps, state);
            if (!si_->isValid(state))
                break;
            ++check.valid;
        }
        si_->freeState(state);
        return check;
    }

    bool ManipulationMotionValidator::checkMotion(const ompl::base::State *s1,
                                                  const ompl::base::State *s2) const
    {
        std::pair<ompl::base::State *, double> noState{nullptr, 0.0};
        return checkMotion(s1, s2, noState);
    }

    bool ManipulationMotionValidator::checkMotion(const ompl::base::State *s1, const ompl::base::State *s2,
                                                  std::pair<ompl::base::State *, double> &lastValid) const
    {
        const StepCheck check = explain(s1, s2) ? checkSteps(s1, s2) : StepCheck{1, 0};
        const bool valid = check.valid == check.steps;
        if (!valid)
        {
            lastValid.second = static_cast<double>(check.valid) / check.steps;
            if (lastValid.first)
                si_->getStateSpace()->interpolate(s1, s2, lastValid.second, lastValid.first);
        }
        ++(valid ? valid_ : invalid_);
        return valid;
    }
}  // namespace ompl_mm
