/* RobotModel: urdfdom parses the URDF; a tinyxml2 pass beforehand finds element lines (which urdfdom
   drops) for messages and the file order of joints; the tree is then flattened parents first. */
#include "ompl_mm/robot/RobotModel.h"

#include "ompl_mm/robot/AxisTurn.h"
#include "ompl_mm/robot/MeshFile.h"

#include <tinyxml2.h>
#include <urdf_parser/urdf_parser.h>

#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <cctype>
#include <cmath>
#include <map>
#include <sstream>
#include <tuple>
#include <utility>

#include "ompl_core/io/InputError.h"
#include "ompl_core/io/InputFile.h"
#include "ompl_core/io/XmlReading.h"

namespace ompl_mm
{
    namespace
    {
        /** A <link> element as written: urdfdom silently drops a collision it cannot read. */
        struct LinkElement
        {
            int line{0};
            std::size_t collisions{0};  ///< <collision> children
            std::size_t visuals{0};     ///< <visual> children
        };

        /** The URDF's name for messages, its link elements and the line of each joint element. */
        struct UrdfSource
        {
            std::string name;
            std::map<std::string, LinkElement> links;
            std::map<std::string, int> jointLines;

            LinkElement link(const std::string &link) const
            {
                auto it = links.find(link);
                return it == links.end() ? LinkElement{} : it->second;
            }

            int jointLine(const std::string &joint) const
            {
                auto it = jointLines.find(joint);
                return it == jointLines.end() ? 0 : it->second;
            }

            ompl_core::InputError linkError(const std::string &link, const std::string &message) const
            {
                return ompl_core::InputError(ompl_core::SourceLocation{name, this->link(link).line},
                                             "link '" + link + "': " + message);
            }

            ompl_core::InputError jointError(const std::string &joint, const std::string &message) const
            {
                return ompl_core::InputError(ompl_core::SourceLocation{name, jointLine(joint)},
                                             "joint '" + joint + "': " + message);
            }
        };

        std::string format(double value)
        {
            std::ostringstream out;
            out << value;
            return out.str();
        }

        /** The link attribute of joint's child element tag ("parent" or "child"), or "". */
        std::string jointLink(const tinyxml2::XMLElement &joint, const char *tag)
        {
            const tinyxml2::XMLElement *element = joint.FirstChildElement(tag);
            const char *link = element != nullptr ? element->Attribute("link") : nullptr;
            return link != nullptr ? link : "";
        }

        /** Checks that the joints make a tree of the links: no link is the child of two joints and no
            joint closes a loop. urdfdom links the tree before it checks it and leaves such a graph a
            cycle of shared pointers, never freed; missing links and names it reports itself. */
        void checkLinkTree(const tinyxml2::XMLElement &robot, const UrdfSource &source)
        {
            std::map<std::string, std::pair<std::string, std::string>> parentOf;  // link: joint, link
            for (auto *e = robot.FirstChildElement("joint"); e != nullptr; e = e->NextSiblingElement("joint"))
            {
                const char *name = e->Attribute("name");
                const std::string parent = jointLink(*e, "parent"), child = jointLink(*e, "child");
                if (name == nullptr || parent.empty() || child.empty())
                    continue;
                if (const auto earlier = parentOf.find(child); earlier != parentOf.end())
                    throw source.jointError(name, "link '" + child + "' is already the child of joint '" +
                                                      earlier->second.first +
                                                      "': the links must form a tree");
                // the joints so far form a tree, so this walk up from the parent ends at its root
                for (auto link = parent;; link = parentOf.at(link).second)
                {
                    if (link == child)
                        throw source.jointError(name, "closes a loop: its child link '" + child +
                                                          "' is its parent link '" + parent +
                                                          "' or above it");
                    if (parentOf.count(link) == 0)
                        break;
                }
                parentOf.emplace(child, std::make_pair(name, parent));
            }
        }

        /** Whether urdf has an entity reference at `at` (&name; &#digits; &#xhex;). */
        bool entityReferenceAt(const std::string &urdf, std::size_t at)
        {
            std::size_t k = at + 1;
            const auto digitsOf = [&](bool hex)
            {
                const std::size_t first = k;
                while (k < urdf.size() && (hex ? std::isxdigit(static_cast<unsigned char>(urdf[k])) != 0
                                               : std::isdigit(static_cast<unsigned char>(urdf[k])) != 0))
                    ++k;
                return k > first;
            };
            if (k < urdf.size() && urdf[k] == '#')
            {
                ++k;
                const bool hex = k < urdf.size() && urdf[k] == 'x';
                if (hex)
                    ++k;
                if (!digitsOf(hex))
                    return false;
            }
            else
            {
                const auto nameStart = [](char c)
                { return std::isalpha(static_cast<unsigned char>(c)) || c == '_' || c == ':'; };
                if (k >= urdf.size() || !nameStart(urdf[k]))
                    return false;
                while (k < urdf.size() &&
                       (nameStart(urdf[k]) || std::isdigit(static_cast<unsigned char>(urdf[k])) ||
                        urdf[k] == '-' || urdf[k] == '.'))
                    ++k;
            }
            return k < urdf.size() && urdf[k] == ';';
        }

        /** Checks that every '&' outside comments, CDATA sections and processing instructions starts
            an entity reference, as XML requires. tinyxml2 keeps a bare '&' as it is, and urdfdom
            leaks the model it was building when it meets one. */
        void checkAmpersands(const std::string &urdf, const std::string &sourceName)
        {
            static const std::vector<std::pair<std::string, std::string>> skipped = {
                {"<!--", "-->"}, {"<![CDATA[", "]]>"}, {"<?", "?>"}};
            std::size_t at = 0;
            while (at < urdf.size())
            {
                const auto skip =
                    std::find_if(skipped.begin(), skipped.end(),
                                 [&](const auto &section)
                                 { return urdf.compare(at, section.first.size(), section.first) == 0; });
                if (skip != skipped.end())
                {
                    const std::size_t end = urdf.find(skip->second, at + skip->first.size());
                    at = end == std::string::npos ? urdf.size() : end + skip->second.size();
                    continue;
                }
                if (urdf[at] == '&' && !entityReferenceAt(urdf, at))
                    throw ompl_core::InputError(
                        ompl_core::SourceLocation{
                            sourceName,
                            static_cast<int>(1 + std::count(urdf.begin(), urdf.begin() + at, '\n'))},
                        "invalid URDF: malformed XML (a '&' that starts no entity reference; write &amp;)");
                ++at;
            }
        }

        /** Checks the XML and indexes elements; also catches moving joints without <limit>, which
            urdfdom rejects without saying which joint. */
        UrdfSource indexElements(const std::string &urdf, const std::string &sourceName)
        {
            UrdfSource source{sourceName, {}, {}};
            checkAmpersands(urdf, sourceName);
            tinyxml2::XMLDocument doc;
            if (doc.Parse(urdf.c_str(), urdf.size()) != tinyxml2::XML_SUCCESS)
                throw ompl_core::InputError(
                    ompl_core::SourceLocation{sourceName, doc.ErrorLineNum()},
                    std::string("invalid URDF: malformed XML (") + doc.ErrorName() + ")");
            const tinyxml2::XMLElement *robot = doc.FirstChildElement("robot");
            if (robot == nullptr)
                throw ompl_core::InputError(ompl_core::SourceLocation{sourceName, 0},
                                            "invalid URDF: no <robot> element");
            const auto count = [](const tinyxml2::XMLElement *link, const char *tag)
            {
                std::size_t n = 0;
                for (auto *c = link->FirstChildElement(tag); c != nullptr; c = c->NextSiblingElement(tag))
                    ++n;
                return n;
            };
            for (auto *e = robot->FirstChildElement("link"); e != nullptr; e = e->NextSiblingElement("link"))
                if (const char *name = e->Attribute("name"))
                    source.links.emplace(
                        name, LinkElement{e->GetLineNum(), count(e, "collision"), count(e, "visual")});
            for (auto *e = robot->FirstChildElement("joint"); e != nullptr;
                 e = e->NextSiblingElement("joint"))
            {
                const char *name = e->Attribute("name");
                if (name == nullptr)
                    continue;  // urdfdom reports it
                source.jointLines.emplace(name, e->GetLineNum());
                const std::string type = e->Attribute("type") != nullptr ? e->Attribute("type") : "";
                if ((type == "revolute" || type == "prismatic") && e->FirstChildElement("limit") == nullptr)
                    throw source.jointError(name, type + " joint has no <limit>");
            }
            checkLinkTree(*robot, source);
            return source;
        }

        Eigen::Isometry3d toIsometry(const urdf::Pose &pose)
        {
            Eigen::Isometry3d frame = Eigen::Isometry3d::Identity();
            frame.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
            const urdf::Rotation &r = pose.rotation;
            frame.linear() = Eigen::Quaterniond(r.w, r.x, r.y, r.z).normalized().toRotationMatrix();
            return frame;
        }

        /** A <mesh>: its file found and read (once per file and scale, through meshes). */
        Shape meshShape(const urdf::Mesh &geometry, const std::string &link, const UrdfSource &source,
                        MeshCache &meshes)
        {
            const Eigen::Vector3d scale(geometry.scale.x, geometry.scale.y, geometry.scale.z);
            if (!(scale.minCoeff() > 0.0))
                throw source.linkError(link, "mesh '" + geometry.filename +
                                                 "': scale must be positive, got " + format(scale.x()) + " " +
                                                 format(scale.y()) + " " + format(scale.z()));
            std::string tried;
            const std::string path = resolveMeshFile(geometry.filename, source.name, tried);
            if (path.empty())
                throw source.linkError(
                    link, "mesh '" + geometry.filename + "' not found (looked for " + tried + ")");
            Shape shape;
            shape.kind = Shape::Kind::Mesh;
            try
            {
                shape.mesh = readMeshFile(path, scale, meshes);
            }
            catch (const std::runtime_error &e)
            {
                throw source.linkError(link, "mesh '" + path + "' cannot be read: " + e.what());
            }
            return shape;
        }

        Shape toShape(const urdf::Geometry &geometry, const std::string &link, const UrdfSource &source,
                      MeshCache &meshes)
        {
            Shape shape;
            switch (geometry.type)
            {
                case urdf::Geometry::BOX:
                {
                    const urdf::Vector3 &d = static_cast<const urdf::Box &>(geometry).dim;
                    shape.kind = Shape::Kind::Box;
                    shape.boxSize = Eigen::Vector3d(d.x, d.y, d.z);
                    if (!(shape.boxSize.minCoeff() > 0.0))
                        throw source.linkError(link, "box size must be positive, got " + format(d.x) + " " +
                                                         format(d.y) + " " + format(d.z));
                    return shape;
                }
                case urdf::Geometry::CYLINDER:
                {
                    const auto &cylinder = static_cast<const urdf::Cylinder &>(geometry);
                    shape.kind = Shape::Kind::Cylinder;
                    shape.radius = cylinder.radius;
                    shape.length = cylinder.length;
                    if (!(shape.radius > 0.0 && shape.length > 0.0))
                        throw source.linkError(link, "cylinder radius and length must be positive, got " +
                                                         format(shape.radius) + " and " +
                                                         format(shape.length));
                    return shape;
                }
                case urdf::Geometry::SPHERE:
                    shape.kind = Shape::Kind::Sphere;
                    shape.radius = static_cast<const urdf::Sphere &>(geometry).radius;
                    if (!(shape.radius > 0.0))
                        throw source.linkError(link,
                                               "sphere radius must be positive, got " + format(shape.radius));
                    return shape;
                case urdf::Geometry::MESH:
                    return meshShape(static_cast<const urdf::Mesh &>(geometry), link, source, meshes);
                default:
                    throw source.linkError(link, "unknown collision geometry");
            }
        }

        /** The link's collision shapes. A link must not look solid without being so: a <collision>
            that urdfdom dropped, or a <visual> without any <collision>, is an error. */
        std::vector<LinkShape> toLinkShapes(const urdf::Link &link, const UrdfSource &source,
                                            MeshCache &meshes)
        {
            const LinkElement written = source.link(link.name);
            if (link.collision_array.size() < written.collisions)
                throw source.linkError(link.name,
                                       "a <collision> element could not be read (is its geometry "
                                       "complete, with numbers where numbers belong?)");
            if (link.collision_array.empty() && written.visuals > 0)
                throw source.linkError(link.name,
                                       "has <visual> but no <collision> geometry, so it would pass "
                                       "through obstacles and objects; add a <collision> element");
            std::vector<LinkShape> shapes;
            for (const urdf::CollisionSharedPtr &collision : link.collision_array)
                shapes.push_back(LinkShape{toShape(*collision->geometry, link.name, source, meshes),
                                           toIsometry(collision->origin)});
            return shapes;
        }

        Joint::Type toJointType(const urdf::Joint &joint, const UrdfSource &source)
        {
            switch (joint.type)
            {
                case urdf::Joint::FIXED:
                    return Joint::Type::Fixed;
                case urdf::Joint::PRISMATIC:
                    return Joint::Type::Prismatic;
                case urdf::Joint::REVOLUTE:
                    return Joint::Type::Revolute;
                case urdf::Joint::CONTINUOUS:
                    return Joint::Type::Continuous;
                default:
                {
                    // urdfdom itself rejects unknown type names
                    const std::string type = joint.type == urdf::Joint::FLOATING ? "floating" : "planar";
                    throw source.jointError(joint.name,
                                            type +
                                                " joints are not supported; use fixed, prismatic, "
                                                "revolute or continuous");
                }
            }
        }

        Joint toJoint(const urdf::Joint &urdfJoint, const UrdfSource &source)
        {
            Joint joint;
            joint.name = urdfJoint.name;
            joint.type = toJointType(urdfJoint, source);
            joint.origin = toIsometry(urdfJoint.parent_to_joint_origin_transform);
            if (joint.type == Joint::Type::Fixed)
                return joint;

            const Eigen::Vector3d axis(urdfJoint.axis.x, urdfJoint.axis.y, urdfJoint.axis.z);
            if (!(axis.norm() > 0.0) || !axis.allFinite())
                throw source.jointError(joint.name, "axis must be a non-zero vector");
            joint.axis = axis.normalized();

            if (urdfJoint.limits && std::isfinite(urdfJoint.limits->velocity) &&
                urdfJoint.limits->velocity > 0.0)
                joint.velocity = urdfJoint.limits->velocity;
            if (joint.type == Joint::Type::Continuous)
            {
                joint.lower = -boost::math::constants::pi<double>();
                joint.upper = boost::math::constants::pi<double>();
                return joint;
            }
            // urdfdom guarantees limits on prismatic and revolute joints
            joint.lower = urdfJoint.limits->lower;
            joint.upper = urdfJoint.limits->upper;
            if (!(joint.lower < joint.upper))
                throw source.jointError(joint.name, "lower limit " + format(joint.lower) +
                                                        " must be below upper limit " + format(joint.upper));
            return joint;
        }

        /** Child joints in file order (urdfdom orders them by name), so the variables of a branch
            follow the order the author wrote. */
        std::vector<urdf::JointSharedPtr> childJointsInFileOrder(const urdf::Link &link,
                                                                 const UrdfSource &source)
        {
            std::vector<urdf::JointSharedPtr> joints = link.child_joints;
            std::stable_sort(joints.begin(), joints.end(),
                             [&source](const urdf::JointSharedPtr &a, const urdf::JointSharedPtr &b)
                             { return source.jointLine(a->name) < source.jointLine(b->name); });
            return joints;
        }

        /** Frame of a joint's child in its parent's frame when the joint takes value. */
        Eigen::Isometry3d jointMotion(const Joint &joint, double value)
        {
            Eigen::Isometry3d transform = joint.origin;
            switch (joint.type)
            {
                case Joint::Type::Fixed:
                    break;
                case Joint::Type::Prismatic:
                    transform.translate(joint.axis * value);
                    break;
                case Joint::Type::Revolute:
                case Joint::Type::Continuous:
                    turnAbout(transform.linear(), joint.axis, alignedAxisOf(joint.axis), value);
                    break;
            }
            return transform;
        }

        /** Frame of a joint's child in its parent's frame for joint values q. */
        Eigen::Isometry3d jointTransform(const Joint &joint, const double *q)
        {
            return joint.type == Joint::Type::Fixed ? joint.origin : jointMotion(joint, joint.value(q));
        }

        /** A URDF <mimic> as written: the follower's index and its leader's name. */
        struct MimicElement
        {
            int joint;
            std::string leader;
            double multiplier;
            double offset;
        };

        /** Makes each follower follow the first leader of its chain of mimics, composing the
            factors, so a joint's value never needs more than one step. */
        void resolveMimics(std::vector<Joint> &joints, const std::vector<MimicElement> &mimics,
                           const UrdfSource &source)
        {
            const auto indexOf = [&joints](const std::string &name)
            {
                for (std::size_t j = 0; j < joints.size(); ++j)
                    if (joints[j].name == name)
                        return static_cast<int>(j);
                return -1;
            };
            const auto written = [&mimics](int joint) -> const MimicElement *
            {
                for (const MimicElement &mimic : mimics)
                    if (mimic.joint == joint)
                        return &mimic;
                return nullptr;
            };
            for (const MimicElement &mimic : mimics)
            {
                Joint &follower = joints[mimic.joint];
                double multiplier = mimic.multiplier;
                double offset = mimic.offset;
                std::string leaderName = mimic.leader;
                for (std::size_t step = 0;; ++step)
                {
                    const int leader = indexOf(leaderName);
                    if (leader < 0)
                        throw source.jointError(follower.name, "<mimic> names joint '" + leaderName +
                                                                   "', which the robot does not have");
                    if (joints[leader].type == Joint::Type::Fixed)
                        throw source.jointError(follower.name,
                                                "<mimic> follows joint '" + leaderName + "', which is fixed");
                    const MimicElement *next = written(leader);
                    if (next == nullptr)
                    {
                        follower.mimics = leader;
                        break;
                    }
                    if (step == mimics.size())
                        throw source.jointError(follower.name,
                                                "its <mimic> joints follow each other in a cycle");
                    // value = m * (m' * q + o') + o
                    offset += multiplier * next->offset;
                    multiplier *= next->multiplier;
                    leaderName = next->leader;
                }
                follower.multiplier = multiplier;
                follower.offset = offset;
            }
        }

        void checkLinkIndex(int link, std::size_t count)
        {
            if (link < 0 || static_cast<std::size_t>(link) >= count)
                throw ompl::Exception("RobotModel: link index " + std::to_string(link) +
                                      " out of range [0, " + std::to_string(count) + ")");
        }
    }  // namespace

    RobotModel RobotModel::fromUrdfFile(const std::string &path)
    {
        return fromUrdfString(ompl_core::readInputFile(path, "URDF file"), path);
    }

    RobotModel RobotModel::fromUrdfString(const std::string &urdf, const std::string &sourceName)
    {
        const UrdfSource source = indexElements(urdf, sourceName);
        MeshCache meshes;
        urdf::ModelInterfaceSharedPtr model;
        try
        {
            model = urdf::parseURDF(urdf);
        }
        catch (const std::exception &e)
        {
            throw ompl_core::InputError(ompl_core::SourceLocation{sourceName, 0},
                                        std::string("invalid URDF: ") + e.what());
        }
        if (!model || !model->getRoot())
            throw ompl_core::InputError(ompl_core::SourceLocation{sourceName, 0}, "invalid URDF");

        RobotModel robot;
        robot.name_ = model->getName();
        std::vector<MimicElement> mimics;
        // depth first from the root, so each branch's variables are contiguous; entries are a link,
        // its parent's index and the joint from the parent (null for the root)
        std::vector<std::tuple<urdf::LinkConstSharedPtr, int, urdf::JointConstSharedPtr>> stack{
            {model->getRoot(), -1, nullptr}};
        while (!stack.empty())
        {
            auto [urdfLink, parent, urdfJoint] = stack.back();
            stack.pop_back();
            Link link{urdfLink->name, parent, -1, toLinkShapes(*urdfLink, source, meshes)};
            if (urdfJoint)
            {
                Joint joint = toJoint(*urdfJoint, source);
                if (urdfJoint->mimic && joint.type != Joint::Type::Fixed)
                    mimics.push_back({static_cast<int>(robot.joints_.size()), urdfJoint->mimic->joint_name,
                                      urdfJoint->mimic->multiplier, urdfJoint->mimic->offset});
                link.joint = static_cast<int>(robot.joints_.size());
                robot.joints_.push_back(std::move(joint));
            }
            const int index = static_cast<int>(robot.links_.size());
            robot.links_.push_back(std::move(link));
            // pushed in reverse so the first child in the file is visited first
            const std::vector<urdf::JointSharedPtr> children = childJointsInFileOrder(*urdfLink, source);
            for (auto it = children.rbegin(); it != children.rend(); ++it)
                stack.emplace_back(model->getLink((*it)->child_link_name), index, *it);
        }
        resolveMimics(robot.joints_, mimics, source);
        robot.numberVariables();
        return robot;
    }

    void RobotModel::numberVariables()
    {
        dof_ = 0;
        variableJoints_.clear();
        for (const Link &link : links_)
            if (link.joint >= 0)
            {
                Joint &joint = joints_[link.joint];
                joint.variable = -1;
                if (joint.type != Joint::Type::Fixed && joint.mimics < 0)
                {
                    joint.variable = static_cast<int>(dof_++);
                    variableJoints_.push_back(link.joint);
                }
            }
        for (Joint &joint : joints_)
            if (joint.mimics >= 0)
                joint.variable = joints_[joint.mimics].variable;
    }

    RobotModel RobotModel::withJointsFixed(const std::vector<std::pair<std::string, double>> &values) const
    {
        RobotModel robot = *this;
        for (const auto &[name, value] : values)
        {
            auto it = std::find_if(robot.joints_.begin(), robot.joints_.end(),
                                   [&name = name](const Joint &joint) { return joint.name == name; });
            if (it == robot.joints_.end() || it->type == Joint::Type::Fixed)
                throw ompl_core::InputError("robot '" + name_ + "' has no moving joint '" + name +
                                            "' (its moving joints: " + robot.variableNames() + ")");
            if (it->mimics >= 0)
                throw ompl_core::InputError("joint '" + name + "' follows joint '" +
                                            robot.joints_[it->mimics].name + "' (<mimic>); fix that one");
            if (!(value >= it->lower && value <= it->upper))
                throw ompl_core::InputError("joint '" + name + "': value " + format(value) +
                                            " lies outside its limits [" + format(it->lower) + ", " +
                                            format(it->upper) + "]");
            const int leader = static_cast<int>(it - robot.joints_.begin());
            for (Joint &joint : robot.joints_)
                if (&joint == &*it || joint.mimics == leader)
                {
                    joint.origin = jointMotion(joint, joint.multiplier * value + joint.offset);
                    joint.type = Joint::Type::Fixed;
                    joint.mimics = -1;
                    joint.multiplier = 1.0;
                    joint.offset = 0.0;
                }
        }
        robot.numberVariables();
        return robot;
    }

    std::string RobotModel::variableNames() const
    {
        std::string names;
        for (unsigned int i = 0; i < dof_; ++i)
            names += (i == 0 ? "" : ", ") + variableJoint(i).name;
        return names;
    }

    int RobotModel::findLink(const std::string &name) const
    {
        for (std::size_t i = 0; i < links_.size(); ++i)
            if (links_[i].name == name)
                return static_cast<int>(i);
        return -1;
    }

    int RobotModel::linkIndex(const std::string &name) const
    {
        const int index = findLink(name);
        if (index < 0)
            throw ompl_core::InputError("robot '" + name_ + "' has no link '" + name + "'");
        return index;
    }

    bool RobotModel::isInSubtree(int descendant, int ancestor) const
    {
        checkLinkIndex(descendant, links_.size());
        checkLinkIndex(ancestor, links_.size());
        for (int i = descendant; i >= 0; i = links_[i].parent)
            if (i == ancestor)
                return true;
        return false;
    }

    void RobotModel::forwardKinematics(const double *q, const Eigen::Isometry3d &base,
                                       std::vector<Eigen::Isometry3d> &frames) const
    {
        frames.resize(links_.size());
        // the root is link 0 and every parent comes before its children
        frames[0] = base;
        for (std::size_t i = 1; i < links_.size(); ++i)
            frames[i] = frames[links_[i].parent] * jointTransform(joints_[links_[i].joint], q);
    }

    Eigen::Isometry3d RobotModel::linkFrame(const double *q, const Eigen::Isometry3d &base, int link) const
    {
        checkLinkIndex(link, links_.size());
        // multiplying on the left while walking up needs no stack of the path
        Eigen::Isometry3d frame = Eigen::Isometry3d::Identity();
        for (int i = link; links_[i].parent >= 0; i = links_[i].parent)
            frame = jointTransform(joints_[links_[i].joint], q) * frame;
        return base * frame;
    }

    bool RobotModel::isBaseJoint(unsigned int i) const
    {
        const int joint = variableJoints_[i];
        if (joints_[joint].type != Joint::Type::Prismatic)
            return false;
        // up from the joint's child link: every moving joint above must slide too
        for (std::size_t l = 0; l < links_.size(); ++l)
            if (links_[l].joint == joint)
                for (int up = links_[l].parent; up >= 0 && links_[up].parent >= 0; up = links_[up].parent)
                {
                    const Joint &above = joints_[links_[up].joint];
                    if (above.variable >= 0 && above.type != Joint::Type::Prismatic)
                        return false;
                }
        return true;
    }

    bool RobotModel::allJointsPrismatic() const
    {
        for (unsigned int i = 0; i < dof(); ++i)
            if (variableJoint(i).type != Joint::Type::Prismatic)
                return false;
        return dof() > 0;
    }
}  // namespace ompl_mm
