#include "ompl_mm/geometric/ManipulationMotionValidator.h"

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

    CollisionWorld::SweepCheck ManipulationMotionValidator::checkSweep(const ompl::base::State *s1,
                                                                       const ompl::base::State *s2) const
    {
        return world_.checkSweep(from_.read(*space_, s1), to_.read(*space_, s2),
                                 [&](double t)
                                 {
                                     space_->interpolate(s1, s2, t, along_);
                                     return alongConfiguration_.read(*space_, along_);
                                 });
    }

    CollisionWorld::SweepCheck ManipulationMotionValidator::judge(const ompl::base::State *s1,
                                                                  const ompl::base::State *s2,
                                                                  bool probe) const
    {
        CollisionWorld::SweepCheck check{false, 0.0};
        if (explain(s1, s2))
        {
            check.free = true;
            for (unsigned int k = 1; probe && check.free && k <= PROBES; ++k)
            {
                space_->interpolate(s1, s2, static_cast<double>(k) / (PROBES + 1), along_);
                check.free = si_->isValid(along_);
            }
            if (check.free)
                check = checkSweep(s1, s2);
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
