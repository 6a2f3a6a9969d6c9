// Tests for SrdfFile: reading MoveIt's SRDF files and expanding their groups into joints.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "common/InputErrors.h"
#include "common/ScratchDirectory.h"
#include "ompl_mm/scene/SrdfFile.h"

using namespace ompl_mm;
using ompl_core::test::contains;
using ompl_core::test::inputErrorOf;
using ompl_core::test::startsWith;

namespace
{
    /** A Panda SRDF as MoveIt Setup Assistant writes it. */
    const std::string PANDA_SRDF = R"(<?xml version="1.0" encoding="UTF-8"?>
<!--This does not replace URDF, and is not an extension of URDF.-->
<robot name="panda">
    <!--GROUPS: Representation of a set of joints and links.-->
    <group name="panda_arm">
        <chain base_link="panda_link0" tip_link="panda_link8"/>
    </group>
    <group name="hand">
        <link name="panda_hand"/>
        <link name="panda_leftfinger"/>
        <link name="panda_rightfinger"/>
    </group>
    <group name="panda_arm_hand">
        <group name="panda_arm"/>
        <group name="hand"/>
    </group>
    <group_state name="ready" group="panda_arm">
        <joint name="panda_joint1" value="0"/>
        <joint name="panda_joint2" value="-0.785"/>
        <joint name="panda_joint3" value="0"/>
        <joint name="panda_joint4" value="-2.356"/>
        <joint name="panda_joint5" value="0"/>
        <joint name="panda_joint6" value="1.571"/>
        <joint name="panda_joint7" value="0.785"/>
    </group_state>
    <group_state name="extended" group="panda_arm">
        <joint name="panda_joint1" value="0"/>
        <joint name="panda_joint2" value="0"/>
        <joint name="panda_joint3" value="0"/>
        <joint name="panda_joint4" value="-0.1"/>
        <joint name="panda_joint5" value="0"/>
        <joint name="panda_joint6" value="3.14159"/>
        <joint name="panda_joint7" value="0.785"/>
    </group_state>
    <group_state name="open" group="hand">
        <joint name="panda_finger_joint1" value="0.035"/>
        <joint name="panda_finger_joint2" value="0.035"/>
    </group_state>
    <group_state name="close" group="hand">
        <joint name="panda_finger_joint1" value="0"/>
        <joint name="panda_finger_joint2" value="0"/>
    </group_state>
    <!--END EFFECTOR: Purpose: Represent information about an end effector.-->
    <end_effector name="hand" parent_link="panda_link8" group="hand" parent_group="panda_arm"/>
    <virtual_joint name="virtual_joint" type="fixed" parent_frame="world" child_link="panda_link0"/>
    <passive_joint name="panda_finger_joint2"/>
    <disable_collisions link1="panda_hand" link2="panda_leftfinger" reason="Adjacent"/>
    <disable_collisions link1="panda_hand" link2="panda_link3" reason="Never"/>
    <disable_collisions link1="panda_hand" link2="panda_link4" reason="Never"/>
    <disable_collisions link1="panda_hand" link2="panda_link6" reason="Never"/>
    <disable_collisions link1="panda_hand" link2="panda_link7" reason="Default"/>
    <disable_collisions link1="panda_hand" link2="panda_link8" reason="Adjacent"/>
    <disable_collisions link1="panda_hand" link2="panda_rightfinger" reason="Adjacent"/>
    <disable_collisions link1="panda_leftfinger" link2="panda_link3" reason="Never"/>
    <disable_collisions link1="panda_leftfinger" link2="panda_link4" reason="Never"/>
    <disable_collisions link1="panda_leftfinger" link2="panda_link6" reason="Never"/>
    <disable_collisions link1="panda_leftfinger" link2="panda_link7" reason="Never"/>
    <disable_collisions link1="panda_leftfinger" link2="panda_link8" reason="Never"/>
    <disable_collisions link1="panda_leftfinger" link2="panda_rightfinger" reason="Default"/>
    <disable_collisions link1="panda_link0" link2="panda_link1" reason="Adjacent"/>
    <disable_collisions link1="panda_link0" link2="panda_link2" reason="Never"/>
    <disable_collisions link1="panda_link0" link2="panda_link3" reason="Never"/>
    <disable_collisions link1="panda_link0" link2="panda_link4" reason="Never"/>
    <disable_collisions link1="panda_link1" link2="panda_link2" reason="Adjacent"/>
    <disable_collisions link1="panda_link1" link2="panda_link3" reason="Never"/>
    <disable_collisions link1="panda_link1" link2="panda_link4" reason="Never"/>
    <disable_collisions link1="panda_link2" link2="panda_link3" reason="Adjacent"/>
    <disable_collisions link1="panda_link2" link2="panda_link4" reason="Never"/>
    <disable_collisions link1="panda_link3" link2="panda_link4" reason="Adjacent"/>
    <disable_collisions link1="panda_link4" link2="panda_link5" reason="Adjacent"/>
</robot>
)";

    /** The lines of text. */
    std::vector<std::string> splitLines(const std::string &text)
    {
        std::vector<std::string> lines;
        std::istringstream in(text);
        for (std::string line; std::getline(in, line);)
            lines.push_back(line);
        return lines;
    }

    std::string joined(const std::vector<std::string> &lines)
    {
        std::string text;
        for (const std::string &line : lines)
            text += line + "\n";
        return text;
    }

    /** A member as "kind name[ tip]@file:line", to compare whole groups at once. */
    std::string describe(const SrdfGroupMember &member)
    {
        const std::array<std::string, 4> kinds = {"joint", "link", "chain", "group"};
        return kinds.at(static_cast<std::size_t>(member.kind)) + " " + member.name +
               (member.tipLink.empty() ? "" : " " + member.tipLink) + "@" + member.where.str();
    }

    /** A group as "name@file:line" and its members, described. */
    std::vector<std::string> describe(const SrdfGroup &group)
    {
        std::vector<std::string> described = {group.name + "@" + group.where.str()};
        for (const SrdfGroupMember &member : group.members)
            described.push_back(describe(member));
        return described;
    }

    SrdfFile readPanda()
    {
        return readSrdfString(PANDA_SRDF, "panda.srdf");
    }

    /** The Panda's kinematic tree: for each link but the root panda_link0, its parent joint and
        link. */
    std::map<std::string, std::pair<std::string, std::string>> pandaTree()
    {
        std::map<std::string, std::pair<std::string, std::string>> tree = {
            {"panda_hand", {"panda_hand_joint", "panda_link8"}},
            {"panda_leftfinger", {"panda_finger_joint1", "panda_hand"}},
            {"panda_rightfinger", {"panda_finger_joint2", "panda_hand"}}};
        for (int i = 1; i <= 8; ++i)
            tree["panda_link" + std::to_string(i)] = {"panda_joint" + std::to_string(i),
                                                      "panda_link" + std::to_string(i - 1)};
        return tree;
    }
    const std::map<std::string, std::pair<std::string, std::string>> PANDA_TREE = pandaTree();

    /** A fake chainJoints: walks up from tip to base; nothing when base is not above tip. */
    std::optional<std::vector<std::string>> pandaChain(const std::string &base, const std::string &tip)
    {
        std::vector<std::string> joints;
        for (std::string link = tip; link != base; link = PANDA_TREE.at(link).second)
        {
            if (PANDA_TREE.count(link) == 0)
                return std::nullopt;
            joints.insert(joints.begin(), PANDA_TREE.at(link).first);
        }
        return joints;
    }

    /** A fake parentJoint on PANDA_TREE. */
    std::optional<std::string> pandaParent(const std::string &link)
    {
        if (link == "panda_link0")
            return std::string();
        const auto found = PANDA_TREE.find(link);
        return found == PANDA_TREE.end() ? std::nullopt : std::optional<std::string>(found->second.first);
    }

    std::vector<std::string> pandaJoints(const SrdfFile &srdf, const std::string &group)
    {
        return groupJoints(srdf, group, pandaChain, pandaParent);
    }

    const std::vector<std::string> ARM_JOINTS = {"panda_joint1", "panda_joint2", "panda_joint3",
                                                 "panda_joint4", "panda_joint5", "panda_joint6",
                                                 "panda_joint7", "panda_joint8"};
    const std::vector<std::string> HAND_JOINTS = {"panda_hand_joint", "panda_finger_joint1",
                                                  "panda_finger_joint2"};

    /** A small valid SRDF; a test replaces line n (1-based) and expects the error at line n. */
    std::vector<std::string> smallLines()
    {
        return {
            R"(<robot name="r">)",                                                                     // 1
            R"(  <group name="arm">)",                                                                 // 2
            R"(    <chain base_link="base" tip_link="tool"/>)",                                        // 3
            R"(  </group>)",                                                                           // 4
            R"(  <group name="hand">)",                                                                // 5
            R"(    <link name="finger"/>)",                                                            // 6
            R"(  </group>)",                                                                           // 7
            R"(  <group name="both">)",                                                                // 8
            R"(    <group name="arm"/>)",                                                              // 9
            R"(  </group>)",                                                                           // 10
            R"(  <group_state name="home" group="arm">)",                                              // 11
            R"(    <joint name="j1" value="0.5"/>)",                                                   // 12
            R"(  </group_state>)",                                                                     // 13
            R"(  <end_effector name="gripper" parent_link="tool" group="hand" parent_group="arm"/>)",  // 14
            R"(  <disable_collisions link1="base" link2="tool" reason="Never"/>)",                     // 15
            R"(  <virtual_joint name="world_joint" type="planar" parent_frame="world" child_link="base"/>)",  // 16
            R"(</robot>)",  // 17
        };
    }

    /** smallLines() with line `line` (1-based) replaced by text. */
    std::vector<std::string> replaced(int line, const std::string &text)
    {
        std::vector<std::string> lines = smallLines();
        lines.at(line - 1) = text;
        return lines;
    }

    /** Expects reading lines to fail at small.srdf:line with a message containing phrase. */
    void expectError(const std::vector<std::string> &lines, int line, const std::string &phrase)
    {
        const std::string message = inputErrorOf([&] { readSrdfString(joined(lines), "small.srdf"); });
        EXPECT_TRUE(startsWith(message, "small.srdf:" + std::to_string(line) + ": ")) << message;
        EXPECT_TRUE(contains(message, phrase)) << message;
    }
}  // namespace

TEST(SrdfFile, ReadsPandaGroupsEndEffectorAndVirtualJoint)
{
    const SrdfFile srdf = readPanda();
    EXPECT_EQ(srdf.file, "panda.srdf");
    EXPECT_EQ(srdf.robotName, "panda");
    ASSERT_EQ(srdf.groups.size(), 3u);
    using Described = std::vector<std::string>;
    EXPECT_EQ(describe(srdf.groups[0]),
              (Described{"panda_arm@panda.srdf:5", "chain panda_link0 panda_link8@panda.srdf:6"}));
    EXPECT_EQ(describe(srdf.groups[1]),
              (Described{"hand@panda.srdf:8", "link panda_hand@panda.srdf:9",
                         "link panda_leftfinger@panda.srdf:10", "link panda_rightfinger@panda.srdf:11"}));
    EXPECT_EQ(describe(srdf.groups[2]),
              (Described{"panda_arm_hand@panda.srdf:13", "group panda_arm@panda.srdf:14",
                         "group hand@panda.srdf:15"}));

    ASSERT_EQ(srdf.endEffectors.size(), 1u);
    EXPECT_EQ(srdf.endEffectors[0].name, "hand");
    EXPECT_EQ(srdf.endEffectors[0].group, "hand");
    EXPECT_EQ(srdf.endEffectors[0].parentLink, "panda_link8");
    EXPECT_EQ(srdf.endEffectors[0].parentGroup, "panda_arm");
    EXPECT_EQ(srdf.endEffectors[0].where.str(), "panda.srdf:44");

    ASSERT_EQ(srdf.virtualJoints.size(), 1u);
    EXPECT_EQ(srdf.virtualJoints[0].name, "virtual_joint");
    EXPECT_EQ(srdf.virtualJoints[0].type, SrdfVirtualJoint::Type::Fixed);
    EXPECT_EQ(srdf.virtualJoints[0].parentFrame, "world");
    EXPECT_EQ(srdf.virtualJoints[0].childLink, "panda_link0");
    EXPECT_EQ(srdf.virtualJoints[0].where.str(), "panda.srdf:45");

    EXPECT_EQ(srdf.findGroup("hand"), &srdf.groups[1]);
    EXPECT_EQ(srdf.findGroup("panda_hand"), nullptr);
}

TEST(SrdfFile, ReadsPandaGroupStates)
{
    const SrdfFile srdf = readPanda();
    // name, group, line, joint name prefix, values of joints 1, 2... on the following lines
    const std::vector<std::tuple<std::string, std::string, int, std::string, std::vector<double>>> expected =
        {{"ready", "panda_arm", 17, "panda_joint", {0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785}},
         {"extended", "panda_arm", 26, "panda_joint", {0.0, 0.0, 0.0, -0.1, 0.0, 3.14159, 0.785}},
         {"open", "hand", 35, "panda_finger_joint", {0.035, 0.035}},
         {"close", "hand", 39, "panda_finger_joint", {0.0, 0.0}}};
    ASSERT_EQ(srdf.groupStates.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i)
    {
        const auto &[name, group, line, prefix, values] = expected[i];
        const SrdfGroupState &state = srdf.groupStates[i];
        EXPECT_EQ(state.name, name);
        EXPECT_EQ(state.group, group);
        EXPECT_EQ(state.where.str(), "panda.srdf:" + std::to_string(line));
        ASSERT_EQ(state.values.size(), values.size());
        for (std::size_t j = 0; j < values.size(); ++j)
        {
            EXPECT_EQ(state.values[j].joint, prefix + std::to_string(j + 1));
            EXPECT_DOUBLE_EQ(state.values[j].value, values[j]);
            EXPECT_EQ(state.values[j].where.line, line + 1 + static_cast<int>(j));
        }
        EXPECT_EQ(srdf.findGroupState(group, name), &state);
    }
    EXPECT_EQ(srdf.findGroupState("hand", "ready"), nullptr);
}

TEST(SrdfFile, ReadsPandaDisabledCollisions)
{
    const std::vector<std::string> lines = splitLines(PANDA_SRDF);
    const SrdfFile srdf = readPanda();
    ASSERT_EQ(srdf.disabledCollisions.size(), 24u);
    const int first = 47;
    for (std::size_t i = 0; i < srdf.disabledCollisions.size(); ++i)
    {
        // each pair is the element on its own line, field by field
        const SrdfDisabledPair &pair = srdf.disabledCollisions[i];
        EXPECT_EQ(pair.where.file, "panda.srdf");
        EXPECT_EQ(pair.where.line, first + static_cast<int>(i));
        EXPECT_EQ(lines.at(pair.where.line - 1), R"(    <disable_collisions link1=")" + pair.link1 +
                                                     R"(" link2=")" + pair.link2 + R"(" reason=")" +
                                                     pair.reason + R"("/>)");
    }
    const SrdfDisabledPair &last = srdf.disabledCollisions.back();
    EXPECT_EQ(last.link1, "panda_link4");
    EXPECT_EQ(last.link2, "panda_link5");
    EXPECT_EQ(last.reason, "Adjacent");
    EXPECT_EQ(lines.at(last.where.line), "</robot>");
}

TEST(SrdfFile, ReadsFromFileAndNamesThePathInErrors)
{
    const std::filesystem::path dir = ompl_core::test::scratchDirectory("test_SrdfFile");
    const std::string good = (dir / "panda.srdf").string();
    std::ofstream(good) << PANDA_SRDF;
    const SrdfFile srdf = readSrdfFile(good);
    EXPECT_EQ(srdf.file, good);
    EXPECT_EQ(srdf.groups.at(0).where.file, good);
    EXPECT_EQ(srdf.disabledCollisions.size(), 24u);

    const std::string bad = (dir / "bad.srdf").string();
    std::ofstream(bad) << joined(replaced(12, R"(    <joint name="j1" value="abc"/>)"));
    const std::string message = inputErrorOf([&] { readSrdfFile(bad); });
    EXPECT_TRUE(startsWith(message, bad + ":12: ")) << message;

    const std::string missing = (dir / "missing.srdf").string();
    const std::string notFound = inputErrorOf([&] { readSrdfFile(missing); });
    EXPECT_TRUE(startsWith(notFound, missing + ": ")) << notFound;
    EXPECT_TRUE(contains(notFound, "SRDF file not found")) << notFound;
}

TEST(SrdfFile, ExpandsChainLinkAndSubgroupMembers)
{
    const SrdfFile srdf = readPanda();
    EXPECT_EQ(pandaJoints(srdf, "panda_arm"), ARM_JOINTS);
    EXPECT_EQ(pandaJoints(srdf, "hand"), HAND_JOINTS);
    std::vector<std::string> all = ARM_JOINTS;
    all.insert(all.end(), HAND_JOINTS.begin(), HAND_JOINTS.end());
    EXPECT_EQ(pandaJoints(srdf, "panda_arm_hand"), all);
}

TEST(SrdfFile, ExpansionKeepsFirstOrderWithoutDuplicates)
{
    SrdfFile srdf =
        readSrdfString(joined({
                           R"(<robot name="panda">)",
                           R"(<group name="hand"><link name="panda_hand"/></group>)",
                           R"(<group name="wrist"><joint name="panda_joint7"/></group>)",
                           R"(<group name="mixed">)",
                           R"(  <joint name="panda_joint3"/>)",
                           R"(  <chain base_link="panda_link0" tip_link="panda_link4"/>)",
                           R"(  <group name="hand"/>)",
                           R"(  <link name="panda_link0"/>)",
                           R"(  <group name="top"/>)",
                           R"(</group>)",
                           R"(<group name="top"><group name="hand"/><group name="wrist"/></group>)",
                           R"(<virtual_joint name="base" type="planar" parent_frame="odom")"
                           R"( child_link="panda_link0"/>)",
                           R"(</robot>)",
                       }),
                       "mixed.srdf");
    // the root link stands for its virtual joint; the diamond through "top" adds hand once
    EXPECT_EQ(pandaJoints(srdf, "mixed"),
              (std::vector<std::string>{"panda_joint3", "panda_joint1", "panda_joint2", "panda_joint4",
                                        "panda_hand_joint", "base", "panda_joint7"}));
    // without a virtual joint the root link adds no joint
    srdf.virtualJoints.clear();
    EXPECT_EQ(pandaJoints(srdf, "mixed"),
              (std::vector<std::string>{"panda_joint3", "panda_joint1", "panda_joint2", "panda_joint4",
                                        "panda_hand_joint", "panda_joint7"}));
}

TEST(SrdfFile, ExpansionNamesTheSrdfLineOfWhatTheRobotLacks)
{
    std::vector<std::string> lines = smallLines();
    lines[2] = R"(    <chain base_link="panda_link8" tip_link="panda_link0"/>)";
    lines[5] = R"(    <link name="panda_thumb"/>)";
    const SrdfFile srdf = readSrdfString(joined(lines), "small.srdf");
    const std::string chain = inputErrorOf([&] { pandaJoints(srdf, "arm"); });
    EXPECT_TRUE(startsWith(chain, "small.srdf:3: ")) << chain;
    EXPECT_TRUE(contains(chain, "'panda_link8' and 'panda_link0' of <chain> in <group> 'arm' form no chain"))
        << chain;
    const std::string link = inputErrorOf([&] { pandaJoints(srdf, "hand"); });
    EXPECT_TRUE(startsWith(link, "small.srdf:6: ")) << link;
    EXPECT_TRUE(contains(link, "robot 'r' has no link 'panda_thumb'")) << link;
    const std::string group = inputErrorOf([&] { pandaJoints(srdf, "leg"); });
    EXPECT_EQ(group, "small.srdf: no group 'leg' (groups: arm, hand, both)");
}

TEST(SrdfFile, ExpansionRejectsCyclesAndUnknownSubgroupsBuiltInCode)
{
    SrdfFile srdf;
    srdf.file = "code.srdf";
    const auto subgroup = [](const std::string &name, int line) {
        return SrdfGroupMember{SrdfGroupMember::Kind::Subgroup, name, "", {"code.srdf", line}};
    };
    srdf.groups = {{"a", {subgroup("b", 2)}, {"code.srdf", 1}}, {"b", {subgroup("a", 4)}, {"code.srdf", 3}}};
    const std::string cycle = inputErrorOf([&] { pandaJoints(srdf, "a"); });
    EXPECT_EQ(cycle, "code.srdf:4: <group> 'a' includes itself through its subgroups: 'a' -> 'b' -> 'a'");
    srdf.groups[1].members = {subgroup("c", 4)};
    const std::string unknown = inputErrorOf([&] { pandaJoints(srdf, "a"); });
    EXPECT_TRUE(startsWith(unknown, "code.srdf:4: unknown subgroup 'c' in <group> 'b'")) << unknown;
}

TEST(SrdfFile, AcceptsSrdfElementsItIgnores)
{
    std::vector<std::string> lines = smallLines();
    lines[0] = R"(<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">)";
    lines.insert(lines.end() - 1,
                 {
                     R"(  <!-- elements MoveIt reads that this project does not use -->)",
                     R"(  <passive_joint name="j2"/>)",
                     R"(  <joint_property joint_name="j1" property_name="angular_distance_weight")"
                     R"( value="0.5"/>)",
                     R"(  <disable_default_collisions link="finger"/>)",
                     R"(  <enable_collisions link1="finger" link2="base" reason="Never"/>)",
                     R"(  <enable_collisions link1="finger" link2="tool"/>)",
                     R"(  <link_sphere_approximation link="tool">)",
                     R"(    <sphere center="0 0 0.1" radius="0.05"/>)",
                     R"(  </link_sphere_approximation>)",
                 });
    const SrdfFile srdf = readSrdfString(joined(lines), "small.srdf");
    EXPECT_EQ(srdf.robotName, "r");
    EXPECT_EQ(srdf.groups.size(), 3u);
    EXPECT_EQ(srdf.groupStates.size(), 1u);
    EXPECT_EQ(srdf.endEffectors.size(), 1u);
    EXPECT_EQ(srdf.disabledCollisions.size(), 1u);
    EXPECT_EQ(srdf.virtualJoints.size(), 1u);
    EXPECT_EQ(srdf.virtualJoints[0].type, SrdfVirtualJoint::Type::Planar);
}

TEST(SrdfFile, RejectsWhatIsNoSrdfAtItsLine)
{
    expectError(replaced(15, R"(  <disable_collision link1="base" link2="tool"/>)"), 15,
                "unknown element <disable_collision> in <robot>");
    expectError(replaced(6, R"(    <links name="finger"/>)"), 6, "unknown element <links> in <group>");
    expectError(replaced(12, R"(    <joint_value name="j1" value="0.5"/>)"), 12,
                "unknown element <joint_value> in <group_state>");
    expectError(replaced(14, R"(  <end_effector name="g" parent_link="tool" group="hand" parent="arm"/>)"),
                14, "unknown attribute 'parent' on <end_effector>");
    expectError(replaced(1, R"(<robot name="r" version="1">)"), 1, "unknown attribute 'version' on <robot>");
    expectError(replaced(15, R"(  <passive_joint nmae="j2"/>)"), 15,
                "unknown attribute 'nmae' on <passive_joint>");
    expectError(replaced(15, R"(  <enable_collisions link1="base"/>)"), 15,
                "missing required attribute 'link2'");
    expectError(
        replaced(15, R"(  <link_sphere_approximation link="tool"><box/></link_sphere_approximation>)"), 15,
        "unknown element <box> in <link_sphere_approximation>");
    expectError(replaced(12, R"(    <joint name="j1" value="0.5">)"), 12,
                "XML syntax error: end tag missing or mismatched for <joint>");
    expectError({R"(<urdf name="r"/>)"}, 1, "the root element must be <robot>");
}

TEST(SrdfFile, RejectsMissingAttributesAtTheirLine)
{
    expectError(replaced(1, R"(<robot>)"), 1, "missing required attribute 'name' on <robot>");
    expectError(replaced(5, R"(  <group>)"), 5, "missing required attribute 'name' on <group>");
    expectError(replaced(3, R"(    <chain base_link="base"/>)"), 3,
                "missing required attribute 'tip_link' on <chain>");
    expectError(replaced(11, R"(  <group_state name="home">)"), 11,
                "missing required attribute 'group' on <group_state>");
    expectError(replaced(12, R"(    <joint name="j1"/>)"), 12,
                "missing required attribute 'value' on <joint>");
    expectError(replaced(14, R"(  <end_effector name="g" group="hand"/>)"), 14,
                "missing required attribute 'parent_link' on <end_effector>");
    expectError(replaced(15, R"(  <disable_collisions link1="base"/>)"), 15,
                "missing required attribute 'link2' on <disable_collisions>");
    expectError(replaced(16, R"(  <virtual_joint name="v" parent_frame="world" child_link="base"/>)"), 16,
                "missing required attribute 'type' on <virtual_joint>");
    expectError(replaced(6, R"(    <link name=""/>)"), 6, "attribute 'name' of <link> must not be empty");
}

TEST(SrdfFile, RejectsJointValuesThatAreNotOneNumber)
{
    expectError(replaced(12, R"(    <joint name="j1" value="abc"/>)"), 12, "malformed number 'abc'");
    expectError(replaced(12, R"(    <joint name="j1" value="nan"/>)"), 12, "malformed number 'nan'");
    expectError(replaced(12, R"(    <joint name="j1" value="0 1 2"/>)"), 12,
                "joint 'j1' has 3 values in '0 1 2': only joints of one value are supported, not multi-dof");
    expectError(replaced(12, R"(    <joint name="j1" value=" "/>)"), 12, "needs 1 value, got 0");
    expectError(
        replaced(16, R"(  <virtual_joint name="v" type="Planar" parent_frame="w" child_link="base"/>)"), 16,
        "unknown type 'Planar' of <virtual_joint> 'v' (known: fixed, floating, planar)");
}

TEST(SrdfFile, RejectsDuplicateNames)
{
    expectError(replaced(8, R"(  <group name="arm">)"), 8, "second <group> named 'arm' (first at line 2)");
    expectError(replaced(13, R"(  </group_state><group_state name="home" group="arm"></group_state>)"), 13,
                "second <group_state> named 'home' for group 'arm' (first at line 11)");
    expectError(replaced(13, R"(    <joint name="j1" value="1"/></group_state>)"), 13,
                "joint 'j1' set twice in <group_state> 'home' (first at line 12)");
    expectError(replaced(15, R"(  <end_effector name="gripper" parent_link="tool" group="hand"/>)"), 15,
                "second <end_effector> named 'gripper' (first at line 14)");
    expectError(
        replaced(15, R"(  <virtual_joint name="world_joint" type="fixed" parent_frame="w" child_link="b"/>)"),
        16, "second <virtual_joint> named 'world_joint' (first at line 15)");
    // one state name in two groups is fine
    const SrdfFile srdf = readSrdfString(
        joined(replaced(13, R"(  </group_state><group_state name="home" group="hand"></group_state>)")),
        "small.srdf");
    EXPECT_NE(srdf.findGroupState("hand", "home"), nullptr);
}

TEST(SrdfFile, RejectsReferencesToUnknownGroups)
{
    expectError(replaced(11, R"(  <group_state name="home" group="leg">)"), 11,
                "<group_state> names unknown group 'leg' (groups: arm, hand, both)");
    expectError(replaced(14, R"(  <end_effector name="g" parent_link="tool" group="leg"/>)"), 14,
                "<end_effector> names unknown group 'leg'");
    expectError(
        replaced(14, R"(  <end_effector name="g" parent_link="tool" group="hand" parent_group="leg"/>)"), 14,
        "<end_effector> names unknown group 'leg'");
    expectError(replaced(9, R"(    <group name="leg"/>)"), 9,
                "unknown subgroup 'leg' in <group> 'both' (groups: arm, hand, both)");
}

TEST(SrdfFile, RejectsSubgroupCyclesAtTheClosingSubgroup)
{
    expectError(replaced(3, R"(    <group name="both"/>)"), 9,
                "<group> 'arm' includes itself through its subgroups: 'arm' -> 'both' -> 'arm'");
    expectError(replaced(6, R"(    <group name="hand"/>)"), 6,
                "<group> 'hand' includes itself through its subgroups: 'hand' -> 'hand'");
    // a group may name a group further down the file
    const SrdfFile srdf = readSrdfString(joined(replaced(6, R"(    <group name="both"/>)")), "small.srdf");
    EXPECT_EQ(srdf.groups[1].members[0].kind, SrdfGroupMember::Kind::Subgroup);
}
