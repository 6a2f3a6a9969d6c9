#include "ompl_mm/base/ManipulationStateSampler.h"

namespace ompl_mm
{
    namespace
    {
        ompl::base::State *robotPart(ompl::base::State *state)
        {
            return state->as<ompl::base::CompoundState>()->components[0];
        }

        const ompl::base::State *robotPart(const ompl::base::State *state)
        {
            return state->as<ompl::base::CompoundState>()->components[0];
        }
    }  // namespace

    ManipulationStateSampler::ManipulationStateSampler(const ManipulationStateSpace *space)
        : ompl::base::StateSampler(space),
          all_(space->ompl::base::CompoundStateSpace::allocDefaultStateSampler()),
          robot_(space->getSubspace(0)->allocStateSampler())
    {
    }

    void ManipulationStateSampler::sampleUniform(ompl::base::State *state)
    {
        all_->sampleUniform(state);
    }

    void ManipulationStateSampler::sampleUniformNear(ompl::base::State *state, const ompl::base::State *near,
                                                     double distance)
    {
        space_->copyState(state, near);
        robot_->sampleUniformNear(robotPart(state), robotPart(near), distance);
    }

    void ManipulationStateSampler::sampleGaussian(ompl::base::State *state, const ompl::base::State *mean,
                                                  double stdDev)
    {
        space_->copyState(state, mean);
        robot_->sampleGaussian(robotPart(state), robotPart(mean), stdDev);
    }
}  // namespace ompl_mm
