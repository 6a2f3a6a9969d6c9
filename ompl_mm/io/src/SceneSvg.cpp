#include "ompl_mm/io/SceneSvg.h"

#include "ompl_mm/io/ScenePicture.h"

#include "ompl_core/io/SvgCanvas.h"
#include "ompl_core/io/TextFormat.h"
#include "ompl_mm/io/LabelLayout.h"
#include "ompl_mm/io/PlanColours.h"

#include <ompl/base/ScopedState.h>
#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
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
        // an arm's picture: the top and side views together this wide, a second title row holding
        // each view's caption and scale bar
        const ompl_core::SvgCanvas::Layout TWO_VIEW_LAYOUT{1400.0, 56.0, 36.0};
        constexpr double TITLE_Y = 21.0;    // baseline of the title row, pixels
        constexpr double CAPTION_Y = 46.0;  // baseline of the captions' row, pixels

        const char *const ARROW_COLOUR = "#8b0000";
        const std::string ARROW_STYLE = std::string("stroke=\"") + ARROW_COLOUR +
                                        R"svg(" stroke-width="2" marker-end="url(#arrowhead)")svg";

        using namespace picture;

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
            // a surface seen edge-on: a light band along the top of the obstacle under it
            for (const SurfaceLine &line : picture.surfaceLines)
                canvas.writePolyline(out, {line.from, line.to},
                                     std::string(R"(class="surface" fill="none" stroke=")") + SURFACE_COLOUR +
                                         R"(" stroke-width="3")",
                                     "<title>" + ompl_core::xmlEscaped(line.name) + "</title>");
        }

        /** "#rrggbb" of a grey, level 0 (black) to 1 (white). */
        std::string grey(double level)
        {
            char text[8];
            const int byte = static_cast<int>(std::lround(255.0 * std::clamp(level, 0.0, 1.0)));
            std::snprintf(text, sizeof text, "#%02x%02x%02x", byte, byte, byte);
            return text;
        }

        /** Attributes of the arm at fraction t of its poses (0 the first, 1 the last): faint and light
            to opaque and dark, as onion skins (the group's opacity, so a pose's own links do not add up). */
        std::string armPoseStyle(double t)
        {
            return "opacity=\"" + ompl_core::SvgCanvas::number(0.3 + 0.7 * t) + "\" fill=\"" +
                   grey(0.88 - 0.39 * t) + "\" stroke=\"" + grey(0.47 - 0.35 * t) + "\" stroke-width=\"1\"";
        }

        /** Each arm pose as a group of its links' outlines, in the path's order. */
        void writeArmPoses(std::ostream &out, const ompl_core::SvgCanvas &canvas, const Picture &picture)
        {
            const std::size_t n = picture.armPoses.size();
            for (std::size_t i = 0; i < n; ++i)
            {
                const double t = n > 1 ? static_cast<double>(i) / static_cast<double>(n - 1) : 1.0;
                out << "<g class=\"arm-pose\" " << armPoseStyle(t) << "><title>"
                    << ompl_core::xmlEscaped(picture.armPoses[i].caption) << "</title>\n";
                for (const Footprint &link : picture.armPoses[i].links)
                    writeFootprint(out, canvas, link, "class=\"arm-link\"", "");
                out << "</g>\n";
            }
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
            // a carried object's centre stays near the tool point: its course is a thin core of the tool's
            for (const ToolSegment &course : picture.carried)
                canvas.writePolyline(
                    out, course.points,
                    std::string(R"(class="carried-path" fill="none" stroke=")") +
                        objectColour(course.object) +
                        R"(" stroke-width="1" stroke-linecap="round" stroke-linejoin="round")");
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

        /** Font size of the labels, pixels. */
        constexpr double LABEL_FONT = 12.0;
        /** Half the size of a goal symbol, pixels. */
        constexpr double GOAL_SYMBOL_HALF = 10.0;

        /** A footprint's pixel box. */
        Eigen::AlignedBox2d pixelBox(const ompl_core::SvgCanvas &canvas, const Footprint &f)
        {
            Eigen::AlignedBox2d box;
            const Eigen::Vector2d reach = Eigen::Vector2d::Constant(f.radius * canvas.scale());
            box.extend(canvas.map(f.centre) - reach).extend(canvas.map(f.centre) + reach);
            for (const Eigen::Vector2d &corner : f.corners)
                box.extend(canvas.map(corner));
            return box;
        }

        /** The goals' symbols, then the labels, placed by a LabelLayout inside area (pixels) so that
            none covers another or a goal symbol: the goals' names under their symbols, the
            objects' names over them where they end, then where they start (when they moved), then
            the mobile robot's; a label with no free place nearby is left out. */
        void writeLabels(std::ostream &out, const ompl_core::SvgCanvas &canvas, const Scene &scene,
                         const Picture &picture, const Eigen::AlignedBox2d &area)
        {
            const std::string style =
                "class=\"label\" font-size=\"12\" text-anchor=\"middle\" stroke=\"white\" stroke-width=\"3\" "
                "paint-order=\"stroke\" fill=\"black\"";
            LabelLayout layout(area, LABEL_FONT);
            const Eigen::Vector2d symbolHalf = Eigen::Vector2d::Constant(GOAL_SYMBOL_HALF);
            for (const GoalMarker &goal : picture.goals)
            {
                writeGoalSymbol(out, canvas.map(goal.at), goal.colour, "goal");
                layout.keepFree(
                    Eigen::AlignedBox2d(canvas.map(goal.at) - symbolHalf, canvas.map(goal.at) + symbolHalf));
            }
            const auto label =
                [&](const std::string &text, const Eigen::AlignedBox2d &target, LabelLayout::Side side)
            {
                if (const std::optional<Eigen::Vector2d> at = layout.place(text, target, side))
                    ompl_core::SvgCanvas::writeText(out, *at, text, style);
            };
            for (const GoalMarker &goal : picture.goals)
                label(goal.label,
                      Eigen::AlignedBox2d(canvas.map(goal.at) - symbolHalf, canvas.map(goal.at) + symbolHalf),
                      LabelLayout::Side::Below);
            for (std::size_t i = 0; i < picture.objectEnd.size(); ++i)
                label(scene.objects[i].name, pixelBox(canvas, picture.objectEnd[i]),
                      LabelLayout::Side::Above);
            for (std::size_t i = 0; i < picture.objectStart.size(); ++i)
            {
                // an object that stayed where it was is named once
                const bool moved =
                    i >= picture.objectEnd.size() ||
                    (canvas.map(picture.objectEnd[i].centre) - canvas.map(picture.objectStart[i].centre))
                            .norm() > 1.0;
                if (moved)
                    label(scene.objects[i].name, pixelBox(canvas, picture.objectStart[i]),
                          LabelLayout::Side::Above);
            }
            if (picture.robotStart)
                label("robot", pixelBox(canvas, *picture.robotStart), LabelLayout::Side::Above);
        }

        /** The drawing band of a canvas, between its title and legend strips, pixels. */
        Eigen::AlignedBox2d drawingBand(const ompl_core::SvgCanvas &canvas)
        {
            return Eigen::AlignedBox2d(
                Eigen::Vector2d(0.0, canvas.layout().titlePx),
                Eigen::Vector2d(canvas.width(), canvas.height() - canvas.layout().legendPx));
        }

        /** Largest power of ten at most a quarter of the width (1 m for room-sized scenes). */
        double scaleBarLength(double metresAcross)
        {
            return std::pow(10.0, std::floor(std::log10(metresAcross / 4.0)));
        }

        void writeTitle(std::ostream &out, const Scene &scene, const ManipulationPath *path)
        {
            std::string title = "scene " + (scene.name.empty() ? std::string("(unnamed)") : scene.name);
            if (path != nullptr)
                title +=
                    ": " + std::to_string(path->getStateCount()) + " waypoints, tool path " +
                    ompl_core::SvgCanvas::number(path->getStateCount() > 0 ? path->toolPathLength() : 0.0) +
                    " m";
            ompl_core::SvgCanvas::writeText(out, {12.0, TITLE_Y}, title,
                                            "class=\"title\" font-size=\"15\" font-weight=\"bold\"");
        }

        /** A view's caption (none when empty) at its left and its scale bar at its right, on the row
            whose baseline is y pixels. */
        void writeCaptionAndScale(std::ostream &out, const ompl_core::SvgCanvas &canvas,
                                  const std::string &caption, double y)
        {
            if (!caption.empty())
                ompl_core::SvgCanvas::writeText(out, {12.0, y}, caption,
                                                "class=\"caption\" font-size=\"13\" fill=\"#444444\"");
            const double metres = scaleBarLength(canvas.width() / canvas.scale());
            const double length = metres * canvas.scale();
            const double right = canvas.width() - 12.0;
            out << "<path class=\"scale-bar\" d=\"M" << ompl_core::SvgCanvas::number(right - length) << ","
                << ompl_core::SvgCanvas::number(y - 9.0) << " V" << ompl_core::SvgCanvas::number(y - 1.0)
                << " H" << ompl_core::SvgCanvas::number(right) << " V"
                << ompl_core::SvgCanvas::number(y - 9.0)
                << "\" fill=\"none\" stroke=\"black\" stroke-width=\"1.5\"/>\n";
            std::ostringstream label;
            label.imbue(std::locale::classic());
            label << metres << " m";
            ompl_core::SvgCanvas::writeText(out, {right - length - 6.0, y}, label.str(),
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

        /** The legend's entry for the arm's poses, right of writeLegend()'s entries (which end
            before x 790). */
        void writeArmLegend(std::ostream &out, const ompl_core::SvgCanvas &canvas)
        {
            const double y = canvas.height() - TWO_VIEW_LAYOUT.legendPx / 2.0;
            const double x = 790.0;
            for (int k = 0; k < 3; ++k)
                out << "<rect class=\"legend\" x=\"" << ompl_core::SvgCanvas::number(x + 9.0 * k) << "\" y=\""
                    << ompl_core::SvgCanvas::number(y - 7.0) << "\" width=\"12\" height=\"14\" "
                    << armPoseStyle(k / 2.0) << "/>\n";
            ompl_core::SvgCanvas::writeText(out, {x + 38.0, y + 4.0}, "arm at the start, mode switches, end",
                                            "class=\"legend\" font-size=\"12\"");
        }

        /** The arrowhead of the push arrows, for the picture's defs. */
        std::string arrowDefs()
        {
            return std::string(R"(<marker id="arrowhead" viewBox="0 0 10 10" refX="9" refY="5" )") +
                   R"(markerWidth="5" markerHeight="5" orient="auto"><path d="M0,0 L10,5 L0,10 z" fill=")" +
                   ARROW_COLOUR + "\"/></marker>";
        }

        /** One view's drawing, in painter's order, without labels. */
        void writeView(std::ostream &out, const ompl_core::SvgCanvas &canvas, const Scene &scene,
                       const Picture &picture)
        {
            writeGround(out, canvas, picture);
            writeArmPoses(out, canvas, picture);
            writeObjectsAndRobot(out, canvas, scene, picture);
            writePath(out, canvas, picture);
        }

        /** The top view alone, LAYOUT wide (a mobile robot's picture). */
        void writeTopView(std::ostream &out, const Scene &scene, const Picture &top,
                          const ManipulationPath *path)
        {
            const ompl_core::SvgCanvas canvas(padded(bounds(top)), LAYOUT);
            canvas.writeHeader(out, arrowDefs());
            writeView(out, canvas, scene, top);
            writeLabels(out, canvas, scene, top, drawingBand(canvas));
            writeTitle(out, scene, path);
            writeCaptionAndScale(out, canvas, "", TITLE_Y);
            writeLegend(out, canvas);
            ompl_core::SvgCanvas::writeFooter(out);
        }

        /** The canvas of a view of the world box (padded) whose drawing band is band pixels high. */
        ompl_core::SvgCanvas viewCanvas(const Eigen::AlignedBox2d &world, double band)
        {
            ompl_core::SvgCanvas::Layout layout = TWO_VIEW_LAYOUT;
            layout.widthPx = band * world.sizes().x() / world.sizes().y();
            return ompl_core::SvgCanvas(world, layout);
        }

        /** The top and the side view side by side, each at the scale that fits it into a common
            height, TWO_VIEW_LAYOUT wide together (an arm's picture). */
        void writeTwoViews(std::ostream &out, const Scene &scene, const Picture &top, const Picture &side,
                           const ManipulationPath *path)
        {
            const Eigen::AlignedBox2d topWorld = padded(bounds(top));
            const Eigen::AlignedBox2d sideWorld = padded(bounds(side));
            const double band = TWO_VIEW_LAYOUT.widthPx / (topWorld.sizes().x() / topWorld.sizes().y() +
                                                           sideWorld.sizes().x() / sideWorld.sizes().y());
            const ompl_core::SvgCanvas topCanvas = viewCanvas(topWorld, band);
            const ompl_core::SvgCanvas sideCanvas = viewCanvas(sideWorld, band);
            // the whole picture, one pixel a unit, for the header and the legend
            const ompl_core::SvgCanvas whole(
                Eigen::AlignedBox2d(Eigen::Vector2d::Zero(), Eigen::Vector2d(TWO_VIEW_LAYOUT.widthPx, band)),
                TWO_VIEW_LAYOUT);
            whole.writeHeader(out, arrowDefs());
            out << "<g class=\"top-view\">\n";
            writeView(out, topCanvas, scene, top);
            writeLabels(out, topCanvas, scene, top, drawingBand(topCanvas));
            writeCaptionAndScale(out, topCanvas, "top view (x\u2013y)", CAPTION_Y);
            out << "</g>\n<g class=\"side-view\" transform=\"translate("
                << ompl_core::SvgCanvas::number(topCanvas.width()) << ",0)\">\n";
            ompl_core::SvgCanvas::writeLine(out, {0.0, TWO_VIEW_LAYOUT.titlePx - 20.0},
                                            {0.0, whole.height() - TWO_VIEW_LAYOUT.legendPx},
                                            R"(class="view-separator" stroke="#cccccc" stroke-width="1")");
            writeView(out, sideCanvas, scene, side);  // the objects' colours name them here
            writeCaptionAndScale(out, sideCanvas, "side view (x\u2013z)", CAPTION_Y);
            out << "</g>\n";
            writeTitle(out, scene, path);
            writeLegend(out, whole);
            writeArmLegend(out, whole);
            ompl_core::SvgCanvas::writeFooter(out);
        }
    }  // namespace

    void writeSceneSvg(std::ostream &out, const ManipulationSetup &setup, const ManipulationPath *path)
    {
        const Scene &scene = setup.model()->scene();
        const Picture top = topPicture(setup, path);
        // a mobile robot is seen whole from above; an arm also needs the height it works at
        if (setup.model()->robot().allJointsPrismatic())
            writeTopView(out, scene, top, path);
        else
            writeTwoViews(out, scene, top, sidePicture(setup, path), path);
    }
}  // namespace ompl_mm
