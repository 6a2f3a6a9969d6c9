#include "ompl_mm/base/ManipulationValidityChecker.h"

#include <ompl/base/SpaceInformation.h>

#include <algorithm>
#include <cmath>

namespace ompl_mm
{
    ManipulationValidityChecker::ManipulationValidityChecker(const ompl::base::SpaceInformationPtr &si)
        : ompl::base::StateValidityChecker(si),
          space_(si->getStateSpace()->as<ManipulationStateSpace>()),
          world_(space_->model()),
          poses_(space_->objectCount()),
          resting_(space_->objectCount())
    {
    }

    bool ManipulationValidityChecker::isValid(const ompl::base::State *state) const
    {
        ++queries_;
        const bool valid = check(state, nullptr);
        if (valid)
            ++freeQueries_;
        return valid;
    }

    std::string ManipulationValidityChecker::explain(const ompl::base::State *state) const
    {
        std::string reason;
        check(state, &reason);
        return reason;
    }

    bool ManipulationValidityChecker::check(const ompl::base::State *state, std::string *reason) const
    {
        // NaN or infinity would slip through every comparison below
        const double *q = space_->robotValues(state);
        bool finite = std::all_of(q, q + space_->robotDimension(), [](double v) { return std::isfinite(v); });
        for (unsigned int i = 0; i < space_->objectCount() && finite; ++i)
            finite =
                space_->objectPosition(state, i).allFinite() && std::isfinite(space_->objectYaw(state, i));
        if (!finite)
        {
            if (reason)
                *reason = "the state has a non-finite value";
            return false;
        }
        const RobotModel &robot = space_->model()->robot();
        for (unsigned int i = 0; i < robot.dof(); ++i)
        {
            const Joint &joint = robot.variableJoint(i);
            if (q[i] < joint.lower || q[i] > joint.upper)
            {
                if (reason)
                    *reason = "joint '" + joint.name + "' = " + std::to_string(q[i]) + " is outside [" +
                              std::to_string(joint.lower) + ", " + std::to_string(joint.upper) + "]";
                return false;
            }
        }

        int held = -1;
        for (unsigned int i = 0; i < space_->objectCount(); ++i)
        {
            poses_[i] = space_->objectPose(state, i);
            resting_[i] = space_->model()->scene().restingSurface(poses_[i].position);
            if (resting_[i] >= 0)
                continue;
            if (held >= 0)
            {
                if (reason)
                    *reason = "objects '" + space_->model()->scene().objects[held].name + "' and '" +
                              space_->model()->scene().objects[i].name + "' both rest on no surface";
                return false;
            }
            held = static_cast<int>(i);
        }
        return world_.isCollisionFree({q, &poses_, &resting_}, reason);
    }
}  // namespace ompl_mm
