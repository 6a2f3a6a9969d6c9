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

    ManipulationStateSampler::ManipulationStateSampler(const ManipulationStateSpace *space,
                                                       bool objectsAtStart)
        : ompl::base::StateSampler(space),
          all_(space->ompl::base::CompoundStateSpace::allocDefaultStateSampler()),
          robot_(space->getSubspace(0)->allocStateSampler()),
          objectsAtStart_(objectsAtStart)
    {
    }

    void ManipulationStateSampler::sampleUniform(ompl::base::State *state)
    {
        if (!objectsAtStart_)
        {
            all_->sampleUniform(state);
            return;
        }
        robot_->sampleUniform(robotPart(state));
        const auto *space = space_->as<ManipulationStateSpace>();
        for (unsigned int i = 0; i < space->objectCount(); ++i)
            space->setObjectPose(state, i, space->model()->scene().objects[i].start);
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
