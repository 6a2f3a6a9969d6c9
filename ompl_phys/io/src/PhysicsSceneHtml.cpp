#include "ompl_phys/io/PhysicsSceneHtml.h"

#include "ompl_phys/io/PhysicsColours.h"

#include <algorithm>

namespace ompl_phys
{
    namespace
    {
        /** A body whose centre moved less than this in one step is not being pushed, m. */
        constexpr double MOVING_THRESHOLD = 1e-4;
        /** The floor is drawn as a slab this thick under z = 0, m. */
        constexpr double FLOOR_THICKNESS = 0.01;
        /** The goal disc's height, m. */
        constexpr double GOAL_HEIGHT = 0.004;
        /** Opacity of the goal disc. */
        constexpr double GOAL_OPACITY = 0.45;

        ompl_core::ViewerSolid solidOf(const PhysicsShape &shape)
        {
            ompl_core::ViewerSolid solid;
            switch (shape.kind)
            {
                case PhysicsShape::Kind::Box:
                    solid.size = shape.boxSize;
                    break;
                case PhysicsShape::Kind::Cylinder:
                    solid.kind = ompl_core::ViewerSolid::Kind::Cylinder;
                    solid.radius = shape.radius;
                    solid.length = shape.length;
                    break;
                case PhysicsShape::Kind::Sphere:
                    solid.kind = ompl_core::ViewerSolid::Kind::Sphere;
                    solid.radius = shape.radius;
                    break;
                case PhysicsShape::Kind::Prism:
                {
                    // the triangle at the bottom and the top, then its faces (outward for any winding:
                    // the viewer's material draws both sides)
                    solid.kind = ompl_core::ViewerSolid::Kind::Mesh;
                    for (const double z : {-shape.length / 2, shape.length / 2})
                        for (int c = 0; c < 3; ++c)
                            solid.vertices.emplace_back(shape.triangle(0, c), shape.triangle(1, c), z);
                    solid.triangles = {{0, 2, 1}, {3, 4, 5}};
                    for (int c = 0; c < 3; ++c)
                    {
                        const int d = (c + 1) % 3;
                        solid.triangles.push_back({c, d, 3 + d});
                        solid.triangles.push_back({c, 3 + d, 3 + c});
                    }
                    break;
                }
            }
            return solid;
        }

        Eigen::Isometry3d poseOf(const BodyState &state)
        {
            return Eigen::Translation3d(state.position) * state.orientation;
        }

        /** What the robot does between two states: "transit", or "push" and the bodies that move. */
        std::string actionBetween(const PhysicsSetup &setup, const BodyStates &from, const BodyStates &to)
        {
            std::string pushed;
            for (std::size_t b = 1; b < from.size(); ++b)
                if ((to[b].position - from[b].position).norm() > MOVING_THRESHOLD)
                    pushed += (pushed.empty() ? " " : ", ") + setup.world().movingBodyName(b);
            return pushed.empty() ? "transit" : "push" + pushed;
        }
    }  // namespace

    ompl_core::ViewerPlan physicsViewerPlan(const PhysicsSetup &setup, const SimulatedPath *simulated,
                                            const std::string &title)
    {
        const PhysicsScene &scene = setup.scene();
        ompl_core::ViewerPlan plan;
        plan.title = title;
        if (scene.floorSize.x() > 0.0)
        {
            ompl_core::ViewerSolid floor;
            floor.size = Eigen::Vector3d(scene.floorSize.x(), scene.floorSize.y(), FLOOR_THICKNESS);
            floor.pose = Eigen::Translation3d(0.0, 0.0, -FLOOR_THICKNESS / 2);
            plan.fixed.push_back({"floor", FLOOR_COLOUR, 1.0, {floor}});
        }
        for (const PhysicsBody &body : scene.bodies)
            if (body.kind == BodyKind::Fixed)
            {
                ompl_core::ViewerSolid solid = solidOf(body.shape);
                solid.pose = body.start;
                plan.fixed.push_back({body.name, FIXED_COLOUR, 1.0, {solid}});
            }
        ompl_core::ViewerSolid disc;
        disc.kind = ompl_core::ViewerSolid::Kind::Cylinder;
        disc.radius = scene.goal.radius;
        disc.length = GOAL_HEIGHT;
        disc.pose = Eigen::Translation3d(scene.goal.centre.x(), scene.goal.centre.y(), GOAL_HEIGHT / 2);
        plan.goals.push_back({"goal", GOAL_COLOUR, GOAL_OPACITY, {disc}});

        const PhysicsWorld &world = setup.world();
        ompl_core::ViewerSolid sphere;
        sphere.kind = ompl_core::ViewerSolid::Kind::Sphere;
        sphere.radius = scene.robot.radius;
        plan.moving.push_back({scene.robot.name, ROBOT_COLOUR, 1.0, {sphere}});
        plan.legend.push_back({scene.robot.name, ROBOT_COLOUR});
        for (std::size_t b = 1; b < world.movingBodyCount(); ++b)
        {
            plan.moving.push_back({world.movingBodyName(b),
                                   bodyColour(b - 1),
                                   1.0,
                                   {solidOf(scene.bodies[world.sceneBodyOf(b)].shape)}});
            plan.legend.push_back({world.movingBodyName(b), bodyColour(b - 1)});
            plan.tracks.push_back(b);
        }
        plan.legend.push_back({"fixed body", FIXED_COLOUR});
        plan.legend.push_back({"goal", GOAL_COLOUR});

        const std::vector<BodyStates> states = simulated && !simulated->states.empty()
                                                   ? simulated->states
                                                   : std::vector<BodyStates>{world.startStates()};
        if (simulated && simulated->robot.stepDuration > 0.0)
            plan.frameStep = simulated->robot.stepDuration;
        for (std::size_t k = 0; k < states.size(); ++k)
        {
            std::vector<Eigen::Isometry3d> poses;
            for (const BodyState &state : states[k])
                poses.push_back(poseOf(state));
            plan.frames.push_back(poses);
            plan.toolPath.push_back(states[k][0].position);
            if (k + 1 == states.size())
                break;
            const std::string action = actionBetween(setup, states[k], states[k + 1]);
            if (!plan.segments.empty())
                plan.segments.back().last = k;
            if (plan.segments.empty() || plan.segments.back().label != action)
                plan.segments.push_back({k, k, action, action == "transit" ? TRANSIT_COLOUR : PUSH_COLOUR});
        }
        if (!plan.segments.empty())
        {
            plan.segments.back().last = states.size() - 1;
            plan.legend.push_back({"robot moves alone", TRANSIT_COLOUR});
            plan.legend.push_back({"robot pushes", PUSH_COLOUR});
        }
        return plan;
    }

    void writePhysicsSceneHtml(std::ostream &out, const PhysicsSetup &setup, const SimulatedPath *simulated,
                               const std::string &title)
    {
        ompl_core::writePlanViewerPage(out, physicsViewerPlan(setup, simulated, title));
    }
}  // namespace ompl_phys
