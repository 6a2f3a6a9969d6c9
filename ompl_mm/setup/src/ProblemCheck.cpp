#include "ompl_mm/setup/ProblemCheck.h"

#include "ompl_core/io/InputError.h"
#include "ompl_core/io/TextFormat.h"
#include "ompl_mm/primitives/EmptySpacePlanner.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iterator>

namespace ompl_mm
{
    ProblemCheck::ProblemCheck(const ManipulationStateSpace &space) : space_(space), world_(space.model()) {}

    void ProblemCheck::rejectCollisions(const double *joints, const ompl_core::SourceLocation &robotWhere,
                                        const std::vector<std::optional<ObjectPose>> &poses,
                                        const std::vector<ompl_core::SourceLocation> &wheres,
                                        const std::string &what, const std::string &when) const
    {
        const std::size_t n = poses.size();
        auto reject = [&](const ompl_core::SourceLocation &where, const std::string &contact)
        {
            if (!contact.empty())
                throw ompl_core::InputError(where, what + ": " + contact + " collide" + when);
        };
        auto only = [&](std::initializer_list<std::size_t> objects)
        {
            std::vector<std::optional<ObjectPose>> chosen(n);
            for (std::size_t i : objects)
                chosen[i] = poses[i];
            return chosen;
        };
        for (std::size_t i = 0; i < n; ++i)
            if (poses[i])
                reject(wheres[i], world_.contactAmong(nullptr, only({i})));
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j)
                if (poses[i] && poses[j])
                    reject(wheres[j], world_.contactAmong(nullptr, only({i, j})));
        if (!joints)
            return;
        reject(robotWhere, world_.contactAmong(joints, only({})));
        for (std::size_t i = 0; i < n; ++i)
            if (poses[i])
                reject(wheres[i], world_.contactAmong(joints, only({i})));
    }

    void ProblemCheck::rejectStart(const ompl::base::State *start, const std::string &reason) const
    {
        const Scene &scene = space_.model()->scene();
        std::vector<std::optional<ObjectPose>> poses;
        std::vector<ompl_core::SourceLocation> wheres;
        for (unsigned int i = 0; i < space_.objectCount(); ++i)
        {
            poses.emplace_back(space_.objectPose(start, i));
            wheres.push_back(scene.objects[i].where);
        }
        // a collision is the reason when the whole start collides that way; else (joint limits,
        // two held objects, non-finite values) the reason says it all
        if (world_.contactAmong(space_.robotValues(start), poses) == reason)
            rejectCollisions(space_.robotValues(start), scene.robotStartWhere, poses, wheres,
                             "the start state is invalid", "");
        throw ompl_core::InputError(scene.robotStartWhere, "the start state is invalid: " + reason);
    }

    std::optional<ObjectPose> ProblemCheck::goalPose(const ObjectGoal &goal,
                                                     const ompl::base::State *start) const
    {
        if (!goal.position[0] || !goal.position[1])
            return std::nullopt;
        ObjectPose pose = space_.objectPose(start, space_.model()->scene().objectIndex(goal.object));
        pose.position.x() = *goal.position[0];
        pose.position.y() = *goal.position[1];
        pose.position.z() = goal.position[2].value_or(pose.position.z());
        pose.yaw = goal.yaw.value_or(pose.yaw);
        return pose;
    }

    bool ProblemCheck::tries(EmptySpacePlanner &planner, const ompl::base::State *from,
                             const ompl::base::State *to, ompl::RNG &rng, Trajectory &trajectory,
                             const std::function<bool(const ompl::base::State *)> &arrived) const
    {
        // primitives that search (inverse kinematics) may miss once: only repeated misses count
        for (unsigned int attempt = 0; attempt < REACH_ATTEMPTS; ++attempt)
            if (planner.plan(from, to, trajectory, rng) != EmptySpacePlanner::Outcome::Failed &&
                arrived(trajectory.back()))
                return true;
        return false;
    }

    bool ProblemCheck::movesThere(EmptySpacePlanner &planner, const ompl::base::State *from,
                                  const ompl::base::State *to, unsigned int object, ompl::RNG &rng,
                                  Trajectory &trajectory) const
    {
        return tries(planner, from, to, rng, trajectory,
                     [&](const ompl::base::State *end) { return !space_.objectMoves(end, to, object); });
    }

    bool ProblemCheck::carriesThere(EmptySpacePlanner &lifting, EmptySpacePlanner &planner,
                                    const ompl::base::State *from, const ompl::base::State *to,
                                    unsigned int object, ompl::RNG &rng, Trajectory &trajectory) const
    {
        // first picked up: the pickups towards the object above its goal (they lift it, by their
        // own height, where the hand grasps it) ...
        ompl::base::State *held = space_.cloneState(to);
        ObjectPose above = space_.objectPose(to, object);
        above.position.z() += CARRY_HEIGHT;
        space_.setObjectPose(held, object, above);
        bool carried =
            space_.restingSurface(held, object) < 0 &&
            tries(lifting, from, held, rng, trajectory,
                  [&](const ompl::base::State *end) { return space_.restingSurface(end, object) < 0; });
        if (carried)
        {
            // ... then set down at the goal from where the robot holds it
            space_.copyState(held, trajectory.back());
            ompl::base::State *placed = space_.cloneState(held);
            space_.setObjectPose(placed, object, space_.objectPose(to, object));
            carried = movesThere(planner, held, placed, object, rng, trajectory);
            space_.freeState(placed);
        }
        space_.freeState(held);
        return carried;
    }

    void ProblemCheck::checkGoal(const ompl::base::State *start,
                                 const std::vector<PrimitivePtr> &primitives) const
    {
        const Scene &scene = space_.model()->scene();
        std::vector<std::optional<ObjectPose>> poses(space_.objectCount());
        std::vector<ompl_core::SourceLocation> wheres(space_.objectCount());
        for (const ObjectGoal &goal : scene.objectGoals)
        {
            const int object = scene.objectIndex(goal.object);
            poses[object] = goalPose(goal, start);
            wheres[object] = goal.where;
        }
        const std::vector<GoalCoordinate> &jointGoals = scene.robotGoal.joints;
        std::vector<double> joints;
        for (const GoalCoordinate &joint : jointGoals)
            if (joint)
                joints.push_back(*joint);
        const bool robotGiven = !jointGoals.empty() && joints.size() == jointGoals.size();
        rejectCollisions(robotGiven ? joints.data() : nullptr, scene.robotGoal.where, poses, wheres,
                         "the goal cannot be reached", " at their goal poses");

        // each object the goal moves: can the primitives move it there, obstacles aside?
        // simulated primitives answer through the kinematic ones they simulate: a simulated push
        // ends near its target, never exactly on it
        std::vector<PrimitivePtr> models;
        for (const PrimitivePtr &primitive : primitives)
            models.push_back(primitive->kinematicModel() ? primitive->kinematicModel() : primitive);
        EmptySpacePlanner planner(&space_, models);
        std::vector<PrimitivePtr> pickups;
        std::copy_if(models.begin(), models.end(), std::back_inserter(pickups),
                     [](const PrimitivePtr &model) { return model->kind() == PrimitiveKind::Pickup; });
        EmptySpacePlanner lifting(&space_, pickups);
        ompl::RNG rng(1);
        Trajectory trajectory(&space_);
        ompl::base::State *target = space_.cloneState(start);
        const ObjectGoal *unreachable = nullptr;
        for (const ObjectGoal &goal : scene.objectGoals)
        {
            const unsigned int object = static_cast<unsigned int>(scene.objectIndex(goal.object));
            ObjectPose pose = space_.objectPose(start, object);
            for (int c = 0; c < 3; ++c)
                if (goal.position[c] &&
                    std::abs(pose.position[c] - *goal.position[c]) > goal.positionTolerance)
                    pose.position[c] = *goal.position[c];
            if (goal.yaw && std::abs(std::remainder(pose.yaw - *goal.yaw, 2 * M_PI)) > goal.yawTolerance)
                pose.yaw = *goal.yaw;
            space_.copyState(target, start);
            space_.setObjectPose(target, object, pose);
            if (!movesThere(planner, start, target, object, rng, trajectory) &&
                (pickups.empty() || !carriesThere(lifting, planner, start, target, object, rng, trajectory)))
            {
                unreachable = &goal;
                break;
            }
        }
        space_.freeState(target);
        if (unreachable)
        {
            std::vector<std::string> names;
            for (const PrimitivePtr &primitive : primitives)
                names.push_back(primitive->name());
            // what the primitives found wrong, so that the fix can be found (a grasp the hand cannot
            // reach, a push pose in collision)
            std::string why;
            for (const auto &[kind, record] : planner.tally().records())
                if (record.noMotion > 0)
                    why += "; " + kind + ": " + std::to_string(record.noMotion) + " of " +
                           std::to_string(record.attempts) + " attempts " + record.mainReason().first + " (" +
                           std::to_string(record.mainReason().second) + " times)";
            throw ompl_core::InputError(unreachable->where,
                                        "the goal cannot be reached: object '" + unreachable->object +
                                            "' must move to its goal but no primitive of the "
                                            "scene can move it there (primitives: " +
                                            ompl_core::joinedNames(names) + why + ")");
        }
    }
}  // namespace ompl_mm
