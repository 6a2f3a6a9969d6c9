#include "ompl_mm/base/ManipulationGoal.h"

#include "ompl_core/io/InputError.h"

#include <ompl/base/SpaceInformation.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ompl_mm
{
    namespace
    {
        /** By how much a difference misses its tolerance: 0 within it, infinity for NaN. */
        double excess(double difference, double tolerance)
        {
            const double miss = std::abs(difference) - tolerance;
            if (std::isnan(miss))
                return std::numeric_limits<double>::infinity();
            return std::max(0.0, miss);
        }

        double excess(double value, const GoalCoordinate &target, double tolerance)
        {
            return target ? excess(value - *target, tolerance) : 0.0;
        }

        /** The surfaces on which an object can meet its goal's defined coordinates. */
        std::vector<const SupportSurface *> surfacesFor(const ObjectGoal *goal, const Scene &scene)
        {
            const auto fits = [goal](int k, double low, double high) {
                return !goal || !goal->position[k] ||
                       (*goal->position[k] >= low && *goal->position[k] <= high);
            };
            std::vector<const SupportSurface *> surfaces;
            for (const SupportSurface &s : scene.surfaces)
                if (fits(0, s.min.x(), s.max.x()) && fits(1, s.min.y(), s.max.y()) &&
                    fits(2, s.height - SupportSurface::REST_TOLERANCE,
                         s.height + SupportSurface::REST_TOLERANCE))
                    surfaces.push_back(&s);
            return surfaces;
        }
    }  // namespace

    ManipulationGoal::ManipulationGoal(const ompl::base::SpaceInformationPtr &si)
        : ompl::base::GoalSampleableRegion(si), space_(si->getStateSpace()->as<ManipulationStateSpace>())
    {
        setThreshold(0.0);
        const ManipulationModel &model = *space_->model();
        const Scene &scene = model.scene();
        robot_ = scene.robotGoal;
        if (!robot_.joints.empty() && robot_.joints.size() != model.dof())
            throw ompl_core::InputError(robot_.where, "goal has " + std::to_string(robot_.joints.size()) +
                                                          " joint values but the robot has " +
                                                          std::to_string(model.dof()) + " moving joints (" +
                                                          model.robot().variableNames() + ")");
        for (std::size_t j = 0; j < robot_.joints.size(); ++j)
        {
            const Joint &joint = model.robot().variableJoint(j);
            if (robot_.joints[j] && (*robot_.joints[j] < joint.lower || *robot_.joints[j] > joint.upper))
                throw ompl_core::InputError(robot_.where, "goal value " + std::to_string(*robot_.joints[j]) +
                                                              " of joint '" + joint.name +
                                                              "' is outside its limits");
        }

        objects_.assign(model.objectCount(), nullptr);
        for (const ObjectGoal &goal : scene.objectGoals)
        {
            const int index = scene.objectIndex(goal.object);
            if (index < 0)
                throw ompl_core::InputError(goal.where, "goal names unknown object '" + goal.object + "'");
            objects_[index] = &goal;
            if (surfacesFor(&goal, scene).empty())
                throw ompl_core::InputError(goal.where,
                                            "goal of object '" + goal.object +
                                                "' lies on no support surface, so it can never rest there");
        }
    }

    bool ManipulationGoal::constrainsObject(unsigned int object) const
    {
        const ObjectGoal *goal = objects_[object];
        return goal && (goal->position[0] || goal->position[1] || goal->position[2] || goal->yaw);
    }

    bool ManipulationGoal::constrainsRobot() const
    {
        return std::any_of(robot_.joints.begin(), robot_.joints.end(),
                           [](const auto &j) { return j.has_value(); });
    }

    double ManipulationGoal::distanceGoal(const ompl::base::State *state) const
    {
        double distance = 0.0;
        const double *q = space_->robotValues(state);
        if (!std::all_of(q, q + space_->robotDimension(), [](double v) { return std::isfinite(v); }))
            return std::numeric_limits<double>::infinity();
        for (std::size_t j = 0; j < robot_.joints.size(); ++j)
            distance = std::max(distance, excess(q[j], robot_.joints[j], robot_.tolerance));
        double unsupported = 0.0;
        for (unsigned int i = 0; i < space_->objectCount(); ++i)
        {
            const ObjectPose pose = space_->objectPose(state, i);
            if (!pose.position.allFinite() || !std::isfinite(pose.yaw))
                return std::numeric_limits<double>::infinity();
            if (space_->model()->scene().restingSurface(pose.position) < 0)
                unsupported += 1.0;
            const ObjectGoal *goal = objects_[i];
            if (!goal)
                continue;
            for (int k = 0; k < 3; ++k)
                distance =
                    std::max(distance, excess(pose.position[k], goal->position[k], goal->positionTolerance));
            if (goal->yaw)
                distance = std::max(
                    distance, excess(std::remainder(pose.yaw - *goal->yaw, 2.0 * M_PI), goal->yawTolerance));
        }
        return distance + unsupported;
    }

    bool ManipulationGoal::isSatisfied(const ompl::base::State *state) const
    {
        return distanceGoal(state) <= 0.0;
    }

    bool ManipulationGoal::isSatisfied(const ompl::base::State *state, double *distance) const
    {
        const double d = distanceGoal(state);
        if (distance)
            *distance = d;
        return d <= 0.0;
    }

    void ManipulationGoal::completeObject(unsigned int object, const ObjectPose *fromSample, ObjectPose &pose,
                                          ompl::RNG &rng, bool keepNearValues) const
    {
        const Scene &scene = space_->model()->scene();
        const ObjectGoal *goal = objects_[object];
        const std::vector<const SupportSurface *> candidates = surfacesFor(goal, scene);
        if (fromSample && space_->model()->scene().restingSurface(fromSample->position) >= 0)
        {
            pose = *fromSample;
        }
        else
        {
            // no sample value: a uniform place on a surface the goal allows
            const SupportSurface &s = *candidates[rng.uniformInt(0, static_cast<int>(candidates.size()) - 1)];
            pose.position = {rng.uniformReal(s.min.x(), s.max.x()), rng.uniformReal(s.min.y(), s.max.y()),
                             s.height};
            pose.yaw = scene.objects[object].start.yaw;
        }
        const bool sampled = fromSample && pose.position == fromSample->position;
        if (goal)
        {
            for (int k = 0; k < 3; ++k)
                if (goal->position[k] &&
                    !(keepNearValues && sampled &&
                      std::abs(pose.position[k] - *goal->position[k]) <= goal->positionTolerance))
                    pose.position[k] = *goal->position[k];
            if (goal->yaw &&
                !(keepNearValues && sampled &&
                  std::abs(std::remainder(pose.yaw - *goal->yaw, 2.0 * M_PI)) <= goal->yawTolerance))
                pose.yaw = *goal->yaw;
        }
        // the goal's x, y may move the object off the sampled surface: rest it on one that fits
        if (space_->model()->scene().restingSurface(pose.position) < 0)
            for (const SupportSurface *s : candidates)
                if (s->contains(pose.position.x(), pose.position.y()))
                {
                    pose.position.z() = s->height;
                    break;
                }
    }

    void ManipulationGoal::complete(const PartialState &sample, ompl::base::State *out, ompl::RNG &rng,
                                    bool keepNearValues) const
    {
        double *q = space_->robotValues(out);
        const double *sampleQ = space_->robotValues(sample.state());
        const RobotModel &robot = space_->model()->robot();
        for (unsigned int j = 0; j < robot.dof(); ++j)
        {
            if (j < robot_.joints.size() && robot_.joints[j])
                q[j] = *robot_.joints[j];
            else if (sample.robotDefined())
                q[j] = sampleQ[j];
            else
                q[j] = rng.uniformReal(robot.variableJoint(j).lower, robot.variableJoint(j).upper);
        }
        for (unsigned int i = 0; i < space_->objectCount(); ++i)
        {
            ObjectPose pose;
            ObjectPose samplePose;
            if (sample.objectDefined(i))
                samplePose = space_->objectPose(sample.state(), i);
            completeObject(i, sample.objectDefined(i) ? &samplePose : nullptr, pose, rng, keepNearValues);
            space_->setObjectPose(out, i, pose);
        }
    }

    void ManipulationGoal::print(std::ostream &out) const
    {
        out << "Manipulation goal: " << (constrainsRobot() ? "robot joints, " : "");
        for (unsigned int i = 0; i < space_->objectCount(); ++i)
            if (constrainsObject(i))
                out << "object '" << space_->model()->scene().objects[i].name << "', ";
        out << "all objects resting" << std::endl;
    }

    void ManipulationGoal::sampleGoal(ompl::base::State *state) const
    {
        PartialState sample(space_);
        sample.setRobotDefined(false);
        for (unsigned int i = 0; i < space_->objectCount(); ++i)
            space_->setObjectPose(sample.state(), i, space_->model()->scene().objects[i].start);
        complete(sample, state, rng_);
    }

    unsigned int ManipulationGoal::maxSampleCount() const
    {
        return std::numeric_limits<unsigned int>::max();
    }
}  // namespace ompl_mm
