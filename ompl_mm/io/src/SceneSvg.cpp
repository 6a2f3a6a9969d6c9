#include "ompl_mm/io/SceneSvg.h"

#include "ompl_core/io/SvgCanvas.h"
#include "ompl_core/io/TextFormat.h"
#include "ompl_mm/io/PlanColours.h"

#include <ompl/base/ScopedState.h>
#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <locale>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace ompl_mm
{
    namespace
    {
        // the picture is laid out in pixels: world metres are mapped into a band between a title strip
        // and a legend strip, so line widths and fonts look the same for any scene size
        const ompl_core::SvgCanvas::Layout LAYOUT;  // the canvas's default strips
        constexpr double MARGIN_FRACTION = 0.05;
        constexpr unsigned int SUB_STEPS = 20;
        constexpr double HEIGHT_QUANTUM = 1e-6;

        const char *const ARROW_COLOUR = "#8b0000";
        const std::string ARROW_STYLE = std::string("stroke=\"") + ARROW_COLOUR +
                                        R"svg(" stroke-width="2" marker-end="url(#arrowhead)")svg";

        /** An upright outline seen from above: a polygon, or a circle when radius > 0. */
        struct Footprint
        {
            std::vector<Eigen::Vector2d> corners;
            Eigen::Vector2d centre{Eigen::Vector2d::Zero()};
            double radius{0.0};
        };

        /** An obstacle or a support surface, drawn lowest top first (painter's order). */
        struct GroundItem
        {
            long long topKey;  // top height in HEIGHT_QUANTUM units, so equal heights compare equal
            bool isSurface;    // at equal height the surface (an obstacle's top) is drawn above it
            bool faint;        // an obstacle at or under the lowest surface (a floor slab)
            Footprint footprint;
            std::string name;
        };

        /** A goal marker with its label. */
        struct GoalMarker
        {
            Eigen::Vector2d at;
            std::string label;
            std::string colour;
        };

        /** The tool point's course along one labelled segment. */
        struct ToolSegment
        {
            PrimitiveKind kind;
            std::vector<Eigen::Vector2d> points;
        };

        /** Everything to draw, in world metres. */
        struct Picture
        {
            std::vector<GroundItem> ground;
            std::vector<Footprint> objectStart;
            std::vector<Footprint> objectEnd;  // empty without a path
            std::vector<GoalMarker> goals;
            std::vector<ToolSegment> segments;
            std::vector<Eigen::Vector2d> waypoints;
            std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> pushArrows;
            std::optional<Footprint> robotStart;
            std::optional<Footprint> robotEnd;
        };

        /** The canvas for a world box: a margin around it, at least a metre across, so a lone
            object is not blown up to the whole picture. */
        ompl_core::SvgCanvas fitCanvas(const Eigen::AlignedBox2d &box)
        {
            const Eigen::Vector2d half = (box.sizes() / 2.0).cwiseMax(0.5);
            const Eigen::Vector2d margin = Eigen::Vector2d::Constant(MARGIN_FRACTION * 2.0 * half.maxCoeff());
            return ompl_core::SvgCanvas(
                Eigen::AlignedBox2d(box.center() - half - margin, box.center() + half + margin), LAYOUT);
        }

        /** Footprint of an upright shape centred at (x, y) turned by yaw: a rectangle, or a circle
            (a mesh's: the circle about its z axis that holds it). */
        Footprint footprint(const Shape &shape, const Eigen::Vector2d &centre, double yaw)
        {
            Footprint f{{}, centre, shape.kind == Shape::Kind::Box ? 0.0 : shape.footprintRadius()};
            const Eigen::Rotation2Dd rotation(yaw);
            const Eigen::Vector2d half = shape.boxSize.head<2>() / 2.0;
            if (shape.kind == Shape::Kind::Box)
                for (const Eigen::Vector2d &sign : {Eigen::Vector2d(-1, -1), Eigen::Vector2d(1, -1),
                                                    Eigen::Vector2d(1, 1), Eigen::Vector2d(-1, 1)})
                    f.corners.push_back(centre + rotation * half.cwiseProduct(sign));
            return f;
        }

        /** An obstacle's footprint, using only its pose's rotation about z. */
        Footprint footprint(const Shape &shape, const Eigen::Isometry3d &pose)
        {
            return footprint(shape, pose.translation().head<2>(),
                             std::atan2(pose.linear()(1, 0), pose.linear()(0, 0)));
        }

        Footprint footprint(const Shape &shape, const ObjectPose &pose)
        {
            return footprint(shape, pose.position.head<2>(), pose.yaw);
        }

        /** World height of the highest point of a shape at a pose. */
        double topHeight(const Shape &shape, const Eigen::Isometry3d &pose)
        {
            const Eigen::Matrix3d &r = pose.linear();
            double reach = shape.kind == Shape::Kind::Mesh ? shape.boundingRadius() : shape.radius;
            if (shape.kind == Shape::Kind::Box)
                reach = (r.row(2).cwiseAbs().transpose().cwiseProduct(shape.boxSize / 2.0)).sum();
            else if (shape.kind == Shape::Kind::Cylinder)
                reach = std::abs(r(2, 2)) * shape.length / 2.0 +
                        shape.radius * std::sqrt(std::max(0.0, 1.0 - r(2, 2) * r(2, 2)));
            return pose.translation().z() + reach;
        }

        long long heightKey(double height)
        {
            return std::llround(height / HEIGHT_QUANTUM);
        }

        /** Obstacles and surfaces in painter's order; floor slabs are marked to be drawn faintly. */
        void addGround(const Scene &scene, Picture &picture)
        {
            long long lowestSurface = std::numeric_limits<long long>::max();
            for (const SupportSurface &s : scene.surfaces)
            {
                Footprint rectangle;
                rectangle.corners = {s.min, {s.max.x(), s.min.y()}, s.max, {s.min.x(), s.max.y()}};
                rectangle.centre = (s.min + s.max) / 2.0;
                lowestSurface = std::min(lowestSurface, heightKey(s.height));
                picture.ground.push_back({heightKey(s.height), true, false, rectangle, s.name});
            }
            for (const Obstacle &obstacle : scene.obstacles)
            {
                const long long top = heightKey(topHeight(obstacle.shape, obstacle.pose));
                picture.ground.push_back({top, false, top <= lowestSurface,
                                          footprint(obstacle.shape, obstacle.pose), obstacle.name});
            }
            std::stable_sort(
                picture.ground.begin(), picture.ground.end(),
                [](const GroundItem &a, const GroundItem &b)
                { return a.topKey != b.topKey ? a.topKey < b.topKey : !a.isSurface && b.isSurface; });
        }

        /** Circle of the tool link's first round shape, where the robot stands in this state. */
        std::optional<Footprint> robotFootprint(const ManipulationStateSpace &space,
                                                const ompl::base::State *state)
        {
            const ManipulationModel &model = *space.model();
            // a robot whose joints are all prismatic is drawn as the round shape of its tool link
            if (!model.robot().allJointsPrismatic())
                return std::nullopt;
            for (const LinkShape &linkShape : model.robot().links()[model.toolLink()].shapes)
            {
                if (linkShape.shape.kind == Shape::Kind::Box)
                    continue;
                const Eigen::Isometry3d link = model.robot().linkFrame(
                    space.robotValues(state), model.scene().robot.basePose, model.toolLink());
                return Footprint{
                    {}, (link * linkShape.origin).translation().head<2>(), linkShape.shape.footprintRadius()};
            }
            return std::nullopt;
        }

        void addGoals(const ManipulationSetup &setup, const ompl::base::State *start, Picture &picture)
        {
            const ManipulationStateSpace &space = *setup.manipulationSpace();
            const Scene &scene = space.model()->scene();
            for (const ObjectGoal &goal : scene.objectGoals)
            {
                if (!goal.position[0] || !goal.position[1])
                    continue;
                const int object = scene.objectIndex(goal.object);
                picture.goals.push_back({Eigen::Vector2d(*goal.position[0], *goal.position[1]),
                                         "goal " + goal.object,
                                         object < 0 ? ROBOT_COLOUR : objectColour(object)});
            }
            const std::vector<GoalCoordinate> &joints = scene.robotGoal.joints;
            const bool complete = joints.size() == space.robotDimension() &&
                                  std::all_of(joints.begin(), joints.end(),
                                              [](const GoalCoordinate &j) { return j.has_value(); });
            if (!space.model()->robot().allJointsPrismatic() || !complete)
                return;
            ompl::base::ScopedState<> goal(setup.getStateSpace());
            space.copyState(goal.get(), start);
            for (std::size_t j = 0; j < joints.size(); ++j)
                space.robotValues(goal.get())[j] = *joints[j];
            picture.goals.push_back({space.toolPosition(goal.get()).head<2>(), "goal robot", ROBOT_COLOUR});
        }

        /** Tool course (interpolated as the space moves the robot), waypoints and push arrows. */
        void addPath(const ManipulationSetup &setup, const ManipulationPath &path, Picture &picture)
        {
            const ManipulationStateSpace &space = *setup.manipulationSpace();
            ompl::base::ScopedState<> between(setup.getStateSpace());
            const std::vector<SegmentLabel> &labels = path.labels();  // checked once, not per waypoint
            for (std::size_t i = 0; i < path.getStateCount(); ++i)
            {
                picture.waypoints.push_back(space.toolPosition(path.getState(i)).head<2>());
                if (i + 1 == path.getStateCount() || i >= labels.size())
                    continue;
                const SegmentLabel &label = labels[i];
                ToolSegment segment{label.kind, {}};
                for (unsigned int k = 0; k <= SUB_STEPS; ++k)
                {
                    space.interpolate(path.getState(i), path.getState(i + 1),
                                      static_cast<double>(k) / SUB_STEPS, between.get());
                    segment.points.push_back(space.toolPosition(between.get()).head<2>());
                }
                picture.segments.push_back(std::move(segment));
                if (label.kind != PrimitiveKind::Push || label.object < 0 ||
                    label.object >= static_cast<int>(space.objectCount()))
                    continue;
                const Eigen::Vector2d from = space.objectPosition(path.getState(i), label.object).head<2>();
                const Eigen::Vector2d to = space.objectPosition(path.getState(i + 1), label.object).head<2>();
                // a push that did not move its object has no direction to show
                if ((to - from).norm() > 1e-6)
                    picture.pushArrows.emplace_back(from, to);
            }
        }

        Picture buildPicture(const ManipulationSetup &setup, const ManipulationPath *path)
        {
            const ompl::base::ProblemDefinitionPtr &pdef = setup.getProblemDefinition();
            if (pdef->getStartStateCount() == 0)
                throw ompl::Exception("writeSceneSvg", "the problem has no start state");
            const ompl::base::State *start = pdef->getStartState(0);
            const ManipulationStateSpace &space = *setup.manipulationSpace();
            const Scene &scene = space.model()->scene();
            const ompl::base::State *end = path != nullptr && path->getStateCount() > 0
                                               ? path->getState(path->getStateCount() - 1)
                                               : nullptr;

            Picture picture;
            addGround(scene, picture);
            for (unsigned int i = 0; i < space.objectCount(); ++i)
            {
                picture.objectStart.push_back(footprint(scene.objects[i].shape, space.objectPose(start, i)));
                if (end != nullptr)
                    picture.objectEnd.push_back(footprint(scene.objects[i].shape, space.objectPose(end, i)));
            }
            addGoals(setup, start, picture);
            picture.robotStart = robotFootprint(space, start);
            if (end != nullptr)
            {
                addPath(setup, *path, picture);
                picture.robotEnd = robotFootprint(space, end);
            }
            return picture;
        }

        void extend(Eigen::AlignedBox2d &box, const Footprint &f)
        {
            box.extend(f.centre - Eigen::Vector2d::Constant(f.radius));
            box.extend(f.centre + Eigen::Vector2d::Constant(f.radius));
            for (const Eigen::Vector2d &corner : f.corners)
                box.extend(corner);
        }

        /** The world box holding everything drawn (floor slabs included: they are drawn too). */
        Eigen::AlignedBox2d bounds(const Picture &picture)
        {
            Eigen::AlignedBox2d box;
            for (const GroundItem &item : picture.ground)
                extend(box, item.footprint);
            for (const std::vector<Footprint> *list : {&picture.objectStart, &picture.objectEnd})
                for (const Footprint &f : *list)
                    extend(box, f);
            for (const std::optional<Footprint> &robot : {picture.robotStart, picture.robotEnd})
                if (robot)
                    extend(box, *robot);
            for (const GoalMarker &goal : picture.goals)
                box.extend(goal.at);
            for (const ToolSegment &segment : picture.segments)
                for (const Eigen::Vector2d &p : segment.points)
                    box.extend(p);
            if (box.isEmpty())
                box.extend(Eigen::Vector2d::Zero());
            return box;
        }

        /** One element for a footprint: a circle or a polygon; attributes are written verbatim. */
        void writeFootprint(std::ostream &out, const ompl_core::SvgCanvas &canvas, const Footprint &f,
                            const std::string &attributes, const std::string &name)
        {
            const std::string title =
                name.empty() ? "" : "<title>" + ompl_core::xmlEscaped(name) + "</title>";
            if (f.corners.empty())
                ompl_core::SvgCanvas::writeCircle(out, canvas.map(f.centre), f.radius * canvas.scale(),
                                                  attributes, title);
            else
                out << "<polygon " << attributes << " points=\"" << canvas.pointList(f.corners) << "\">"
                    << title << "</polygon>\n";
        }

        /** Attributes of a dashed outline (a start pose). */
        std::string outlineStyle(const char *cls, const std::string &colour)
        {
            return std::string("class=\"") + cls + R"(" fill="none" stroke=")" + colour +
                   R"(" stroke-width="2" stroke-dasharray="6 4")";
        }

        /** Attributes of a filled footprint. */
        std::string fillStyle(const char *cls, const std::string &colour, const std::string &opacity)
        {
            return std::string("class=\"") + cls + R"(" fill=")" + colour + R"(" fill-opacity=")" + opacity +
                   R"(" stroke=")" + colour + R"(" stroke-width="1")";
        }

        void writeGround(std::ostream &out, const ompl_core::SvgCanvas &canvas, const Picture &picture)
        {
            // floor slabs are faint so the floor's outline and anything on it stay readable
            for (const GroundItem &item : picture.ground)
                writeFootprint(out, canvas, item.footprint,
                               item.isSurface
                                   ? fillStyle("surface", SURFACE_COLOUR, "1")
                                   : fillStyle("obstacle", OBSTACLE_COLOUR, item.faint ? "0.25" : "1"),
                               item.name);
        }

        void writeObjectsAndRobot(std::ostream &out, const ompl_core::SvgCanvas &canvas, const Scene &scene,
                                  const Picture &picture)
        {
            // the robot under the objects it touches; start outlines last, so fills never hide them
            if (picture.robotStart)
                writeFootprint(out, canvas, *picture.robotStart, outlineStyle("robot-start", ROBOT_COLOUR),
                               "robot");
            if (picture.robotEnd)
                writeFootprint(out, canvas, *picture.robotEnd, fillStyle("robot-end", ROBOT_COLOUR, "0.35"),
                               "robot");
            for (std::size_t i = 0; i < picture.objectEnd.size(); ++i)
                writeFootprint(out, canvas, picture.objectEnd[i],
                               fillStyle("object-end", objectColour(i), "0.85"), scene.objects[i].name);
            for (std::size_t i = 0; i < picture.objectStart.size(); ++i)
                writeFootprint(out, canvas, picture.objectStart[i],
                               outlineStyle("object-start", objectColour(i)), scene.objects[i].name);
        }

        void writePath(std::ostream &out, const ompl_core::SvgCanvas &canvas, const Picture &picture)
        {
            for (const ToolSegment &segment : picture.segments)
            {
                out << "<polyline class=\"tool-path\" fill=\"none\" stroke=\""
                    << primitiveColour(segment.kind)
                    << R"(" stroke-width="2.5" stroke-linecap="round" stroke-linejoin="round" points=")"
                    << canvas.pointList(segment.points) << "\"><title>" << primitiveKindName(segment.kind)
                    << "</title></polyline>\n";
            }
            for (const auto &[from, to] : picture.pushArrows)
                ompl_core::SvgCanvas::writeLine(out, canvas.map(from), canvas.map(to),
                                                std::string("class=\"push-arrow\" ") + ARROW_STYLE);
            for (const Eigen::Vector2d &waypoint : picture.waypoints)
                ompl_core::SvgCanvas::writeCircle(out, canvas.map(waypoint), 2.5,
                                                  R"(class="waypoint" fill="black")");
        }

        /** A ring with a cross, centred at c (pixels), over a white halo so it shows on any fill. */
        void writeGoalSymbol(std::ostream &out, const Eigen::Vector2d &c, const std::string &colour,
                             const char *cls)
        {
            const std::string shape =
                "<circle cx=\"" + ompl_core::SvgCanvas::number(c.x()) + "\" cy=\"" +
                ompl_core::SvgCanvas::number(c.y()) + "\" r=\"7\"/><path d=\"M" +
                ompl_core::SvgCanvas::number(c.x() - 10) + "," + ompl_core::SvgCanvas::number(c.y()) + " H" +
                ompl_core::SvgCanvas::number(c.x() + 10) + " M" + ompl_core::SvgCanvas::number(c.x()) + "," +
                ompl_core::SvgCanvas::number(c.y() - 10) + " V" + ompl_core::SvgCanvas::number(c.y() + 10) +
                "\"/>";
            out << "<g class=\"" << cls << "\" fill=\"none\"><g stroke=\"white\" stroke-width=\"4\">" << shape
                << "</g><g stroke=\"" << colour << "\" stroke-width=\"2\">" << shape << "</g></g>\n";
        }

        /** Where a footprint's label goes: just above it, so the path and arrows inside stay visible. */
        Eigen::Vector2d labelAnchor(const ompl_core::SvgCanvas &canvas, const Footprint &f)
        {
            double halfHeight = f.radius;
            for (const Eigen::Vector2d &corner : f.corners)
                halfHeight = std::max(halfHeight, std::abs(corner.y() - f.centre.y()));
            return canvas.map(f.centre) - Eigen::Vector2d(0.0, halfHeight * canvas.scale() + 5.0);
        }

        void writeLabels(std::ostream &out, const ompl_core::SvgCanvas &canvas, const Scene &scene,
                         const Picture &picture)
        {
            const std::string style =
                "class=\"label\" font-size=\"12\" text-anchor=\"middle\" stroke=\"white\" stroke-width=\"3\" "
                "paint-order=\"stroke\" fill=\"black\"";
            for (const GoalMarker &goal : picture.goals)
            {
                writeGoalSymbol(out, canvas.map(goal.at), goal.colour, "goal");
                ompl_core::SvgCanvas::writeText(out, canvas.map(goal.at) + Eigen::Vector2d(0.0, 24.0),
                                                goal.label, style);
            }
            // an object that moved is named at both places, unless the two names would overlap
            for (std::size_t i = 0; i < picture.objectStart.size(); ++i)
            {
                const Eigen::Vector2d start = labelAnchor(canvas, picture.objectStart[i]);
                bool nameStart = true;
                if (i < picture.objectEnd.size())
                {
                    const Eigen::Vector2d end = labelAnchor(canvas, picture.objectEnd[i]);
                    ompl_core::SvgCanvas::writeText(out, end, scene.objects[i].name, style);
                    nameStart = std::abs(end.x() - start.x()) > 40.0 || std::abs(end.y() - start.y()) > 14.0;
                }
                if (nameStart)
                    ompl_core::SvgCanvas::writeText(out, start, scene.objects[i].name, style);
            }
            if (picture.robotStart)
                ompl_core::SvgCanvas::writeText(out, labelAnchor(canvas, *picture.robotStart), "robot",
                                                style);
        }

        /** Largest power of ten at most a quarter of the width (1 m for room-sized scenes). */
        double scaleBarLength(double metresAcross)
        {
            return std::pow(10.0, std::floor(std::log10(metresAcross / 4.0)));
        }

        void writeTitleAndScale(std::ostream &out, const ompl_core::SvgCanvas &canvas, const Scene &scene,
                                const ManipulationPath *path)
        {
            std::string title = "scene " + (scene.name.empty() ? std::string("(unnamed)") : scene.name);
            if (path != nullptr)
                title +=
                    ": " + std::to_string(path->getStateCount()) + " waypoints, tool path " +
                    ompl_core::SvgCanvas::number(path->getStateCount() > 0 ? path->toolPathLength() : 0.0) +
                    " m";
            ompl_core::SvgCanvas::writeText(out, {12.0, 21.0}, title,
                                            "class=\"title\" font-size=\"15\" font-weight=\"bold\"");

            const double metres = scaleBarLength(LAYOUT.widthPx / canvas.scale());
            const double length = metres * canvas.scale();
            const double right = LAYOUT.widthPx - 12.0;
            out << "<path class=\"scale-bar\" d=\"M" << ompl_core::SvgCanvas::number(right - length)
                << ",12.00 V20.00 H" << ompl_core::SvgCanvas::number(right)
                << " V12.00\" fill=\"none\" stroke=\"black\" stroke-width=\"1.5\"/>\n";
            std::ostringstream label;
            label.imbue(std::locale::classic());
            label << metres << " m";
            ompl_core::SvgCanvas::writeText(out, {right - length - 6.0, 21.0}, label.str(),
                                            "class=\"scale-label\" font-size=\"12\" text-anchor=\"end\"");
        }

        void writeLegend(std::ostream &out, const ompl_core::SvgCanvas &canvas)
        {
            const double y = canvas.height() - LAYOUT.legendPx / 2.0;
            double x = 16.0;
            const std::string text = "class=\"legend\" font-size=\"12\"";
            for (PrimitiveKind kind : {PrimitiveKind::Transit, PrimitiveKind::Push, PrimitiveKind::Pickup,
                                       PrimitiveKind::Transfer})
            {
                ompl_core::SvgCanvas::writeLine(
                    out, {x, y}, {x + 24, y},
                    std::string("stroke=\"") + primitiveColour(kind) + "\" stroke-width=\"2.5\"");
                ompl_core::SvgCanvas::writeText(out, {x + 30, y + 4}, primitiveKindName(kind), text);
                x += 100.0;
            }
            ompl_core::SvgCanvas::writeCircle(
                out, {x + 8, y}, 7.0,
                R"(fill="none" stroke="black" stroke-width="1.5" stroke-dasharray="4 3")");
            ompl_core::SvgCanvas::writeText(out, {x + 22, y + 4}, "start", text);
            x += 80.0;
            ompl_core::SvgCanvas::writeCircle(out, {x + 8, y}, 7.0, R"(fill="#777777")");
            ompl_core::SvgCanvas::writeText(out, {x + 22, y + 4}, "end", text);
            x += 70.0;
            writeGoalSymbol(out, {x + 8, y}, "black", "legend");
            ompl_core::SvgCanvas::writeText(out, {x + 24, y + 4}, "goal", text);
            x += 70.0;
            ompl_core::SvgCanvas::writeLine(out, {x, y}, {x + 28, y}, ARROW_STYLE);
            ompl_core::SvgCanvas::writeText(out, {x + 34, y + 4}, "pushed object", text);
        }
    }  // namespace

    void writeSceneSvg(std::ostream &out, const ManipulationSetup &setup, const ManipulationPath *path)
    {
        const Scene &scene = setup.model()->scene();
        const Picture picture = buildPicture(setup, path);
        const ompl_core::SvgCanvas canvas = fitCanvas(bounds(picture));
        canvas.writeHeader(
            out, std::string(R"(<marker id="arrowhead" viewBox="0 0 10 10" refX="9" refY="5" )") +
                     R"(markerWidth="5" markerHeight="5" orient="auto"><path d="M0,0 L10,5 L0,10 z" fill=")" +
                     ARROW_COLOUR + "\"/></marker>");
        writeGround(out, canvas, picture);
        writeObjectsAndRobot(out, canvas, scene, picture);
        writePath(out, canvas, picture);
        writeLabels(out, canvas, scene, picture);
        writeTitleAndScale(out, canvas, scene, path);
        writeLegend(out, canvas);
        ompl_core::SvgCanvas::writeFooter(out);
    }
}  // namespace ompl_mm
