#include "ompl_mm/scene/SceneLoader.h"

#include <tinyxml2.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <system_error>

#include "ompl_mm/scene/InputError.h"
#include "ompl_mm/scene/XmlReading.h"

namespace ompl_mm
{
    namespace
    {
        namespace fs = std::filesystem;

        /** An object rests on a surface when its base height differs from the surface height by
            less than this, metres (the tolerance of the original MOPL implementation). */
        constexpr double RESTING_TOLERANCE = 1e-4;

        /** For each name or tag already used, where it was first used. */
        using FirstUses = std::map<std::string, SourceLocation>;

        /** Records that element uses name. @throws InputError with message when it was used before. */
        void claimName(FirstUses &uses, const XmlElement &element, const std::string &name,
                       const std::string &message)
        {
            const auto [first, inserted] = uses.emplace(name, element.where());
            if (!inserted)
                element.fail("name", message + " (first at line " + std::to_string(first->second.line) + ")");
        }

        /** Records that child appears in parent. @throws InputError when it appeared before. */
        void claimOnce(FirstUses &uses, const XmlElement &child, const XmlElement &parent)
        {
            const auto [first, inserted] = uses.emplace(child.name(), child.where());
            if (!inserted)
                child.fail("second " + child.tag() + " in " + parent.tag() +
                           ", only one is allowed (first at line " + std::to_string(first->second.line) +
                           ")");
        }

        Shape readShape(const XmlElement &element)
        {
            Shape shape;
            if (element.name() == "box")
            {
                checkLeaf(element, {"size"});
                shape.kind = Shape::Kind::Box;
                shape.boxSize = element.positiveVector3("size");
            }
            else if (element.name() == "cylinder")
            {
                checkLeaf(element, {"radius", "length"});
                shape.kind = Shape::Kind::Cylinder;
                shape.radius = element.positive("radius");
                shape.length = element.positive("length");
            }
            else
            {
                checkLeaf(element, {"radius"});
                shape.kind = Shape::Kind::Sphere;
                shape.radius = element.positive("radius");
            }
            return shape;
        }

        /** The one shape among the shape elements of a body. */
        Shape readOnlyShape(const XmlElement &body, const std::vector<XmlElement> &shapes)
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

            Scene parse(const XmlElement &root);

        private:
            void readRobot(const XmlElement &element);
            std::string resolveUrdf(const XmlElement &element) const;
            void readObstacle(const XmlElement &element);
            void readSurface(const XmlElement &element);
            void readRegion(const XmlElement &element);
            void readObject(const XmlElement &element);
            void readStart(const XmlElement &element);
            void readStartObject(const XmlElement &element, FirstUses &started);
            void checkResting(const XmlElement &element, const MovableObject &object) const;
            void readGoal(const XmlElement &element);
            void readGoalObject(const XmlElement &element, FirstUses &goals);
            void readPrimitives(const XmlElement &element);
            void readPlanner(const XmlElement &element);

            std::string baseDir_;
            Scene scene_;
            FirstUses bodies_;  ///< obstacles and objects share one name space, the collision world
            FirstUses surfaces_;
            FirstUses regions_;
        };

        Scene SceneParser::parse(const XmlElement &root)
        {
            root.checkAttributes({"name", "time_limit"});
            scene_.name = root.text("name", fs::path(scene_.file).stem().string());
            if (root.has("time_limit"))
                scene_.timeLimit = root.positive("time_limit");

            std::map<std::string, std::vector<XmlElement>> byTag;
            FirstUses singles;
            for (const XmlElement &child : root.children({"robot", "obstacle", "surface", "region", "object",
                                                          "start", "goal", "primitives", "planner"}))
            {
                const std::string tag = child.name();
                if (tag != "obstacle" && tag != "surface" && tag != "region" && tag != "object")
                    claimOnce(singles, child, root);
                byTag[tag].push_back(child);
            }
            for (const char *tag : {"robot", "surface", "start", "goal", "primitives"})
                if (byTag[tag].empty())
                    root.fail(
                        "missing <" + std::string(tag) + "> in <scene>" +
                        (tag == std::string("surface") ? " (at least one support surface is needed)" : ""));

            readRobot(byTag["robot"].front());
            for (const XmlElement &element : byTag["obstacle"])
                readObstacle(element);
            for (const XmlElement &element : byTag["surface"])
                readSurface(element);
            for (const XmlElement &element : byTag["region"])
                readRegion(element);
            for (const XmlElement &element : byTag["object"])
                readObject(element);
            readStart(byTag["start"].front());
            readGoal(byTag["goal"].front());
            readPrimitives(byTag["primitives"].front());
            if (!byTag["planner"].empty())
                readPlanner(byTag["planner"].front());
            return std::move(scene_);
        }

        void SceneParser::readRobot(const XmlElement &element)
        {
            element.checkAttributes({"urdf", "tool_link"});
            RobotSpec &robot = scene_.robot;
            robot.where = element.where();
            robot.urdfFile = resolveUrdf(element);
            robot.toolLink = element.text("tool_link");
            FirstUses singles;
            for (const XmlElement &child : element.children({"origin", "tool_offset", "allow_collision"}))
            {
                if (child.name() == "allow_collision")
                {
                    checkLeaf(child, {"link1", "link2"});
                    robot.allowedCollisions.emplace_back(child.text("link1"), child.text("link2"));
                    continue;
                }
                claimOnce(singles, child, element);
                if (child.name() == "origin")
                    robot.basePose = readOrigin(child);
                else
                {
                    checkLeaf(child, {"xyz"});
                    robot.toolOffset = child.vector3("xyz");
                }
            }
        }

        std::string SceneParser::resolveUrdf(const XmlElement &element) const
        {
            const std::string urdf = element.text("urdf");
            fs::path path(urdf);
            if (path.is_relative())
                path = fs::path(baseDir_) / path;
            std::error_code error;
            if (!fs::is_regular_file(path, error))
                element.fail("urdf", "URDF file '" + urdf + "' not found (looked for " + path.string() + ")");
            const fs::path absolute = fs::absolute(path, error);
            return (error ? path : absolute).lexically_normal().string();
        }

        void SceneParser::readObstacle(const XmlElement &element)
        {
            element.checkAttributes({"name"});
            Obstacle obstacle;
            obstacle.name = element.text("name");
            obstacle.where = element.where();
            claimName(bodies_, element, obstacle.name, "duplicate name '" + obstacle.name + "'");
            std::vector<XmlElement> shapes;
            FirstUses singles;
            for (const XmlElement &child : element.children({"origin", "box", "cylinder", "sphere"}))
            {
                if (child.name() != "origin")
                {
                    shapes.push_back(child);
                    continue;
                }
                claimOnce(singles, child, element);
                obstacle.pose = readOrigin(child);
            }
            obstacle.shape = readOnlyShape(element, shapes);
            scene_.obstacles.push_back(obstacle);
        }

        void SceneParser::readSurface(const XmlElement &element)
        {
            checkLeaf(element, {"name", "height", "min", "max", "obstacle"});
            SupportSurface surface;
            surface.name = element.text("name");
            surface.where = element.where();
            claimName(surfaces_, element, surface.name, "duplicate surface name '" + surface.name + "'");
            surface.height = element.number("height");
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

        void SceneParser::readRegion(const XmlElement &element)
        {
            checkLeaf(element, {"name", "min", "max"});
            SamplingRegion region;
            region.name = element.text("name");
            region.where = element.where();
            claimName(regions_, element, region.name, "duplicate region name '" + region.name + "'");
            const Eigen::Vector3d min = element.vector3("min");
            const Eigen::Vector3d max = element.vector3("max");
            if ((min.array() >= max.array()).any())
                element.fail("region '" + region.name + "': min must be less than max in x, y and z");
            region.box = Eigen::AlignedBox3d(min, max);
            scene_.samplingRegions.push_back(region);
        }

        void SceneParser::readObject(const XmlElement &element)
        {
            element.checkAttributes({"name"});
            MovableObject object;
            object.name = element.text("name");
            object.where = element.where();
            claimName(bodies_, element, object.name, "duplicate name '" + object.name + "'");
            object.shape = readOnlyShape(element, element.children({"box", "cylinder", "sphere"}));
            scene_.objects.push_back(object);
        }

        void SceneParser::readStart(const XmlElement &element)
        {
            element.checkAttributes({});
            FirstUses singles;
            FirstUses started;
            for (const XmlElement &child : element.children({"robot", "object"}))
            {
                if (child.name() == "object")
                {
                    readStartObject(child, started);
                    continue;
                }
                claimOnce(singles, child, element);
                checkLeaf(child, {"joints"});
                scene_.robotStart = child.numbers("joints", 0);
                scene_.robotStartWhere = child.where();
            }
            if (singles.empty())
                element.fail("missing <robot joints=\"...\"/> in <start>");
            for (const MovableObject &object : scene_.objects)
                if (started.count(object.name) == 0)
                    throw InputError(object.where, "object '" + object.name +
                                                       "' has no start: add <object name=\"" + object.name +
                                                       "\" xyz=\"...\"/> to <start> (line " +
                                                       std::to_string(element.where().line) + ")");
        }

        void SceneParser::readStartObject(const XmlElement &element, FirstUses &started)
        {
            checkLeaf(element, {"name", "xyz", "yaw"});
            const std::string name = element.text("name");
            const int index = scene_.objectIndex(name);
            if (index < 0)
                element.fail("name",
                             "start for unknown object '" + name + "' (no <object name=\"" + name + "\">)");
            claimName(started, element, name, "second start for object '" + name + "'");
            MovableObject &object = scene_.objects[index];
            object.start.position = element.vector3("xyz");
            object.start.yaw = element.angle("yaw", 0.0);
            checkResting(element, object);
        }

        void SceneParser::checkResting(const XmlElement &element, const MovableObject &object) const
        {
            const Eigen::Vector3d &p = object.start.position;
            for (const SupportSurface &surface : scene_.surfaces)
                if (std::abs(p.z() - surface.height) < RESTING_TOLERANCE && surface.contains(p.x(), p.y()))
                    return;
            element.fail("xyz",
                         "start of object '" + object.name +
                             "' does not rest on any <surface>: z must equal a surface's height (within "
                             "1e-4) and x, y lie inside it");
        }

        void SceneParser::readGoal(const XmlElement &element)
        {
            element.checkAttributes({});
            const std::vector<XmlElement> children = element.children({"robot", "object"});
            if (children.empty())
                element.fail("<goal> needs at least one <robot> or <object> child");
            FirstUses singles;
            FirstUses goals;
            for (const XmlElement &child : children)
            {
                if (child.name() == "object")
                {
                    readGoalObject(child, goals);
                    continue;
                }
                claimOnce(singles, child, element);
                checkLeaf(child, {"joints", "tolerance"});
                RobotGoal &goal = scene_.robotGoal;
                goal.joints = child.coordinates("joints", 0);
                goal.tolerance = child.nonNegative("tolerance", goal.tolerance);
                goal.where = child.where();
            }
        }

        void SceneParser::readGoalObject(const XmlElement &element, FirstUses &goals)
        {
            checkLeaf(element, {"name", "xyz", "yaw", "tolerance", "yaw_tolerance"});
            ObjectGoal goal;
            goal.object = element.text("name");
            if (scene_.objectIndex(goal.object) < 0)
                element.fail("name", "goal for unknown object '" + goal.object + "' (no <object name=\"" +
                                         goal.object + "\">)");
            claimName(goals, element, goal.object, "second goal for object '" + goal.object + "'");
            const std::vector<GoalCoordinate> xyz = element.coordinates("xyz", 3);
            std::copy(xyz.begin(), xyz.end(), goal.position.begin());
            goal.yaw = element.angleOrAny("yaw", std::nullopt);
            goal.positionTolerance = element.nonNegative("tolerance", goal.positionTolerance);
            goal.yawTolerance = element.nonNegativeAngle("yaw_tolerance", goal.yawTolerance);
            goal.where = element.where();
            scene_.objectGoals.push_back(goal);
        }

        void SceneParser::readPrimitives(const XmlElement &element)
        {
            element.checkAttributes({});
            for (const XmlElement &child : element.children())
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

        void SceneParser::readPlanner(const XmlElement &element)
        {
            element.checkAttributes({"type"});
            scene_.planner = element.text("type", scene_.planner);
            FirstUses names;
            for (const XmlElement &child : element.children({"param"}))
            {
                checkLeaf(child, {"name", "value"});
                PlannerParam param;
                param.name = child.text("name");
                param.value = child.text("value");
                param.where = child.where();
                claimName(names, child, param.name, "second <param> '" + param.name + "'");
                scene_.plannerParams.push_back(param);
            }
        }
    }  // namespace

    Scene loadScene(const std::string &path)
    {
        return parseScene(readInputFile(path, "scene file"), path, fs::path(path).parent_path().string());
    }

    Scene parseScene(const std::string &xml, const std::string &sourceName, const std::string &baseDir)
    {
        tinyxml2::XMLDocument document;
        return SceneParser(sourceName, baseDir).parse(parseRootElement(document, xml, sourceName, "scene"));
    }
}  // namespace ompl_mm
