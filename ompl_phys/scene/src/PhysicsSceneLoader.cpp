#include "ompl_phys/scene/PhysicsSceneLoader.h"

#include <tinyxml2.h>

#include <cmath>
#include <filesystem>
#include <locale>
#include <map>
#include <sstream>

#include "ompl_core/io/InputError.h"
#include "ompl_core/io/InputFile.h"
#include "ompl_core/io/XmlReading.h"
#include "ompl_phys/scene/PhysicalBounds.h"

namespace ompl_phys
{
    namespace
    {

        /** "xmin xmax ymin ymax" as a box, each max above its min. */
        Eigen::AlignedBox2d readRegion(const ompl_core::XmlElement &element, const char *attribute,
                                       const Eigen::AlignedBox2d &fallback)
        {
            if (!element.has(attribute))
                return fallback;
            const std::vector<double> v = element.numbers(attribute, 4);
            if (!(v[0] < v[1] && v[2] < v[3]))
                element.fail(attribute,
                             std::string(attribute) + " must be \"xmin xmax ymin ymax\" with min < max");
            return Eigen::AlignedBox2d(Eigen::Vector2d(v[0], v[2]), Eigen::Vector2d(v[1], v[3]));
        }

        PhysicsShape readShape(const ompl_core::XmlElement &element)
        {
            PhysicsShape shape;
            const std::string name = element.name();
            if (name == "box")
            {
                ompl_core::checkLeaf(element, {"size"});
                shape.kind = PhysicsShape::Kind::Box;
                shape.boxSize = element.lengths3("size");
            }
            else if (name == "cylinder")
            {
                ompl_core::checkLeaf(element, {"radius", "length"});
                shape.kind = PhysicsShape::Kind::Cylinder;
                shape.radius = element.length("radius");
                shape.length = element.length("length");
            }
            else if (name == "sphere")
            {
                ompl_core::checkLeaf(element, {"radius"});
                shape.kind = PhysicsShape::Kind::Sphere;
                shape.radius = element.length("radius");
            }
            else
            {
                ompl_core::checkLeaf(element, {"corners", "length"});
                shape.kind = PhysicsShape::Kind::Prism;
                const std::vector<double> c = element.numbers("corners", 6);
                shape.triangle << c[0], c[2], c[4], c[1], c[3], c[5];
                shape.length = element.length("length");
                const Eigen::Vector2d a = shape.triangle.col(1) - shape.triangle.col(0);
                const Eigen::Vector2d b = shape.triangle.col(2) - shape.triangle.col(0);
                const double area2 = a.x() * b.y() - a.y() * b.x();
                if (area2 <= 1e-9)
                    element.fail("corners",
                                 "the prism's corners must be counter-clockwise and not collinear");
            }
            return shape;
        }

        /** Builds a PhysicsScene from the <physics_scene> element. */
        class PhysicsSceneParser
        {
        public:
            explicit PhysicsSceneParser(const std::string &file) { scene_.file = file; }

            PhysicsScene parse(const ompl_core::XmlElement &root);

        private:
            void readSimulation(const ompl_core::XmlElement &element);
            void readMaterials(const ompl_core::XmlElement &element);
            void readLimits(const ompl_core::XmlElement &element);
            void readFloor(const ompl_core::XmlElement &element);
            void readRobot(const ompl_core::XmlElement &element);
            void readBody(const ompl_core::XmlElement &element);
            void readPush(const ompl_core::XmlElement &element, PhysicsBody &body);
            void readGoal(const ompl_core::XmlElement &element);
            void checkPlacement(const ompl_core::XmlElement &robot, const ompl_core::XmlElement &goal) const;
            void checkBodies() const;
            void checkWorkPerControl() const;

            PhysicsScene scene_;
            ompl_core::FirstUses names_;
        };

        PhysicsScene PhysicsSceneParser::parse(const ompl_core::XmlElement &root)
        {
            root.checkAttributes({"name", "time_limit"});
            scene_.name = root.text("name", std::filesystem::path(scene_.file).stem().string());
            if (root.has("time_limit"))
                scene_.timeLimit = root.positive("time_limit");

            auto byTag = ompl_core::childrenByTag(
                root, {"simulation", "materials", "limits", "floor", "robot", "body", "goal"}, {"body"},
                {"robot", "goal"});

            for (const ompl_core::XmlElement &e : byTag["simulation"])
                readSimulation(e);
            for (const ompl_core::XmlElement &e : byTag["materials"])
                readMaterials(e);
            for (const ompl_core::XmlElement &e : byTag["limits"])
                readLimits(e);
            for (const ompl_core::XmlElement &e : byTag["floor"])
                readFloor(e);
            readRobot(byTag["robot"].front());
            for (const ompl_core::XmlElement &e : byTag["body"])
                readBody(e);
            readGoal(byTag["goal"].front());
            checkPlacement(byTag["robot"].front(), byTag["goal"].front());
            checkBodies();
            checkWorkPerControl();
            return scene_;
        }

        void PhysicsSceneParser::readSimulation(const ompl_core::XmlElement &element)
        {
            ompl_core::checkLeaf(element,
                                 {"gravity", "erp", "cfm", "max_contacts", "iterations", "substeps"});
            ContactParameters &c = scene_.contact;
            c.gravity = element.inRange("gravity", -bounds::MAX_GRAVITY, 0.0, c.gravity);
            c.erp = element.inRange("erp", 1e-6, 1.0, c.erp);
            c.cfm = element.inRange("cfm", 0.0, 1.0, c.cfm);
            c.maxContacts = element.count("max_contacts", 1, 16, c.maxContacts);
            c.iterations = element.count("iterations", 1, 1000, c.iterations);
            c.substeps = element.count("substeps", 1, bounds::MAX_SUBSTEPS_PER_CONTROL, c.substeps);
            c.where = element.where();
        }

        void PhysicsSceneParser::readMaterials(const ompl_core::XmlElement &element)
        {
            ompl_core::checkLeaf(element, {"robot_floor", "default"});
            scene_.materials.robotFloor =
                element.inRange("robot_floor", 0.0, bounds::MAX_FRICTION, scene_.materials.robotFloor);
            scene_.materials.defaultMu =
                element.inRange("default", 0.0, bounds::MAX_FRICTION, scene_.materials.defaultMu);
            scene_.materials.where = element.where();
        }

        void PhysicsSceneParser::readLimits(const ompl_core::XmlElement &element)
        {
            ompl_core::checkLeaf(
                element, {"robot_region", "body_region", "max_robot_speed", "max_body_speed",
                          "max_angular_speed", "max_force", "step", "min_steps", "max_steps", "goal_bias"});
            PlanningLimits &l = scene_.limits;
            l.robotRegion = readRegion(element, "robot_region", l.robotRegion);
            l.bodyRegion = readRegion(element, "body_region", l.bodyRegion);
            // positive quantities with an upper bound: given, they must be in (0, high]
            const auto bounded = [&element](const char *attribute, double high, double fallback)
            {
                if (!element.has(attribute))
                    return fallback;
                element.positive(attribute);
                return element.inRange(attribute, 0.0, high);
            };
            l.maxRobotSpeed = bounded("max_robot_speed", bounds::MAX_SPEED, l.maxRobotSpeed);
            l.maxBodySpeed = bounded("max_body_speed", bounds::MAX_SPEED, l.maxBodySpeed);
            l.maxAngularSpeed = bounded("max_angular_speed", bounds::MAX_ANGULAR_SPEED, l.maxAngularSpeed);
            l.maxForce = bounded("max_force", bounds::MAX_FORCE, l.maxForce);
            l.stepSize = bounded("step", bounds::MAX_STEP, l.stepSize);
            l.minControlSteps =
                element.count("min_steps", 1, bounds::MAX_SUBSTEPS_PER_CONTROL, l.minControlSteps);
            l.maxControlSteps =
                element.count("max_steps", 1, bounds::MAX_SUBSTEPS_PER_CONTROL, l.maxControlSteps);
            if (l.maxControlSteps < l.minControlSteps)
                element.fail("max_steps", "max_steps (" + std::to_string(l.maxControlSteps) +
                                              ") must not be below min_steps (" +
                                              std::to_string(l.minControlSteps) + ")");
            l.goalBias = element.inRange("goal_bias", 0.0, 1.0, l.goalBias);
            l.where = element.where();
        }

        void PhysicsSceneParser::readFloor(const ompl_core::XmlElement &element)
        {
            ompl_core::checkLeaf(element, {"size"});
            scene_.floorSize = element.vector2("size");
            if (!(scene_.floorSize.array() > 0.0).all())
                element.fail("size", "the floor size must be two positive numbers");
        }

        void PhysicsSceneParser::readRobot(const ompl_core::XmlElement &element)
        {
            ompl_core::checkLeaf(element, {"name", "radius", "mass", "start"});
            PhysicsRobot &robot = scene_.robot;
            robot.name = element.text("name", robot.name);
            robot.radius = element.length("radius");
            robot.mass = element.inRange("mass", bounds::MIN_MASS, bounds::MAX_MASS);
            robot.start << element.vector2("start"), robot.radius;
            robot.where = element.where();
            names_.emplace(robot.name, robot.where);
        }

        void PhysicsSceneParser::readBody(const ompl_core::XmlElement &element)
        {
            element.checkAttributes({"name", "kind", "mass"});
            PhysicsBody body;
            body.name = element.text("name");
            body.where = element.where();
            ompl_core::claimName(names_, element, body.name, "second body named '" + body.name + "'");
            const std::string kind = element.text("kind");
            if (kind == "fixed")
                body.kind = BodyKind::Fixed;
            else if (kind == "free")
                body.kind = BodyKind::Free;
            else if (kind == "constrained")
                body.kind = BodyKind::Constrained;
            else
                element.fail("kind", "unknown kind '" + kind + "', expected fixed, free or constrained");
            if (body.kind == BodyKind::Fixed && element.has("mass"))
                element.fail("mass", "a fixed body has no mass");
            if (body.kind != BodyKind::Fixed)
                body.mass = element.inRange("mass", bounds::MIN_MASS, bounds::MAX_MASS);

            std::vector<ompl_core::XmlElement> shapes;
            bool hasOrigin = false;
            bool hasPush = false;
            for (const ompl_core::XmlElement &child :
                 element.children({"origin", "box", "cylinder", "sphere", "prism", "push"}))
            {
                const std::string name = child.name();
                if (name == "origin" || name == "push")
                {
                    bool &seen = name == "origin" ? hasOrigin : hasPush;
                    if (seen)
                        child.fail("second " + child.tag() + " in body '" + body.name + "'");
                    seen = true;
                    if (name == "origin")
                        body.start = ompl_core::readOrigin(child);
                    else
                        readPush(child, body);
                }
                else
                    shapes.push_back(child);
            }
            if (shapes.size() != 1)
                (shapes.empty() ? element : shapes[1])
                    .fail("body '" + body.name +
                          "' needs exactly one shape (<box>, <cylinder>, <sphere> or <prism>), found " +
                          std::to_string(shapes.size()));
            body.shape = readShape(shapes.front());
            // ODE needs a dynamic body's centre of mass at its origin, which a prism's corners do not fix
            if (body.shape.kind == PhysicsShape::Kind::Prism && body.kind != BodyKind::Fixed)
                shapes.front().fail("a <prism> can only be a fixed body; '" + body.name + "' is " + kind);
            if (body.kind == BodyKind::Constrained && !hasPush)
                element.fail("constrained body '" + body.name + "' needs a <push> element (axis and region)");
            scene_.bodies.push_back(body);
        }

        void PhysicsSceneParser::readPush(const ompl_core::XmlElement &element, PhysicsBody &body)
        {
            ompl_core::checkLeaf(element,
                                 {"axis", "strip_half_width", "lateral_tolerance", "angle_tolerance"});
            if (body.kind != BodyKind::Constrained)
                element.fail("<push> is only for constrained bodies, '" + body.name + "' is not");
            const Eigen::Vector3d axis = element.vector3("axis");
            if (axis.norm() < 1e-9)
                element.fail("axis", "the push axis must not be zero");
            body.push.axis = axis.normalized();
            body.push.stripHalfWidth = element.positive("strip_half_width");
            body.push.lateralTolerance = element.positive("lateral_tolerance");
            body.push.angleTolerance = element.nonNegativeAngle("angle_tolerance", 0.0);
            if (body.push.angleTolerance <= 0.0)
                element.fail("angle_tolerance", "angle_tolerance must be given and > 0");
        }

        void PhysicsSceneParser::readGoal(const ompl_core::XmlElement &element)
        {
            ompl_core::checkLeaf(element, {"xy", "radius"});
            scene_.goal.centre = element.vector2("xy");
            scene_.goal.radius = element.length("radius");
            scene_.goal.where = element.where();
        }

        void PhysicsSceneParser::checkPlacement(const ompl_core::XmlElement &robot,
                                                const ompl_core::XmlElement &goal) const
        {
            const Eigen::AlignedBox2d &region = scene_.limits.robotRegion;
            if (region.isEmpty())
                robot.fail("no robot region: give <limits robot_region=\"xmin xmax ymin ymax\">");
            if (scene_.limits.bodyRegion.isEmpty())
                robot.fail("no body region: give <limits body_region=\"xmin xmax ymin ymax\">");
            if (!region.contains(scene_.robot.start.head<2>()))
                robot.fail("start", "the robot starts outside its region (limits robot_region)");
            if (!region.contains(scene_.goal.centre))
                goal.fail("xy", "the goal centre is outside the robot region (limits robot_region)");
        }

        void PhysicsSceneParser::checkBodies() const
        {
            for (const PhysicsBody &body : scene_.bodies)
                if (body.kind != BodyKind::Fixed &&
                    !scene_.limits.bodyRegion.contains(body.start.translation().head<2>()))
                    throw ompl_core::InputError(
                        body.where,
                        "body '" + body.name + "' starts outside the body region (limits body_region)");
        }

        void PhysicsSceneParser::checkWorkPerControl() const
        {
            // a propagation does not poll the planner's time limit: the longest one must be short
            const unsigned int work = scene_.limits.maxControlSteps * scene_.contact.substeps;
            if (work > bounds::MAX_SUBSTEPS_PER_CONTROL)
                throw ompl_core::InputError(
                    scene_.limits.where.line > 0 ? scene_.limits.where : scene_.contact.where,
                    "max_steps × substeps = " + std::to_string(scene_.limits.maxControlSteps) + " × " +
                        std::to_string(scene_.contact.substeps) + " = " + std::to_string(work) +
                        " ODE sub-steps per control, more than " +
                        std::to_string(bounds::MAX_SUBSTEPS_PER_CONTROL) +
                        ": one control's propagation could overrun the planner's time limit");
        }
    }  // namespace

    PhysicsScene loadPhysicsScene(const std::string &path)
    {
        return parsePhysicsScene(ompl_core::readInputFile(path, "scene file"), path);
    }

    PhysicsScene parsePhysicsScene(const std::string &xml, const std::string &sourceName)
    {
        tinyxml2::XMLDocument document;
        return PhysicsSceneParser(sourceName)
            .parse(ompl_core::parseRootElement(document, xml, sourceName, "physics_scene"));
    }
}  // namespace ompl_phys
