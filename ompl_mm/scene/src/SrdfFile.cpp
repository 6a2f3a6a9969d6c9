#include "ompl_mm/scene/SrdfFile.h"

#include <tinyxml2.h>

#include <algorithm>
#include <cassert>
#include <iterator>
#include <set>
#include <sstream>
#include <utility>

#include "ompl_core/io/InputError.h"
#include "ompl_core/io/InputFile.h"
#include "ompl_core/io/TextFormat.h"
#include "ompl_core/io/XmlReading.h"

namespace ompl_mm
{
    namespace
    {
        using ompl_core::XmlElement;

        /** The names of all groups of srdf, for messages. */
        std::string srdfGroupNames(const SrdfFile &srdf)
        {
            std::vector<std::string> names;
            for (const SrdfGroup &group : srdf.groups)
                names.push_back(group.name);
            return ompl_core::joinedNames(names);
        }

        /** Checks a leaf element's attribute names (allowed) and that each of required is present
            and not empty. */
        void checkSrdfLeaf(const XmlElement &element, std::initializer_list<const char *> allowed,
                           std::initializer_list<const char *> required)
        {
            ompl_core::checkLeaf(element, allowed);
            for (const char *attribute : required)
                element.text(attribute);
        }

        /** Checks an SRDF element this project ignores: its attribute names, required attributes
            and children, as MoveIt reads them. */
        void checkIgnoredSrdfElement(const XmlElement &element)
        {
            const std::string tag = element.name();
            if (tag == "passive_joint")
                checkSrdfLeaf(element, {"name"}, {"name"});
            else if (tag == "joint_property")
                checkSrdfLeaf(element, {"joint_name", "property_name", "value"},
                              {"joint_name", "property_name", "value"});
            else if (tag == "disable_default_collisions")
                checkSrdfLeaf(element, {"link"}, {"link"});
            else if (tag == "enable_collisions")
                checkSrdfLeaf(element, {"link1", "link2", "reason"}, {"link1", "link2"});
            else
            {
                assert(tag == "link_sphere_approximation");
                element.checkAttributes({"link"});
                element.text("link");
                for (const XmlElement &sphere : element.children({"sphere"}))
                    checkSrdfLeaf(sphere, {"center", "radius"}, {"center", "radius"});
            }
        }

        /** Expands groups depth first, through their subgroups, finding unknown subgroups and
            cycles; with callbacks, also collects the joints of the groups visited. */
        class SrdfGroupWalk
        {
        public:
            /** Walks the groups of srdf; without callbacks (nullptr) it only checks subgroups. */
            SrdfGroupWalk(const SrdfFile &srdf, const SrdfChainJoints *chainJoints,
                          const SrdfParentJoint *parentJoint)
                : srdf_(srdf), chainJoints_(chainJoints), parentJoint_(parentJoint)
            {
            }

            /** Visits group and its subgroups unless visited before. */
            void visit(const SrdfGroup &group)
            {
                if (done_.count(group.name) > 0)
                    return;
                path_.push_back(group.name);
                for (const SrdfGroupMember &member : group.members)
                {
                    if (member.kind == SrdfGroupMember::Kind::Subgroup)
                        visit(subgroup(group, member));
                    else if (chainJoints_)
                        addMember(group, member);
                }
                path_.pop_back();
                done_.insert(group.name);
            }

            /** The joints found, in the order found. */
            const std::vector<std::string> &joints() const { return joints_; }

        private:
            /** The group that member names. @throws InputError when unknown or on the path. */
            const SrdfGroup &subgroup(const SrdfGroup &group, const SrdfGroupMember &member) const
            {
                const SrdfGroup *found = srdf_.findGroup(member.name);
                if (!found)
                    throw ompl_core::InputError(
                        member.where, "unknown subgroup '" + member.name + "' in <group> '" + group.name +
                                          "' (groups: " + srdfGroupNames(srdf_) + ")");
                const auto onPath = std::find(path_.begin(), path_.end(), member.name);
                if (onPath != path_.end())
                {
                    std::string cycle;
                    for (auto name = onPath; name != path_.end(); ++name)
                        cycle += "'" + *name + "' -> ";
                    throw ompl_core::InputError(
                        member.where, "<group> '" + member.name +
                                          "' includes itself through its subgroups: " + cycle + "'" +
                                          member.name + "'");
                }
                return *found;
            }

            /** Adds the joints of a joint, link or chain member. */
            void addMember(const SrdfGroup &group, const SrdfGroupMember &member)
            {
                const std::string in = " in <group> '" + group.name + "'";
                if (member.kind == SrdfGroupMember::Kind::Joint)
                    addJoint(member.name);
                else if (member.kind == SrdfGroupMember::Kind::Link)
                {
                    const std::optional<std::string> joint = (*parentJoint_)(member.name);
                    if (!joint)
                        throw ompl_core::InputError(member.where, "robot '" + srdf_.robotName +
                                                                      "' has no link '" + member.name +
                                                                      "' (<link>" + in + ")");
                    addJoint(joint->empty() ? rootJoint(member.name) : *joint);
                }
                else
                {
                    const std::optional<std::vector<std::string>> chain =
                        (*chainJoints_)(member.name, member.tipLink);
                    if (!chain)
                        throw ompl_core::InputError(member.where, "links '" + member.name + "' and '" +
                                                                      member.tipLink + "' of <chain>" + in +
                                                                      " form no chain of robot '" +
                                                                      srdf_.robotName + "'");
                    for (const std::string &joint : *chain)
                        addJoint(joint);
                }
            }

            /** The virtual joint whose child is the root link link, or "". */
            std::string rootJoint(const std::string &link) const
            {
                for (const SrdfVirtualJoint &joint : srdf_.virtualJoints)
                    if (joint.childLink == link)
                        return joint.name;
                return "";
            }

            /** Adds joint unless it is empty or was added before. */
            void addJoint(const std::string &joint)
            {
                if (!joint.empty() && seen_.insert(joint).second)
                    joints_.push_back(joint);
            }

            const SrdfFile &srdf_;
            const SrdfChainJoints *chainJoints_;
            const SrdfParentJoint *parentJoint_;
            std::vector<std::string> path_;  // the groups being visited, outermost first
            std::set<std::string> done_;     // the groups visited in full
            std::set<std::string> seen_;     // the joints added
            std::vector<std::string> joints_;
        };

        /** Builds an SrdfFile from the <robot> element: groups first, so that the other elements
            may name groups further down, as MoveIt allows. */
        class SrdfReader
        {
        public:
            /** Reads into an SrdfFile whose messages name file. */
            explicit SrdfReader(const std::string &file) { srdf_.file = file; }

            /** Reads the whole file from its root. */
            SrdfFile read(const XmlElement &root);

        private:
            void readRobotAttributes(const XmlElement &root);
            void readGroup(const XmlElement &element);
            SrdfGroupMember readMember(const XmlElement &element) const;
            void readGroupState(const XmlElement &element);
            double readJointValue(const XmlElement &element) const;
            void readEndEffector(const XmlElement &element);
            void readDisabledPair(const XmlElement &element);
            void readVirtualJoint(const XmlElement &element);
            /** The attribute's text, which must name a group of the file. */
            std::string groupReference(const XmlElement &element, const char *attribute) const;

            SrdfFile srdf_;
            ompl_core::FirstUses groupNames_;
            ompl_core::FirstUses stateNames_;  // group name, NUL, state name
            ompl_core::FirstUses endEffectorNames_;
            ompl_core::FirstUses virtualJointNames_;
        };

        SrdfFile SrdfReader::read(const XmlElement &root)
        {
            readRobotAttributes(root);
            const std::vector<XmlElement> children =
                root.children({"group", "group_state", "end_effector", "disable_collisions", "virtual_joint",
                               "passive_joint", "joint_property", "disable_default_collisions",
                               "enable_collisions", "link_sphere_approximation"});
            for (const XmlElement &child : children)
                if (child.name() == "group")
                    readGroup(child);
            for (const XmlElement &child : children)
            {
                const std::string tag = child.name();
                if (tag == "group")
                    continue;
                if (tag == "group_state")
                    readGroupState(child);
                else if (tag == "end_effector")
                    readEndEffector(child);
                else if (tag == "disable_collisions")
                    readDisabledPair(child);
                else if (tag == "virtual_joint")
                    readVirtualJoint(child);
                else
                    checkIgnoredSrdfElement(child);
            }
            // subgroups: known, and no cycles
            SrdfGroupWalk walk(srdf_, nullptr, nullptr);
            for (const SrdfGroup &group : srdf_.groups)
                walk.visit(group);
            return std::move(srdf_);
        }

        void SrdfReader::readRobotAttributes(const XmlElement &root)
        {
            // xacro-made SRDFs may keep their namespace declarations
            for (const auto &[name, value] : root.attributes())
                if (name != "name" && name.rfind("xmlns", 0) != 0)
                    root.fail(name.c_str(),
                              "unknown attribute '" + name + "' on <robot> (allowed: name, xmlns...)");
            srdf_.robotName = root.text("name");
        }

        void SrdfReader::readGroup(const XmlElement &element)
        {
            element.checkAttributes({"name"});
            SrdfGroup group;
            group.name = element.text("name");
            group.where = element.where();
            ompl_core::claimName(groupNames_, element, group.name,
                                 "second <group> named '" + group.name + "'");
            for (const XmlElement &child : element.children({"joint", "link", "chain", "group"}))
                group.members.push_back(readMember(child));
            srdf_.groups.push_back(std::move(group));
        }

        SrdfGroupMember SrdfReader::readMember(const XmlElement &element) const
        {
            SrdfGroupMember member;
            member.where = element.where();
            const std::string tag = element.name();
            if (tag == "chain")
            {
                ompl_core::checkLeaf(element, {"base_link", "tip_link"});
                member.kind = SrdfGroupMember::Kind::Chain;
                member.name = element.text("base_link");
                member.tipLink = element.text("tip_link");
                return member;
            }
            ompl_core::checkLeaf(element, {"name"});
            member.kind = tag == "joint"  ? SrdfGroupMember::Kind::Joint
                          : tag == "link" ? SrdfGroupMember::Kind::Link
                                          : SrdfGroupMember::Kind::Subgroup;
            member.name = element.text("name");
            return member;
        }

        void SrdfReader::readGroupState(const XmlElement &element)
        {
            element.checkAttributes({"name", "group"});
            SrdfGroupState state;
            state.name = element.text("name");
            state.group = groupReference(element, "group");
            state.where = element.where();
            ompl_core::claimName(
                stateNames_, element, state.group + std::string(1, '\0') + state.name,
                "second <group_state> named '" + state.name + "' for group '" + state.group + "'");
            ompl_core::FirstUses joints;
            for (const XmlElement &child : element.children({"joint"}))
            {
                ompl_core::checkLeaf(child, {"name", "value"});
                SrdfJointValue value;
                value.joint = child.text("name");
                ompl_core::claimName(
                    joints, child, value.joint,
                    "joint '" + value.joint + "' set twice in <group_state> '" + state.name + "'");
                value.value = readJointValue(child);
                value.where = child.where();
                state.values.push_back(std::move(value));
            }
            srdf_.groupStates.push_back(std::move(state));
        }

        double SrdfReader::readJointValue(const XmlElement &element) const
        {
            std::istringstream tokens(element.text("value"));
            const auto count = std::distance(std::istream_iterator<std::string>(tokens),
                                             std::istream_iterator<std::string>());
            if (count > 1)
                element.fail("value", "joint '" + element.text("name") + "' has " + std::to_string(count) +
                                          " values in '" + element.text("value") +
                                          "': only joints of one value are supported, not multi-dof joints");
            return element.number("value");
        }

        void SrdfReader::readEndEffector(const XmlElement &element)
        {
            element.checkAttributes({"name", "group", "parent_link", "parent_group"});
            element.children({});
            SrdfEndEffector effector;
            effector.name = element.text("name");
            ompl_core::claimName(endEffectorNames_, element, effector.name,
                                 "second <end_effector> named '" + effector.name + "'");
            effector.group = groupReference(element, "group");
            effector.parentLink = element.text("parent_link");
            if (element.has("parent_group"))
                effector.parentGroup = groupReference(element, "parent_group");
            effector.where = element.where();
            srdf_.endEffectors.push_back(std::move(effector));
        }

        void SrdfReader::readDisabledPair(const XmlElement &element)
        {
            ompl_core::checkLeaf(element, {"link1", "link2", "reason"});
            SrdfDisabledPair pair;
            pair.link1 = element.text("link1");
            pair.link2 = element.text("link2");
            pair.reason = element.text("reason", "");
            pair.where = element.where();
            srdf_.disabledCollisions.push_back(std::move(pair));
        }

        void SrdfReader::readVirtualJoint(const XmlElement &element)
        {
            ompl_core::checkLeaf(element, {"name", "type", "parent_frame", "child_link"});
            SrdfVirtualJoint joint;
            joint.name = element.text("name");
            ompl_core::claimName(virtualJointNames_, element, joint.name,
                                 "second <virtual_joint> named '" + joint.name + "'");
            const std::string type = element.text("type");
            if (type == "fixed")
                joint.type = SrdfVirtualJoint::Type::Fixed;
            else if (type == "floating")
                joint.type = SrdfVirtualJoint::Type::Floating;
            else if (type == "planar")
                joint.type = SrdfVirtualJoint::Type::Planar;
            else
                element.fail("type", "unknown type '" + type + "' of <virtual_joint> '" + joint.name +
                                         "' (known: fixed, floating, planar)");
            joint.parentFrame = element.text("parent_frame");
            joint.childLink = element.text("child_link");
            joint.where = element.where();
            srdf_.virtualJoints.push_back(std::move(joint));
        }

        std::string SrdfReader::groupReference(const XmlElement &element, const char *attribute) const
        {
            const std::string name = element.text(attribute);
            if (!srdf_.findGroup(name))
                element.fail(attribute, element.tag() + " names unknown group '" + name +
                                            "' (groups: " + srdfGroupNames(srdf_) + ")");
            return name;
        }
    }  // namespace

    const SrdfGroup *SrdfFile::findGroup(const std::string &name) const
    {
        for (const SrdfGroup &group : groups)
            if (group.name == name)
                return &group;
        return nullptr;
    }

    const SrdfGroupState *SrdfFile::findGroupState(const std::string &group, const std::string &name) const
    {
        for (const SrdfGroupState &state : groupStates)
            if (state.group == group && state.name == name)
                return &state;
        return nullptr;
    }

    SrdfFile readSrdfFile(const std::string &path)
    {
        return readSrdfString(ompl_core::readInputFile(path, "SRDF file"), path);
    }

    SrdfFile readSrdfString(const std::string &text, const std::string &sourceName)
    {
        tinyxml2::XMLDocument document;
        const XmlElement root = ompl_core::parseRootElement(document, text, sourceName, "robot");
        return SrdfReader(sourceName).read(root);
    }

    std::vector<std::string> groupJoints(const SrdfFile &srdf, const std::string &group,
                                         const SrdfChainJoints &chainJoints,
                                         const SrdfParentJoint &parentJoint)
    {
        assert(chainJoints && parentJoint);
        const SrdfGroup *found = srdf.findGroup(group);
        if (!found)
            throw ompl_core::InputError(ompl_core::SourceLocation{srdf.file, 0},
                                        "no group '" + group + "' (groups: " + srdfGroupNames(srdf) + ")");
        SrdfGroupWalk walk(srdf, &chainJoints, &parentJoint);
        walk.visit(*found);
        return walk.joints();
    }
}  // namespace ompl_mm
