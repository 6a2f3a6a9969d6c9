/* Reading MoveIt's SRDF files, the semantic description that sits beside a robot's URDF: planning
   groups, named group states, end effectors, the link pairs whose collisions are disabled and the
   virtual joints, each entry with the SRDF line it came from, so that checks made later against the
   URDF can name that line. Knows nothing of the robot model: expanding a group into its joints
   takes the robot's tree as two callbacks (groupJoints()).

   Kept, as fields of SrdfFile: <robot name>; <group> with its <joint>, <link>, <chain> and
   subgroup <group> children in document order; <group_state> with one number per <joint>;
   <end_effector>; <disable_collisions>; <virtual_joint> (a group may list it as a joint, so later
   checks must tell it from a misspelt URDF joint).

   Read and ignored: <passive_joint>, <joint_property>, <disable_default_collisions>,
   <enable_collisions> and <link_sphere_approximation> (with its <sphere> children). The planners
   here plan every URDF joint of a group and keep their own collision rules, so nothing uses them;
   their attribute names, required attributes and children are checked all the same, so a typo
   in them is reported rather than silently dropped.

   Stricter than MoveIt, which logs and skips bad entries: every fault below throws. References
   between SRDF entries are checked here (groups of states, end effectors and subgroups; subgroup
   cycles); names of URDF joints and links are not, since they need the robot. */
#pragma once

#include "ompl_core/io/SourceLocation.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace ompl_mm
{
    /** One child of a `<group>`: a joint, a link, a chain of links or another group. */
    struct SrdfGroupMember
    {
        /** What the member names. */
        enum class Kind
        {
            Joint,    ///< `<joint name>`: that joint
            Link,     ///< `<link name>`: the joint whose child is that link
            Chain,    ///< `<chain base_link tip_link>`: the joints on the chain from base to tip
            Subgroup  ///< `<group name>`: the joints of that group
        };
        Kind kind{Kind::Joint};           ///< which element it is, and so what name means
        std::string name;                 ///< joint, link or subgroup name; a chain's base link
        std::string tipLink;              ///< a chain's tip link; empty for the other kinds
        ompl_core::SourceLocation where;  ///< the SRDF line of the member's element
    };

    /** A planning group (`<group name>`): the joints a planner moves together, such as an arm. */
    struct SrdfGroup
    {
        std::string name;                      ///< unique among the groups
        std::vector<SrdfGroupMember> members;  ///< its children in document order; may be empty
        ompl_core::SourceLocation where;       ///< the SRDF line of `<group>`
    };

    /** One joint's value in a named group state. */
    struct SrdfJointValue
    {
        std::string joint;                ///< the joint's name (not checked against the URDF)
        double value{0.0};                ///< radians or metres as the joint's type says; finite
        ompl_core::SourceLocation where;  ///< the SRDF line of the `<joint>` element
    };

    /** A named configuration of a group (`<group_state name group>`), such as "ready". */
    struct SrdfGroupState
    {
        std::string name;                    ///< unique among the states of its group
        std::string group;                   ///< the name of a group of the file
        std::vector<SrdfJointValue> values;  ///< in document order, each joint at most once
        ompl_core::SourceLocation where;     ///< the SRDF line of `<group_state>`
    };

    /** An end effector (`<end_effector name group parent_link parent_group?>`): a group, such as a
        hand, attached to a link of the rest of the robot. */
    struct SrdfEndEffector
    {
        std::string name;                 ///< unique among the end effectors
        std::string group;                ///< the group of the end effector's own joints
        std::string parentLink;           ///< the link it is attached to (not checked against the URDF)
        std::string parentGroup;          ///< the group that moves parentLink; empty when not given
        ompl_core::SourceLocation where;  ///< the SRDF line of `<end_effector>`
    };

    /** Two links whose collisions are never checked (<disable_collisions link1 link2 reason?>). */
    struct SrdfDisabledPair
    {
        std::string link1;                ///< one link, as written
        std::string link2;                ///< the other link, as written
        std::string reason;               ///< MoveIt's "Adjacent", "Never", "Default"...; empty if not given
        ompl_core::SourceLocation where;  ///< the SRDF line of `<disable_collisions>`
    };

    /** A joint between the world and the robot's root link that the URDF does not hold
        (`<virtual_joint name type parent_frame child_link>`). */
    struct SrdfVirtualJoint
    {
        /** The joint's motion, written in lower case in the file. */
        enum class Type
        {
            Fixed,     ///< "fixed": no motion
            Floating,  ///< "floating": any pose
            Planar     ///< "planar": x, y and yaw in the plane
        };
        std::string name;                 ///< unique among the virtual joints
        Type type{Type::Fixed};           ///< its motion
        std::string parentFrame;          ///< the world frame it hangs from, such as "world"
        std::string childLink;            ///< the robot's link it moves (normally the URDF root)
        ompl_core::SourceLocation where;  ///< the SRDF line of `<virtual_joint>`
    };

    /** What an SRDF file holds that this project uses (see the file comment for what is ignored).
        A plain value; entries keep document order. */
    struct SrdfFile
    {
        std::string file;                                  ///< the file or source name read
        std::string robotName;                             ///< `<robot name>`, to match the URDF's
        std::vector<SrdfGroup> groups;                     ///< the planning groups
        std::vector<SrdfGroupState> groupStates;           ///< the named group states
        std::vector<SrdfEndEffector> endEffectors;         ///< the end effectors
        std::vector<SrdfDisabledPair> disabledCollisions;  ///< the link pairs never checked
        std::vector<SrdfVirtualJoint> virtualJoints;       ///< the virtual joints

        /** The group called name, or nullptr when there is none. */
        const SrdfGroup *findGroup(const std::string &name) const;

        /** The state called name of the group called group, or nullptr when there is none. */
        const SrdfGroupState *findGroupState(const std::string &group, const std::string &name) const;
    };

    /** Reads an SRDF file (see the file comment for what is kept).
        @throws ompl_core::InputError "path: SRDF file not found" (or unreadable), or with
        "path:line: message" for any fault readSrdfString() reports. */
    SrdfFile readSrdfFile(const std::string &path);

    /** Reads SRDF text; sourceName names it in messages and in SrdfFile::file.
        @throws ompl_core::InputError with "sourceName:line: message" for: malformed XML; a root
        other than `<robot>`; an element or attribute that SRDF does not have; a missing or empty
        required attribute; a joint value that is not one finite number (several numbers, for
        multi-dof joints, are refused); an unknown virtual joint type; a second group, end effector
        or virtual joint of one name, a second state of one name for one group, a joint set twice
        in a state; a state, end effector or subgroup naming no group of the file; a group that
        includes itself through its subgroups. */
    SrdfFile readSrdfString(const std::string &text, const std::string &sourceName);

    /** The joints on the chain of links from baseLink to tipLink, from base towards tip, as the
        robot model defines them (MoveIt: the parent joints of the links after baseLink up to
        tipLink); nothing (std::nullopt) when the robot has no such links or they form no chain. */
    using SrdfChainJoints = std::function<std::optional<std::vector<std::string>>(
        const std::string &baseLink, const std::string &tipLink)>;

    /** The joint whose child is link; "" when link is the robot's root; nothing (std::nullopt)
        when the robot has no such link. */
    using SrdfParentJoint = std::function<std::optional<std::string>(const std::string &link)>;

    /** The joint names of the group called group: its members in document order, a `<joint>` as
        written, a `<link>` as its parent joint (for the root link, the virtual joint whose child it
        is, or nothing), a `<chain>` as chainJoints() gives it, a subgroup as its own joints. Each
        name appears once, where it is first found. Names are not checked against the robot beyond
        what the callbacks report.
        @pre chainJoints and parentJoint are callable.
        @throws ompl_core::InputError "file: no group ..." when srdf has no such group; naming the
        member's SRDF line when a chain or link is unknown to the callbacks, a subgroup is unknown,
        or a subgroup includes a group that includes it (possible only in an SrdfFile built in
        code: readSrdfString() refuses those). */
    std::vector<std::string> groupJoints(const SrdfFile &srdf, const std::string &group,
                                         const SrdfChainJoints &chainJoints,
                                         const SrdfParentJoint &parentJoint);
}  // namespace ompl_mm
