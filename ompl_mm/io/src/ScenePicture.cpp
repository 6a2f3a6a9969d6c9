#include "ompl_mm/io/ScenePicture.h"

#include "ompl_mm/io/PlanColours.h"

#include <ompl/base/ScopedState.h>
#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace ompl_mm::picture
{
    namespace
    {
        constexpr double MARGIN_FRACTION = 0.05;
        constexpr unsigned int SUB_STEPS = 20;
        constexpr unsigned int CYLINDER_SIDES = 24;  // of the polygon a cylinder's rims are drawn with
        constexpr double HEIGHT_QUANTUM = 1e-6;

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

        /** The convex hull of points, counter-clockwise (Andrew's monotone chain). @pre points is
            not empty. */
        std::vector<Eigen::Vector2d> convexHull(std::vector<Eigen::Vector2d> points)
        {
            std::sort(points.begin(), points.end(),
                      [](const Eigen::Vector2d &a, const Eigen::Vector2d &b)
                      { return a.x() != b.x() ? a.x() < b.x() : a.y() < b.y(); });
            const auto turnsLeft =
                [](const Eigen::Vector2d &o, const Eigen::Vector2d &a, const Eigen::Vector2d &b)
            {
                const Eigen::Vector2d u = a - o, v = b - o;
                return u.x() * v.y() - u.y() * v.x() > 0.0;
            };
            // the lower chain left to right, then the upper one back
            std::vector<Eigen::Vector2d> hull;
            for (int pass = 0; pass < 2; ++pass)
            {
                const std::size_t chainStart = hull.size();
                for (const Eigen::Vector2d &p : points)
                {
                    while (hull.size() >= chainStart + 2 && !turnsLeft(hull[hull.size() - 2], hull.back(), p))
                        hull.pop_back();
                    hull.push_back(p);
                }
                hull.pop_back();  // the chain's last point starts the other chain
                std::reverse(points.begin(), points.end());
            }
            return hull.empty() ? std::vector<Eigen::Vector2d>{points.front()} : hull;
        }

        /** Points of a shape, in its frame, whose convex hull is its own: a box's corners, a
            cylinder's rims, a mesh's convex hull's corners (all its vertices when they span no
            volume); not for spheres. */
        std::vector<Eigen::Vector3d> hullPoints(const Shape &shape)
        {
            if (shape.kind == Shape::Kind::Mesh && shape.mesh != nullptr)
            {
                try
                {
                    return shape.mesh->convexHull()->vertices;
                }
                catch (const ompl::Exception &)
                {
                    return shape.mesh->vertices;  // flat: its vertices outline it as well
                }
            }
            std::vector<Eigen::Vector3d> points;
            if (shape.kind == Shape::Kind::Cylinder)
            {
                for (unsigned int k = 0; k < CYLINDER_SIDES; ++k)
                    for (const double z : {-shape.length / 2.0, shape.length / 2.0})
                    {
                        const double angle = 2.0 * M_PI * k / CYLINDER_SIDES;
                        points.emplace_back(shape.radius * std::cos(angle), shape.radius * std::sin(angle),
                                            z);
                    }
                return points;
            }
            const Eigen::AlignedBox3d box(-shape.boxSize / 2.0, shape.boxSize / 2.0);
            for (int c = 0; c < 8; ++c)
                points.push_back(box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)));
            return points;
        }

        /** A shape's outline in a view when its centre has the world pose frame: a circle for a
            sphere, else the convex hull of its projected hullPoints(). */
        Footprint viewOutline(View view, const Shape &shape, const Eigen::Isometry3d &frame)
        {
            Footprint f{{}, project(view, frame.translation()), 0.0};
            if (shape.kind == Shape::Kind::Sphere)
            {
                f.radius = shape.radius;
                return f;
            }
            std::vector<Eigen::Vector2d> projected;
            for (const Eigen::Vector3d &p : hullPoints(shape))
                projected.push_back(project(view, frame * p));
            f.corners = convexHull(std::move(projected));
            return f;
        }

        /** An object's outline in a view; its shape's centre is half its height above its base. */
        Footprint objectOutline(View view, const Shape &shape, const ObjectPose &pose)
        {
            if (view == View::Top)
                return footprint(shape, pose);
            return viewOutline(
                View::Side, shape,
                Eigen::Translation3d(pose.position + Eigen::Vector3d(0.0, 0.0, shape.height() / 2.0)) *
                    Eigen::AngleAxisd(pose.yaw, Eigen::Vector3d::UnitZ()));
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

        /** Height key of the scene's lowest support surface (the largest key when it has none). */
        long long lowestSurfaceKey(const Scene &scene)
        {
            long long lowest = std::numeric_limits<long long>::max();
            for (const SupportSurface &s : scene.surfaces)
                lowest = std::min(lowest, heightKey(s.height));
            return lowest;
        }

        /** True for an obstacle at or under the lowest surface (a floor slab), drawn faintly. */
        bool underLowestSurface(const Obstacle &obstacle, long long lowestSurface)
        {
            return heightKey(topHeight(obstacle.shape, obstacle.pose)) <= lowestSurface;
        }

        /** Sorts the ground by its order key; at equal keys a surface goes above an obstacle. */
        void sortGround(Picture &picture)
        {
            std::stable_sort(
                picture.ground.begin(), picture.ground.end(),
                [](const GroundItem &a, const GroundItem &b)
                { return a.orderKey != b.orderKey ? a.orderKey < b.orderKey : !a.isSurface && b.isSurface; });
        }

        /** Obstacles and surfaces seen from above, lowest top first; floor slabs drawn faintly. */
        void addGround(const Scene &scene, Picture &picture)
        {
            const long long lowestSurface = lowestSurfaceKey(scene);
            for (const SupportSurface &s : scene.surfaces)
            {
                Footprint rectangle;
                rectangle.corners = {s.min, {s.max.x(), s.min.y()}, s.max, {s.min.x(), s.max.y()}};
                rectangle.centre = (s.min + s.max) / 2.0;
                picture.ground.push_back({heightKey(s.height), true, false, rectangle, s.name});
            }
            for (const Obstacle &obstacle : scene.obstacles)
                picture.ground.push_back({heightKey(topHeight(obstacle.shape, obstacle.pose)), false,
                                          underLowestSurface(obstacle, lowestSurface),
                                          footprint(obstacle.shape, obstacle.pose), obstacle.name});
            sortGround(picture);
        }

        /** Obstacles seen from the side, the farthest (largest y) first, and surfaces edge-on. */
        void addSideGround(const Scene &scene, Picture &picture)
        {
            const long long lowestSurface = lowestSurfaceKey(scene);
            for (const Obstacle &obstacle : scene.obstacles)
                picture.ground.push_back({heightKey(-obstacle.pose.translation().y()), false,
                                          underLowestSurface(obstacle, lowestSurface),
                                          viewOutline(View::Side, obstacle.shape, obstacle.pose),
                                          obstacle.name});
            sortGround(picture);
            for (const SupportSurface &s : scene.surfaces)
                picture.surfaceLines.push_back({{s.min.x(), s.height}, {s.max.x(), s.height}, s.name});
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

        /** The arm's link shapes in a view at the state's joints. */
        ArmPose armPose(View view, const ManipulationStateSpace &space, const ompl::base::State *state,
                        const std::string &caption)
        {
            const ManipulationModel &model = *space.model();
            std::vector<Eigen::Isometry3d> frames;
            model.robot().forwardKinematics(space.robotValues(state), model.scene().robot.basePose, frames);
            ArmPose pose{{}, caption};
            for (std::size_t link = 0; link < frames.size(); ++link)
                for (const LinkShape &linkShape : model.robot().links()[link].shapes)
                    pose.links.push_back(viewOutline(view, linkShape.shape, frames[link] * linkShape.origin));
            return pose;
        }

        /** "pickup cyl1": a segment's primitive and the object it moves. */
        std::string segmentName(const Scene &scene, const SegmentLabel &label)
        {
            const bool named = label.object >= 0 && label.object < static_cast<int>(scene.objects.size());
            return primitiveKindName(label.kind) + (named ? " " + scene.objects[label.object].name : "");
        }

        /** The arm at the start, at every mode switch (where the segments' primitive or object
            changes) and at the end; at the start alone without a path. */
        void addArmPoses(View view, const ManipulationSetup &setup, const ompl::base::State *start,
                         const ManipulationPath *path, Picture &picture)
        {
            const ManipulationStateSpace &space = *setup.manipulationSpace();
            if (path == nullptr || path->getStateCount() == 0)
            {
                picture.armPoses.push_back(armPose(view, space, start, "start"));
                return;
            }
            const std::vector<SegmentLabel> &labels = path->labels();
            const std::size_t last = path->getStateCount() - 1;
            for (std::size_t i = 0; i <= last; ++i)
            {
                const bool switches = i > 0 && i < labels.size() && labels[i] != labels[i - 1];
                if (i != 0 && i != last && !switches)
                    continue;
                const std::string then =
                    i < labels.size() ? segmentName(space.model()->scene(), labels[i]) : "end";
                picture.armPoses.push_back(
                    armPose(view, space, path->getState(i), "waypoint " + std::to_string(i) + ": " + then));
            }
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

        /** A point's course along segment i of the path, interpolated as the space moves the robot
            and what it carries; point maps a state to the world point to follow. */
        template <class PointOf>
        std::vector<Eigen::Vector2d> course(const ManipulationStateSpace &space, const ManipulationPath &path,
                                            std::size_t i, View view, ompl::base::State *between,
                                            const PointOf &point)
        {
            std::vector<Eigen::Vector2d> points;
            for (unsigned int k = 0; k <= SUB_STEPS; ++k)
            {
                space.interpolate(path.getState(i), path.getState(i + 1), static_cast<double>(k) / SUB_STEPS,
                                  between);
                points.push_back(project(view, point(between)));
            }
            return points;
        }

        /** Tool course, waypoints and push arrows, as the view sees them. */
        void addPath(const ManipulationSetup &setup, const ManipulationPath &path, View view,
                     Picture &picture)
        {
            const ManipulationStateSpace &space = *setup.manipulationSpace();
            ompl::base::ScopedState<> between(setup.getStateSpace());
            const auto toolOf = [&space](const ompl::base::State *s) { return space.toolPosition(s); };
            const std::vector<SegmentLabel> &labels = path.labels();  // checked once, not per waypoint
            for (std::size_t i = 0; i < path.getStateCount(); ++i)
            {
                picture.waypoints.push_back(project(view, space.toolPosition(path.getState(i))));
                if (i + 1 == path.getStateCount() || i >= labels.size())
                    continue;
                const SegmentLabel &label = labels[i];
                picture.segments.push_back({label.kind, course(space, path, i, view, between.get(), toolOf)});
                if (label.kind != PrimitiveKind::Push || label.object < 0 ||
                    label.object >= static_cast<int>(space.objectCount()))
                    continue;
                const Eigen::Vector2d from =
                    project(view, space.objectPosition(path.getState(i), label.object));
                const Eigen::Vector2d to =
                    project(view, space.objectPosition(path.getState(i + 1), label.object));
                // a push that did not move its object has no direction to show
                if ((to - from).norm() > 1e-6)
                    picture.pushArrows.emplace_back(from, to);
            }
        }

        /** The course of each transferred object's centre (its base centre + half its height). */
        void addCarried(const ManipulationSetup &setup, const ManipulationPath &path, View view,
                        Picture &picture)
        {
            const ManipulationStateSpace &space = *setup.manipulationSpace();
            ompl::base::ScopedState<> between(setup.getStateSpace());
            const std::vector<SegmentLabel> &labels = path.labels();
            for (std::size_t i = 0; i + 1 < path.getStateCount() && i < labels.size(); ++i)
            {
                const int object = labels[i].object;
                if (labels[i].kind != PrimitiveKind::Transfer || object < 0 ||
                    object >= static_cast<int>(space.objectCount()))
                    continue;
                const double halfHeight = space.model()->scene().objects[object].shape.height() / 2.0;
                const auto centreOf = [&](const ompl::base::State *s) {
                    return Eigen::Vector3d(space.objectPosition(s, object) +
                                           Eigen::Vector3d(0.0, 0.0, halfHeight));
                };
                picture.carried.push_back(
                    {labels[i].kind, course(space, path, i, view, between.get(), centreOf), object});
            }
        }

        /** The objects at the start and at the end of the path, and the tool's course. */
        Picture pathPicture(const ManipulationSetup &setup, const ManipulationPath *path, View view)
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
            for (unsigned int i = 0; i < space.objectCount(); ++i)
            {
                picture.objectStart.push_back(
                    objectOutline(view, scene.objects[i].shape, space.objectPose(start, i)));
                if (end != nullptr)
                    picture.objectEnd.push_back(
                        objectOutline(view, scene.objects[i].shape, space.objectPose(end, i)));
            }
            if (end != nullptr)
                addPath(setup, *path, view, picture);
            return picture;
        }

        void extend(Eigen::AlignedBox2d &box, const Footprint &f)
        {
            box.extend(f.centre - Eigen::Vector2d::Constant(f.radius));
            box.extend(f.centre + Eigen::Vector2d::Constant(f.radius));
            for (const Eigen::Vector2d &corner : f.corners)
                box.extend(corner);
        }
    }  // namespace

    /** A world box with a margin around it, at least a metre across, so a lone object is not
        blown up to the whole picture. */
    Eigen::AlignedBox2d padded(const Eigen::AlignedBox2d &box)
    {
        const Eigen::Vector2d half = (box.sizes() / 2.0).cwiseMax(0.5);
        const Eigen::Vector2d margin = Eigen::Vector2d::Constant(MARGIN_FRACTION * 2.0 * half.maxCoeff());
        return Eigen::AlignedBox2d(box.center() - half - margin, box.center() + half + margin);
    }

    /** The view from above: ground, objects, goals, tool course, and a mobile robot's disc or an
        arm's links. */
    Picture topPicture(const ManipulationSetup &setup, const ManipulationPath *path)
    {
        Picture picture = pathPicture(setup, path, View::Top);
        const ManipulationStateSpace &space = *setup.manipulationSpace();
        const ompl::base::State *start = setup.getProblemDefinition()->getStartState(0);
        addGround(space.model()->scene(), picture);
        addGoals(setup, start, picture);
        picture.robotStart = robotFootprint(space, start);
        if (path != nullptr && path->getStateCount() > 0)
            picture.robotEnd = robotFootprint(space, path->getState(path->getStateCount() - 1));
        // an arm seen from above: its links' footprints, as in the side view
        if (!space.model()->robot().allJointsPrismatic())
            addArmPoses(View::Top, setup, start, path, picture);
        return picture;
    }

    bool isFloorSlab(const Scene &scene, const Obstacle &obstacle)
    {
        return underLowestSurface(obstacle, lowestSurfaceKey(scene));
    }

    /** The view from the side: ground, objects, the arm at its mode switches, tool course and
        the carried objects' courses. */
    Picture sidePicture(const ManipulationSetup &setup, const ManipulationPath *path)
    {
        Picture picture = pathPicture(setup, path, View::Side);
        addSideGround(setup.model()->scene(), picture);
        addArmPoses(View::Side, setup, setup.getProblemDefinition()->getStartState(0), path, picture);
        if (path != nullptr && path->getStateCount() > 0)
            addCarried(setup, *path, View::Side, picture);
        return picture;
    }

    /** The world box holding everything drawn (floor slabs included: they are drawn too). */
    Eigen::AlignedBox2d bounds(const Picture &picture)
    {
        Eigen::AlignedBox2d box;
        for (const GroundItem &item : picture.ground)
            extend(box, item.footprint);
        for (const SurfaceLine &line : picture.surfaceLines)
            box.extend(line.from).extend(line.to);
        for (const std::vector<Footprint> *list : {&picture.objectStart, &picture.objectEnd})
            for (const Footprint &f : *list)
                extend(box, f);
        for (const ArmPose &pose : picture.armPoses)
            for (const Footprint &f : pose.links)
                extend(box, f);
        for (const std::optional<Footprint> &robot : {picture.robotStart, picture.robotEnd})
            if (robot)
                extend(box, *robot);
        for (const GoalMarker &goal : picture.goals)
            box.extend(goal.at);
        for (const std::vector<ToolSegment> *list : {&picture.segments, &picture.carried})
            for (const ToolSegment &segment : *list)
                for (const Eigen::Vector2d &p : segment.points)
                    box.extend(p);
        if (box.isEmpty())
            box.extend(Eigen::Vector2d::Zero());
        return box;
    }
}  // namespace ompl_mm::picture
