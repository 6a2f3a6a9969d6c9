#include "ompl_mm/setup/SceneRobot.h"

#include "ompl_core/io/InputError.h"
#include "ompl_mm/scene/SrdfFile.h"

#include <algorithm>
#include <optional>
#include <utility>

namespace ompl_mm
{
    namespace
    {
        /** The robot of the URDF, which must have collision geometry: a robot without it would pass
            through everything and every plan would be wrong. */
        RobotModel readUrdf(const Scene &scene)
        {
            RobotModel robot;
            try
            {
                robot = RobotModel::fromUrdfFile(scene.robot.urdfFile);
            }
            catch (const ompl::Exception &e)
            {
                throw ompl_core::InputError(scene.robot.where, e.what());
            }
            const std::vector<Link> &links = robot.links();
            if (std::all_of(links.begin(), links.end(), [](const Link &link) { return link.shapes.empty(); }))
                throw ompl_core::InputError(scene.robot.where,
                                            "robot '" + robot.name() + "' (" + scene.robot.urdfFile +
                                                ") has no collision geometry on any link: it would pass "
                                                "through everything");
            return robot;
        }

        /** The joint names of an SRDF group, its chains and links found in robot's tree. */
        std::vector<std::string> jointsOfGroup(const SrdfFile &srdf, const std::string &group,
                                               const RobotModel &robot)
        {
            const auto jointOf = [&robot](int link)
            { return robot.joints()[robot.links()[link].joint].name; };
            const SrdfChainJoints chain =
                [&](const std::string &base,
                    const std::string &tip) -> std::optional<std::vector<std::string>>
            {
                const int baseLink = robot.findLink(base), tipLink = robot.findLink(tip);
                if (baseLink < 0 || tipLink < 0 || !robot.isInSubtree(tipLink, baseLink))
                    return std::nullopt;
                std::vector<std::string> joints;
                for (int link = tipLink; link != baseLink; link = robot.links()[link].parent)
                    joints.insert(joints.begin(), jointOf(link));
                return joints;
            };
            const SrdfParentJoint parent = [&](const std::string &name) -> std::optional<std::string>
            {
                const int link = robot.findLink(name);
                if (link < 0)
                    return std::nullopt;
                return link == 0 ? std::string() : jointOf(link);
            };
            return groupJoints(srdf, group, chain, parent);
        }

        const Joint *findJoint(const RobotModel &robot, const std::string &name)
        {
            for (const Joint &joint : robot.joints())
                if (joint.name == name)
                    return &joint;
            return nullptr;
        }

        /** Where a joint no group plans is held: 0, or the middle of its limits when 0 lies outside. */
        double restingValue(const Joint &joint)
        {
            return joint.lower <= 0.0 && joint.upper >= 0.0 ? 0.0 : 0.5 * (joint.lower + joint.upper);
        }

        /** Holds every moving joint that follows no other and lies outside the planning group. */
        RobotModel planGroup(const Scene &scene, const SrdfFile &srdf, const RobotModel &robot)
        {
            if (srdf.findGroup(scene.robot.group) == nullptr)
                throw ompl_core::InputError(
                    scene.robot.where,
                    "SRDF file '" + srdf.file + "' has no group '" + scene.robot.group + "'");
            const std::vector<std::string> planned = jointsOfGroup(srdf, scene.robot.group, robot);
            for (const std::string &name : planned)
            {
                const bool virtualJoint =
                    std::any_of(srdf.virtualJoints.begin(), srdf.virtualJoints.end(),
                                [&name](const SrdfVirtualJoint &joint) { return joint.name == name; });
                if (!virtualJoint && findJoint(robot, name) == nullptr)
                    throw ompl_core::InputError(srdf.findGroup(scene.robot.group)->where,
                                                "group '" + scene.robot.group + "' names joint '" + name +
                                                    "', which robot '" + robot.name() + "' does not have");
            }
            std::vector<std::pair<std::string, double>> held;
            for (unsigned int i = 0; i < robot.dof(); ++i)
            {
                const Joint &joint = robot.variableJoint(i);
                const bool fixedByScene =
                    std::any_of(scene.robot.fixedJoints.begin(), scene.robot.fixedJoints.end(),
                                [&joint](const FixedJointValue &fixed) { return fixed.joint == joint.name; });
                if (!fixedByScene && std::find(planned.begin(), planned.end(), joint.name) == planned.end())
                    held.emplace_back(joint.name, restingValue(joint));
            }
            if (held.size() == robot.dof())
                throw ompl_core::InputError(
                    scene.robot.where, "group '" + scene.robot.group +
                                           "' holds none of the moving joints of robot '" + robot.name() +
                                           "' (" + robot.variableNames() + ")");
            return robot.withJointsFixed(held);
        }

        /** The links of the end effectors that belong to the planning group (all, without one). */
        std::vector<std::string> endEffectorLinks(const Scene &scene, const SrdfFile &srdf,
                                                  const RobotModel &robot)
        {
            std::vector<std::string> links;
            for (const SrdfEndEffector &effector : srdf.endEffectors)
            {
                if (!scene.robot.group.empty() && !effector.parentGroup.empty() &&
                    effector.parentGroup != scene.robot.group)
                    continue;
                for (const std::string &joint : jointsOfGroup(srdf, effector.group, robot))
                    for (const Link &link : robot.links())
                        if (link.joint >= 0 && robot.joints()[link.joint].name == joint)
                            links.push_back(link.name);
            }
            return links;
        }

        /** The planning joints' values in the named state: the planning group's state of that name,
            or else the first state of that name of any group. */
        std::vector<double> stateValues(const SrdfFile &srdf, const std::string &group,
                                        const std::string &name, const RobotModel &robot,
                                        const ompl_core::SourceLocation &where)
        {
            const SrdfGroupState *state = srdf.findGroupState(group, name);
            for (const SrdfGroupState &candidate : srdf.groupStates)
                if (state == nullptr && candidate.name == name)
                    state = &candidate;
            if (state == nullptr)
                throw ompl_core::InputError(
                    where, "SRDF file '" + srdf.file + "' has no group state '" + name + "'");
            std::vector<double> values;
            for (unsigned int i = 0; i < robot.dof(); ++i)
            {
                const std::string &joint = robot.variableJoint(i).name;
                auto it =
                    std::find_if(state->values.begin(), state->values.end(),
                                 [&joint](const SrdfJointValue &value) { return value.joint == joint; });
                if (it == state->values.end())
                    throw ompl_core::InputError(
                        where,
                        "state '" + name + "' of group '" + state->group + "' (" + state->where.str() +
                            ") gives no value for planning joint '" + joint +
                            "'; hold it with <fixed_joint> or choose a planning group (attribute group)");
                values.push_back(it->value);
            }
            return values;
        }

        /** Adds what the SRDF says to scene and holds the joints outside its planning group. */
        RobotModel applySrdf(Scene &scene, const SrdfFile &srdf, RobotModel robot)
        {
            if (!scene.robot.group.empty())
                robot = planGroup(scene, srdf, robot);
            for (const SrdfDisabledPair &pair : srdf.disabledCollisions)
                scene.robot.allowedCollisions.push_back({pair.link1, pair.link2, pair.where});
            for (std::string &link : endEffectorLinks(scene, srdf, robot))
                scene.robot.gripperLinks.push_back(std::move(link));
            return robot;
        }

        /** Turns the start's and the goal's named states into joint values (after every joint is held
            that will be, so the values are the planning joints'). */
        void resolveStates(Scene &scene, const SrdfFile &srdf, const RobotModel &robot)
        {
            if (!scene.robotStartState.empty())
                scene.robotStart =
                    stateValues(srdf, scene.robot.group, scene.robotStartState, robot, scene.robotStartWhere);
            if (!scene.robotGoal.state.empty())
            {
                const std::vector<double> goal =
                    stateValues(srdf, scene.robot.group, scene.robotGoal.state, robot, scene.robotGoal.where);
                scene.robotGoal.joints.assign(goal.begin(), goal.end());
            }
        }
    }  // namespace

    SceneRobot loadSceneRobot(const Scene &scene)
    {
        SceneRobot loaded{scene, readUrdf(scene)};
        // the scene loader lets named states through only with an SRDF
        const std::optional<SrdfFile> srdf =
            scene.robot.srdfFile.empty() ? std::nullopt
                                         : std::optional<SrdfFile>(readSrdfFile(scene.robot.srdfFile));
        if (srdf)
            loaded.robot = applySrdf(loaded.scene, *srdf, std::move(loaded.robot));
        for (const FixedJointValue &fixed : scene.robot.fixedJoints)
            try
            {
                loaded.robot = loaded.robot.withJointsFixed({{fixed.joint, fixed.value}});
            }
            catch (const ompl::Exception &e)
            {
                throw ompl_core::InputError(fixed.where, e.what());
            }
        if (srdf)
            resolveStates(loaded.scene, *srdf, loaded.robot);
        else if (!scene.robotStartState.empty() || !scene.robotGoal.state.empty())
            throw ompl_core::InputError(
                scene.robotStartState.empty() ? scene.robotGoal.where : scene.robotStartWhere,
                "a named state needs the robot's SRDF file (RobotSpec::srdfFile)");
        return loaded;
    }
}  // namespace ompl_mm
