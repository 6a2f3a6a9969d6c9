#include "ompl_mm/scene/SceneLoader.h"

#include <tinyxml2.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <system_error>

#include "ompl_core/io/InputError.h"
#include "ompl_core/io/InputFile.h"
#include "ompl_core/io/TextFormat.h"
#include "ompl_core/io/XmlReading.h"

namespace ompl_mm
{
    namespace
    {
        namespace fs = std::filesystem;

        Shape readShape(const ompl_core::XmlElement &element)
        {
            Shape shape;
            if (element.name() == "box")
            {
                ompl_core::checkLeaf(element, {"size"});
                shape.kind = Shape::Kind::Box;
                shape.boxSize = element.lengths3("size");
            }
            else if (element.name() == "cylinder")
            {
                ompl_core::checkLeaf(element, {"radius", "length"});
                shape.kind = Shape::Kind::Cylinder;
                shape.radius = element.length("radius");
                shape.length = element.length("length");
            }
            else
            {
                ompl_core::checkLeaf(element, {"radius"});
                shape.kind = Shape::Kind::Sphere;
                shape.radius = element.length("radius");
            }
            return shape;
        }

        /** The one shape among the shape elements of a body. */
        Shape readOnlyShape(const ompl_core::XmlElement &body,
                            const std::vector<ompl_core::XmlElement> &shapes)
        {
            if (shapes.size() != 1)
                (shapes.empty() ? body : shapes[1])
                    .fail(body.tag() + " '" + body.text("name") +
                          "' needs exactly one shape (<box>, <cylinder> or <sphere>), found " +
                          std::to_string(shapes.size()));
            return readShape(shapes.front());
        }

        /** Builds a Scene from the <scene> element. Children are read grouped by kind (bodies,
            then start, goal, primitives), so references may point to elements further down. */
        class SceneParser
        {
        public:
            SceneParser(const std::string &file, const std::string &baseDir) : baseDir_(baseDir)
            {
                scene_.file = file;
            }

            Scene parse(const ompl_core::XmlElement &root);

        private:
            void readRobot(const ompl_core::XmlElement &element);
            /** A <tool name link> with an optional <origin>. */
            ToolFrame readToolFrame(const ompl_core::XmlElement &element);
            /** The file an attribute of element names (URDF or SRDF), relative to the scene's folder;
                an error at the attribute when it is no regular file. */
            std::string resolveFile(const ompl_core::XmlElement &element, const char *attribute,
                                    const std::string &kind) const;
            /** The name of an obstacle or object, whose element carries only the attributes
                allowed (name among them); obstacles and objects share one name space, the
                collision world's. */
            std::string claimBodyName(const ompl_core::XmlElement &element,
                                      std::initializer_list<const char *> allowed);
            void readObstacle(const ompl_core::XmlElement &element);
            void readSurface(const ompl_core::XmlElement &element);
            void readRegion(const ompl_core::XmlElement &element);
            void readObject(const ompl_core::XmlElement &element);
            void readStart(const ompl_core::XmlElement &element);
            void readStartObject(const ompl_core::XmlElement &element, ompl_core::FirstUses &started);
            /** The state attribute of a start's or goal's robot element, or "" when it gives joints
                (exactly one of the two); a name needs the robot's SRDF. */
            std::string readStateName(const ompl_core::XmlElement &element, const std::string &parent) const;
            void checkResting(const ompl_core::XmlElement &element, const MovableObject &object) const;
            void readGoal(const ompl_core::XmlElement &element);
            void readGoalObject(const ompl_core::XmlElement &element, ompl_core::FirstUses &goals);
            void readPrimitives(const ompl_core::XmlElement &element);
            void readPlanner(const ompl_core::XmlElement &element);

            std::string baseDir_;
            Scene scene_;
            ompl_core::FirstUses
                bodies_;  ///< obstacles and objects share one name space, the collision world
            ompl_core::FirstUses surfaces_;
            ompl_core::FirstUses regions_;
        };

        Scene SceneParser::parse(const ompl_core::XmlElement &root)
        {
            root.checkAttributes({"name", "time_limit"});
            scene_.name = root.text("name", fs::path(scene_.file).stem().string());
            if (root.has("time_limit"))
                scene_.timeLimit = root.positive("time_limit");

            auto byTag = ompl_core::childrenByTag(root,
                                                  {"robot", "obstacle", "surface", "region", "object",
                                                   "start", "goal", "primitives", "planner"},
                                                  {"obstacle", "surface", "region", "object"}, {"robot"});
            if (byTag["surface"].empty())
                root.fail("missing <surface> in <scene> (at least one support surface is needed)");
            for (const char *tag : {"start", "goal", "primitives"})
                if (byTag[tag].empty())
                    root.fail("missing <" + std::string(tag) + "> in <scene>");

            readRobot(byTag["robot"].front());
            for (const ompl_core::XmlElement &element : byTag["obstacle"])
                readObstacle(element);
            for (const ompl_core::XmlElement &element : byTag["surface"])
                readSurface(element);
            for (const ompl_core::XmlElement &element : byTag["region"])
                readRegion(element);
            for (const ompl_core::XmlElement &element : byTag["object"])
                readObject(element);
            readStart(byTag["start"].front());
            readGoal(byTag["goal"].front());
            readPrimitives(byTag["primitives"].front());
            if (!byTag["planner"].empty())
                readPlanner(byTag["planner"].front());
            return std::move(scene_);
        }

        void SceneParser::readRobot(const ompl_core::XmlElement &element)
        {
            element.checkAttributes({"urdf", "tool_link", "meshes", "srdf", "group"});
            RobotSpec &robot = scene_.robot;
            robot.where = element.where();
            robot.urdfFile = resolveFile(element, "urdf", "URDF");
            if (element.has("srdf"))
                robot.srdfFile = resolveFile(element, "srdf", "SRDF");
            robot.group = element.text("group", "");
            if (!robot.group.empty() && robot.srdfFile.empty())
                element.fail("group", "a planning group needs an SRDF file that defines it (attribute srdf)");
            robot.toolLink = element.text("tool_link");
            const std::string meshes = element.text("meshes", "exact");
            if (meshes == "convex_hull")
                robot.meshCollision = MeshCollision::ConvexHull;
            else if (meshes != "exact")
                element.fail("meshes", "attribute 'meshes' of " + element.tag() +
                                           " must be \"exact\" or \"convex_hull\", got '" + meshes + "'");
            ompl_core::FirstUses singles, toolNames, fixedNames;
            for (const ompl_core::XmlElement &child :
                 element.children({"origin", "tool_offset", "allow_collision", "tool", "fixed_joint"}))
            {
                if (child.name() == "fixed_joint")
                {
                    ompl_core::checkLeaf(child, {"name", "value"});
                    robot.fixedJoints.push_back({child.text("name"), child.number("value"), child.where()});
                    ompl_core::claimName(fixedNames, child, robot.fixedJoints.back().joint,
                                         "joint '" + robot.fixedJoints.back().joint + "' is fixed twice");
                    continue;
                }
                if (child.name() == "tool")
                {
                    robot.tools.push_back(readToolFrame(child));
                    ompl_core::claimName(toolNames, child, robot.tools.back().name,
                                         "duplicate tool frame '" + robot.tools.back().name + "'");
                    continue;
                }
                if (child.name() == "allow_collision")
                {
                    ompl_core::checkLeaf(child, {"link1", "link2"});
                    robot.allowedCollisions.push_back(
                        {child.text("link1"), child.text("link2"), child.where()});
                    continue;
                }
                ompl_core::claimOnce(singles, child, element);
                if (child.name() == "origin")
                    robot.basePose = ompl_core::readOrigin(child);
                else
                {
                    robot.toolOffset = ompl_core::readOrigin(child);
                }
            }
        }

        ToolFrame SceneParser::readToolFrame(const ompl_core::XmlElement &element)
        {
            element.checkAttributes({"name", "link"});
            ToolFrame tool{element.text("name"), element.text("link"), Eigen::Isometry3d::Identity(),
                           element.where()};
            ompl_core::FirstUses singles;
            for (const ompl_core::XmlElement &child : element.children({"origin"}))
            {
                ompl_core::claimOnce(singles, child, element);
                tool.pose = ompl_core::readOrigin(child);
            }
            return tool;
        }

        std::string SceneParser::resolveFile(const ompl_core::XmlElement &element, const char *attribute,
                                             const std::string &kind) const
        {
            const std::string file = element.text(attribute);
            fs::path path(file);
            if (path.is_relative())
                path = fs::path(baseDir_) / path;
            std::error_code error;
            if (!fs::is_regular_file(path, error))
                element.fail(attribute,
                             kind + " file '" + file + "' not found (looked for " + path.string() + ")");
            const fs::path absolute = fs::absolute(path, error);
            return (error ? path : absolute).lexically_normal().string();
        }

        std::string SceneParser::claimBodyName(const ompl_core::XmlElement &element,
                                               std::initializer_list<const char *> allowed)
        {
            element.checkAttributes(allowed);
            const std::string name = element.text("name");
            ompl_core::claimName(bodies_, element, name, "duplicate name '" + name + "'");
            return name;
        }

        void SceneParser::readObstacle(const ompl_core::XmlElement &element)
        {
            Obstacle obstacle;
            obstacle.name = claimBodyName(element, {"name"});
            obstacle.where = element.where();
            std::vector<ompl_core::XmlElement> shapes;
            ompl_core::FirstUses singles;
            for (const ompl_core::XmlElement &child :
                 element.children({"origin", "box", "cylinder", "sphere"}))
            {
                if (child.name() != "origin")
                {
                    shapes.push_back(child);
                    continue;
                }
                ompl_core::claimOnce(singles, child, element);
                obstacle.pose = ompl_core::readOrigin(child);
            }
            obstacle.shape = readOnlyShape(element, shapes);
            scene_.obstacles.push_back(obstacle);
        }

        void SceneParser::readSurface(const ompl_core::XmlElement &element)
        {
            ompl_core::checkLeaf(element, {"name", "height", "min", "max", "obstacle"});
            SupportSurface surface;
            surface.name = element.text("name");
            surface.where = element.where();
            ompl_core::claimName(surfaces_, element, surface.name,
                                 "duplicate surface name '" + surface.name + "'");
            surface.height = element.inRange("height", -ompl_core::MAX_LIST_VALUE, ompl_core::MAX_LIST_VALUE);
            surface.min = element.vector2("min");
            surface.max = element.vector2("max");
            if ((surface.min.array() >= surface.max.array()).any())
                element.fail("surface '" + surface.name + "': min must be less than max in both x and y");
            surface.obstacle = element.text("obstacle", "");
            const bool known = std::any_of(scene_.obstacles.begin(), scene_.obstacles.end(),
                                           [&](const Obstacle &o) { return o.name == surface.obstacle; });
            if (!surface.obstacle.empty() && !known)
                element.fail("obstacle", "surface '" + surface.name + "' names unknown obstacle '" +
                                             surface.obstacle + "'");
            scene_.surfaces.push_back(surface);
        }

        void SceneParser::readRegion(const ompl_core::XmlElement &element)
        {
            ompl_core::checkLeaf(element, {"name", "min", "max"});
            SamplingRegion region;
            region.name = element.text("name");
            region.where = element.where();
            ompl_core::claimName(regions_, element, region.name,
                                 "duplicate region name '" + region.name + "'");
            const Eigen::Vector3d min = element.vector3("min");
            const Eigen::Vector3d max = element.vector3("max");
            if ((min.array() >= max.array()).any())
                element.fail("region '" + region.name + "': min must be less than max in x, y and z");
            region.box = Eigen::AlignedBox3d(min, max);
            scene_.samplingRegions.push_back(region);
        }

        void SceneParser::readObject(const ompl_core::XmlElement &element)
        {
            if (scene_.objects.size() == MAX_OBJECTS)
                element.fail("a scene holds at most " + std::to_string(MAX_OBJECTS) + " movable objects");
            MovableObject object;
            object.name = claimBodyName(element, {"name", "mass", "friction"});
            object.where = element.where();
            object.mass = element.has("mass") ? element.positive("mass") : MovableObject::DEFAULT_MASS;
            if (object.mass > MovableObject::MAX_MASS)
                element.fail("mass", "mass must be at most " +
                                         ompl_core::formatNumber(MovableObject::MAX_MASS) + " kg");
            object.friction = element.inRange("friction", 0.0, MovableObject::MAX_FRICTION,
                                              MovableObject::DEFAULT_FRICTION);
            object.shape = readOnlyShape(element, element.children({"box", "cylinder", "sphere"}));
            scene_.objects.push_back(object);
        }

        void SceneParser::readStart(const ompl_core::XmlElement &element)
        {
            element.checkAttributes({});
            ompl_core::FirstUses singles;
            ompl_core::FirstUses started;
            for (const ompl_core::XmlElement &child : element.children({"robot", "object"}))
            {
                if (child.name() == "object")
                {
                    readStartObject(child, started);
                    continue;
                }
                ompl_core::claimOnce(singles, child, element);
                ompl_core::checkLeaf(child, {"joints", "state"});
                scene_.robotStartWhere = child.where();
                scene_.robotStartState = readStateName(child, "start");
                if (scene_.robotStartState.empty())
                    scene_.robotStart = child.numbers("joints", 0);
            }
            if (singles.empty())
                element.fail("missing <robot joints=\"...\"/> in <start>");
            for (const MovableObject &object : scene_.objects)
                if (started.count(object.name) == 0)
                    throw ompl_core::InputError(
                        object.where, "object '" + object.name + "' has no start: add <object name=\"" +
                                          object.name + "\" xyz=\"...\"/> to <start> (line " +
                                          std::to_string(element.where().line) + ")");
        }

        std::string SceneParser::readStateName(const ompl_core::XmlElement &element,
                                               const std::string &parent) const
        {
            const bool joints = element.has("joints"), state = element.has("state");
            if (joints == state)
                element.fail("<robot> in <" + parent +
                             "> needs either joints=\"...\" or state=\"NAME\" (a group state of the SRDF)");
            // the robot element is read first, wherever it stands
            if (state && scene_.robot.srdfFile.empty())
                element.fail("state", "a named state needs an SRDF file (attribute srdf of <robot> at line " +
                                          std::to_string(scene_.robot.where.line) + ")");
            return state ? element.text("state") : "";
        }

        void SceneParser::readStartObject(const ompl_core::XmlElement &element, ompl_core::FirstUses &started)
        {
            ompl_core::checkLeaf(element, {"name", "xyz", "yaw"});
            const std::string name = element.text("name");
            const int index = scene_.objectIndex(name);
            if (index < 0)
                element.fail("name",
                             "start for unknown object '" + name + "' (no <object name=\"" + name + "\">)");
            ompl_core::claimName(started, element, name, "second start for object '" + name + "'");
            MovableObject &object = scene_.objects[index];
            object.start.position = element.vector3("xyz");
            object.start.yaw = element.angle("yaw", 0.0);
            checkResting(element, object);
        }

        void SceneParser::checkResting(const ompl_core::XmlElement &element,
                                       const MovableObject &object) const
        {
            if (scene_.restingSurface(object.start.position) >= 0)
                return;
            element.fail("xyz",
                         "start of object '" + object.name +
                             "' does not rest on any <surface>: z must equal a surface's height (within "
                             "1e-4) and x, y lie inside it");
        }

        void SceneParser::readGoal(const ompl_core::XmlElement &element)
        {
            element.checkAttributes({});
            const std::vector<ompl_core::XmlElement> children = element.children({"robot", "object"});
            if (children.empty())
                element.fail("<goal> needs at least one <robot> or <object> child");
            ompl_core::FirstUses singles;
            ompl_core::FirstUses goals;
            for (const ompl_core::XmlElement &child : children)
            {
                if (child.name() == "object")
                {
                    readGoalObject(child, goals);
                    continue;
                }
                ompl_core::claimOnce(singles, child, element);
                ompl_core::checkLeaf(child, {"joints", "state", "tolerance"});
                RobotGoal &goal = scene_.robotGoal;
                goal.state = readStateName(child, "goal");
                if (goal.state.empty())
                    goal.joints = child.coordinates("joints", 0);
                goal.tolerance = child.nonNegative("tolerance", goal.tolerance);
                goal.where = child.where();
            }
        }

        void SceneParser::readGoalObject(const ompl_core::XmlElement &element, ompl_core::FirstUses &goals)
        {
            ompl_core::checkLeaf(element, {"name", "xyz", "yaw", "tolerance", "yaw_tolerance"});
            ObjectGoal goal;
            goal.object = element.text("name");
            if (scene_.objectIndex(goal.object) < 0)
                element.fail("name", "goal for unknown object '" + goal.object + "' (no <object name=\"" +
                                         goal.object + "\">)");
            ompl_core::claimName(goals, element, goal.object, "second goal for object '" + goal.object + "'");
            const std::vector<GoalCoordinate> xyz = element.coordinates("xyz", 3);
            std::copy(xyz.begin(), xyz.end(), goal.position.begin());
            goal.yaw = element.angleOrAny("yaw", std::nullopt);
            goal.positionTolerance = element.nonNegative("tolerance", goal.positionTolerance);
            goal.yawTolerance = element.nonNegativeAngle("yaw_tolerance", goal.yawTolerance);
            goal.where = element.where();
            scene_.objectGoals.push_back(goal);
        }

        void SceneParser::readPrimitives(const ompl_core::XmlElement &element)
        {
            element.checkAttributes({});
            for (const ompl_core::XmlElement &child : element.children())
            {
                // a primitive's parameters are checked by the primitive itself
                child.children({});
                PrimitiveSpec primitive;
                primitive.type = child.name();
                for (const auto &[name, value] : child.attributes())
                    primitive.params[name] = value;
                primitive.where = child.where();
                scene_.primitives.push_back(primitive);
            }
            if (scene_.primitives.empty())
                element.fail("<primitives> needs at least one primitive, e.g. <transit/>");
        }

        void SceneParser::readPlanner(const ompl_core::XmlElement &element)
        {
            element.checkAttributes({"type"});
            scene_.planner = element.text("type", scene_.planner);
            ompl_core::FirstUses names;
            for (const ompl_core::XmlElement &child : element.children({"param"}))
            {
                ompl_core::checkLeaf(child, {"name", "value"});
                ompl_core::ParameterSetting param;
                param.name = child.text("name");
                param.value = child.text("value");
                param.where = child.where();
                ompl_core::claimName(names, child, param.name, "second <param> '" + param.name + "'");
                scene_.plannerParams.push_back(param);
            }
        }
    }  // namespace

    Scene loadScene(const std::string &path)
    {
        return parseScene(ompl_core::readInputFile(path, "scene file"), path,
                          fs::path(path).parent_path().string());
    }

    Scene parseScene(const std::string &xml, const std::string &sourceName, const std::string &baseDir)
    {
        tinyxml2::XMLDocument document;
        return SceneParser(sourceName, baseDir)
            .parse(ompl_core::parseRootElement(document, xml, sourceName, "scene"));
    }
}  // namespace ompl_mm
