#include "ompl_phys/io/PhysicsSceneSvg.h"

#include "ompl_phys/io/PhysicsColours.h"

#include "ompl_core/io/SvgCanvas.h"
#include "ompl_phys/knowledge/Footprint.h"

#include <cmath>
#include <vector>

namespace ompl_phys
{
    namespace
    {
        const ompl_core::SvgCanvas::Layout LAYOUT{700.0, 30.0, 30.0};
        constexpr double MARGIN_M = 0.1;
        constexpr double CIRCLE_SEGMENTS = 32;
        /** A body whose centre moved less than this is not drawn as pushed, m. */
        constexpr double MOVED_THRESHOLD = 0.01;

        /** The outline of a shape at (position, yaw) as floor points. */
        std::vector<Eigen::Vector2d> outline(const PhysicsShape &shape, const Eigen::Vector2d &position,
                                             double yaw)
        {
            std::vector<Eigen::Vector2d> local;
            switch (shape.kind)
            {
                case PhysicsShape::Kind::Box:
                {
                    const Eigen::Vector2d h = 0.5 * shape.boxSize.head<2>();
                    local = {{-h.x(), -h.y()}, {h.x(), -h.y()}, {h.x(), h.y()}, {-h.x(), h.y()}};
                    break;
                }
                case PhysicsShape::Kind::Prism:
                    for (int i = 0; i < 3; ++i)
                        local.push_back(shape.triangle.col(i));
                    break;
                case PhysicsShape::Kind::Cylinder:
                case PhysicsShape::Kind::Sphere:
                    for (int i = 0; i < CIRCLE_SEGMENTS; ++i)
                    {
                        const double a = 2.0 * M_PI * i / CIRCLE_SEGMENTS;
                        local.push_back(shape.radius * Eigen::Vector2d(std::cos(a), std::sin(a)));
                    }
                    break;
            }
            std::vector<Eigen::Vector2d> world;
            for (const Eigen::Vector2d &p : local)
                world.push_back(position + Eigen::Rotation2Dd(yaw) * p);
            return world;
        }

        void polyline(std::ostream &out, const ompl_core::SvgCanvas &canvas,
                      const std::vector<Eigen::Vector2d> &points, const std::string &style)
        {
            canvas.writePolyline(out, points, "fill=\"none\" " + style);
        }

        void circle(std::ostream &out, const ompl_core::SvgCanvas &canvas, const Eigen::Vector2d &centre,
                    double radius, const std::string &style)
        {
            ompl_core::SvgCanvas::writeCircle(out, canvas.map(centre), radius * canvas.scale(), style);
        }

        Eigen::AlignedBox2d drawingArea(const PhysicsScene &scene)
        {
            Eigen::AlignedBox2d area = scene.limits.robotRegion;
            area.extend(scene.limits.bodyRegion);
            area.extend(Eigen::Vector2d(0.5 * scene.floorSize));
            area.extend(Eigen::Vector2d(-0.5 * scene.floorSize));
            for (const PhysicsBody &body : scene.bodies)
                for (const Eigen::Vector2d &p : outline(body.shape, body.start.translation().head<2>(),
                                                        yawOf(Eigen::Quaterniond(body.start.linear()))))
                    area.extend(p);
            return Eigen::AlignedBox2d(area.min() - Eigen::Vector2d::Constant(MARGIN_M),
                                       area.max() + Eigen::Vector2d::Constant(MARGIN_M));
        }

        void drawBody(std::ostream &out, const ompl_core::SvgCanvas &canvas, const PhysicsBody &body,
                      const BodyState &state, const std::string &style)
        {
            const double yaw = yawOf(state.orientation);
            canvas.writePolygon(out, outline(body.shape, state.position.head<2>(), yaw), style);
            if (body.kind != BodyKind::Constrained)
                return;
            const Eigen::Vector2d axis = (state.orientation * body.push.axis).head<2>().normalized();
            const double half = body.shape.boundingRadius();
            polyline(out, canvas,
                     {state.position.head<2>() - half * axis, state.position.head<2>() + half * axis},
                     "stroke=\"#000000\" stroke-width=\"1\" stroke-dasharray=\"3,2\"");
        }
    }  // namespace

    void writePhysicsSceneSvg(std::ostream &out, const PhysicsSetup &setup, const SimulatedPath *simulated,
                              const std::string &title)
    {
        const PhysicsScene &scene = setup.scene();
        const PhysicsWorld &world = setup.world();
        const ompl_core::SvgCanvas canvas(drawingArea(scene), LAYOUT);
        canvas.writeHeader(out, "");
        ompl_core::SvgCanvas::writeText(out, {8.0, 20.0}, title, "font-size=\"14\"");
        const Eigen::Vector2d floorHalf = 0.5 * scene.floorSize;
        if (scene.floorSize.x() > 0.0)
            canvas.writePolygon(out,
                                {{-floorHalf.x(), -floorHalf.y()},
                                 {floorHalf.x(), -floorHalf.y()},
                                 floorHalf,
                                 {-floorHalf.x(), floorHalf.y()}},
                                std::string("fill=\"") + FLOOR_COLOUR + "\" stroke=\"#cccccc\"");
        circle(
            out, canvas, scene.goal.centre, scene.goal.radius,
            std::string("fill=\"") + GOAL_COLOUR + "\" fill-opacity=\"0.3\" stroke=\"" + GOAL_COLOUR + "\"");
        for (const PhysicsBody &body : scene.bodies)
            if (body.kind == BodyKind::Fixed)
            {
                BodyState fixed;
                fixed.position = body.start.translation();
                fixed.orientation = Eigen::Quaterniond(body.start.linear());
                drawBody(out, canvas, body, fixed, std::string("fill=\"") + FIXED_COLOUR + "\"");
            }

        const BodyStates start = world.startStates();
        const BodyStates &end = simulated && !simulated->states.empty() ? simulated->states.back() : start;
        for (std::size_t i = 1; i < world.movingBodyCount(); ++i)
        {
            const PhysicsBody &body = scene.bodies[world.sceneBodyOf(i)];
            const std::string colour = bodyColour(i - 1);
            drawBody(out, canvas, body, start[i],
                     "fill=\"none\" stroke=\"" + colour + "\" stroke-width=\"2\" stroke-dasharray=\"5,3\"");
            drawBody(out, canvas, body, end[i],
                     "fill=\"" + colour + "\" fill-opacity=\"0.7\" stroke=\"" + colour + "\"");
            if (simulated && (end[i].position - start[i].position).norm() > MOVED_THRESHOLD)
            {
                std::vector<Eigen::Vector2d> track;
                for (const BodyStates &states : simulated->states)
                    track.push_back(states[i].position.head<2>());
                polyline(out, canvas, track, "stroke=\"" + colour + "\" stroke-width=\"2\"");
            }
        }
        if (simulated)
        {
            std::vector<Eigen::Vector2d> track;
            for (const Eigen::Vector3d &p : simulated->robot.positions)
                track.push_back(p.head<2>());
            polyline(out, canvas, track, std::string("stroke=\"") + ROBOT_COLOUR + "\" stroke-width=\"2\"");
        }
        circle(out, canvas, start[0].position.head<2>(), scene.robot.radius,
               std::string("fill=\"none\" stroke=\"") + ROBOT_COLOUR + "\" stroke-width=\"2\"");
        circle(out, canvas, end[0].position.head<2>(), scene.robot.radius,
               std::string("fill=\"") + ROBOT_COLOUR + "\"");
        ompl_core::SvgCanvas::writeText(
            out, {8.0, canvas.height() - 10.0},
            "grey: fixed · dashed: start · filled: end · blue: robot path · green: goal", "font-size=\"14\"");
        ompl_core::SvgCanvas::writeFooter(out);
    }
}  // namespace ompl_phys
