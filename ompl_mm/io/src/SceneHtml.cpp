#include "ompl_mm/io/SceneHtml.h"

#include "ompl_mm/io/PlanColours.h"

#include <ompl/base/ScopedState.h>
#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>

namespace ompl_mm
{
    namespace
    {
        /** Support surfaces are drawn as slabs this thick, just below their height, metres. */
        constexpr double SURFACE_THICKNESS = 0.004;
        /** Opacity of goal poses. */
        constexpr double GOAL_OPACITY = 0.3;

        ompl_core::ViewerSolid solidOf(const Shape &shape, const Eigen::Isometry3d &pose)
        {
            ompl_core::ViewerSolid solid;
            solid.pose = pose;
            switch (shape.kind)
            {
                case Shape::Kind::Box:
                    solid.kind = ompl_core::ViewerSolid::Kind::Box;
                    solid.size = shape.boxSize;
                    break;
                case Shape::Kind::Cylinder:
                    solid.kind = ompl_core::ViewerSolid::Kind::Cylinder;
                    solid.radius = shape.radius;
                    solid.length = shape.length;
                    break;
                case Shape::Kind::Sphere:
                    solid.kind = ompl_core::ViewerSolid::Kind::Sphere;
                    solid.radius = shape.radius;
                    break;
                case Shape::Kind::Mesh:
                    solid.kind = ompl_core::ViewerSolid::Kind::Mesh;
                    solid.vertices = shape.mesh->vertices;
                    solid.triangles = shape.mesh->triangles;
                    break;
            }
            return solid;
        }

        /** The object's solid in its frame: the shape's centre lies half its height above the base. */
        ompl_core::ViewerSolid objectSolid(const MovableObject &object)
        {
            return solidOf(object.shape,
                           Eigen::Isometry3d(Eigen::Translation3d(0.0, 0.0, object.shape.height() / 2)));
        }

        /** Builds the plan: the bodies, then the frames of the path. */
        class ViewerPlanBuilder
        {
        public:
            ViewerPlanBuilder(const ManipulationSetup &setup, const std::string &title)
                : space_(*setup.manipulationSpace()),
                  scene_(space_.model()->scene()),
                  robot_(space_.model()->robot())
            {
                plan_.title = title;
                if (setup.getProblemDefinition()->getStartStateCount() == 0)
                    throw ompl::Exception("manipulationViewerPlan", "the setup has no start state");
                start_ = setup.getProblemDefinition()->getStartState(0);
            }

            ompl_core::ViewerPlan build(const ManipulationPath *path)
            {
                addWorld();
                addMovingBodies();
                addGoals();
                if (path && path->getStateCount() > 0)
                    addPath(*path);
                else
                    addFrame(start_);
                return plan_;
            }

        private:
            void addWorld()
            {
                for (const Obstacle &obstacle : scene_.obstacles)
                    plan_.fixed.push_back(
                        {obstacle.name, OBSTACLE_COLOUR, 1.0, {solidOf(obstacle.shape, obstacle.pose)}});
                for (const SupportSurface &surface : scene_.surfaces)
                {
                    ompl_core::ViewerSolid slab;
                    slab.size = Eigen::Vector3d(surface.max.x() - surface.min.x(),
                                                surface.max.y() - surface.min.y(), SURFACE_THICKNESS);
                    const Eigen::Vector2d centre = (surface.min + surface.max) / 2;
                    // just below the surface, so objects resting on it stand on the slab
                    slab.pose = Eigen::Translation3d(centre.x(), centre.y(),
                                                     surface.height - SURFACE_THICKNESS / 2 - 1e-4);
                    plan_.fixed.push_back({surface.name, SURFACE_COLOUR, 1.0, {slab}});
                }
                plan_.legend.push_back({"obstacle", OBSTACLE_COLOUR});
                plan_.legend.push_back({"support surface", SURFACE_COLOUR});
            }

            /** The robot's links that have shapes, then the objects. */
            void addMovingBodies()
            {
                for (std::size_t l = 0; l < robot_.links().size(); ++l)
                {
                    const Link &link = robot_.links()[l];
                    if (link.shapes.empty())
                        continue;
                    ompl_core::ViewerBody body{link.name, ROBOT_COLOUR, 1.0, {}};
                    for (const LinkShape &shape : link.shapes)
                        body.solids.push_back(solidOf(shape.shape, shape.origin));
                    plan_.moving.push_back(body);
                    robotLinks_.push_back(l);
                }
                plan_.legend.push_back({"robot", ROBOT_COLOUR});
                for (unsigned int i = 0; i < scene_.objects.size(); ++i)
                {
                    plan_.moving.push_back(
                        {scene_.objects[i].name, objectColour(i), 1.0, {objectSolid(scene_.objects[i])}});
                    plan_.legend.push_back({scene_.objects[i].name, objectColour(i)});
                }
            }

            /** Objects at their goals, "don't care" coordinates at their start values, and the robot at
                its goal when every joint has one. */
            void addGoals()
            {
                for (const ObjectGoal &goal : scene_.objectGoals)
                {
                    const int i = scene_.objectIndex(goal.object);
                    if (i < 0)
                        continue;
                    const MovableObject &object = scene_.objects[static_cast<std::size_t>(i)];
                    ObjectPose pose = object.start;
                    for (int k = 0; k < 3; ++k)
                        if (goal.position[k])
                            pose.position[k] = *goal.position[k];
                    if (goal.yaw)
                        pose.yaw = *goal.yaw;
                    ompl_core::ViewerSolid solid = objectSolid(object);
                    solid.pose = pose.frame() * solid.pose;
                    plan_.goals.push_back({"goal " + object.name,
                                           objectColour(static_cast<unsigned int>(i)),
                                           GOAL_OPACITY,
                                           {solid}});
                }
                const std::vector<GoalCoordinate> &joints = scene_.robotGoal.joints;
                if (joints.size() != robot_.dof() ||
                    !std::all_of(joints.begin(), joints.end(),
                                 [](const GoalCoordinate &j) { return j.has_value(); }))
                    return;
                std::vector<double> q;
                for (const GoalCoordinate &j : joints)
                    q.push_back(*j);
                std::vector<Eigen::Isometry3d> frames;
                robot_.forwardKinematics(q.data(), scene_.robot.basePose, frames);
                ompl_core::ViewerBody body{"goal robot", ROBOT_COLOUR, GOAL_OPACITY, {}};
                for (const std::size_t l : robotLinks_)
                    for (const LinkShape &shape : robot_.links()[l].shapes)
                        body.solids.push_back(solidOf(shape.shape, frames[l] * shape.origin));
                plan_.goals.push_back(body);
            }

            /** How far a segment goes: the tool point's travel, or the joints' or an object's motion
                when larger (a turn on the spot), metres or radians. */
            double segmentLength(const ompl::base::State *a, const ompl::base::State *b) const
            {
                double joints = 0.0;
                for (unsigned int j = 0; j < space_.robotDimension(); ++j)
                    joints = std::max(joints, std::abs(space_.robotValues(a)[j] - space_.robotValues(b)[j]));
                double objects = 0.0;
                for (unsigned int i = 0; i < space_.objectCount(); ++i)
                    objects =
                        std::max(objects, (space_.objectPosition(a, i) - space_.objectPosition(b, i)).norm());
                return std::max({space_.toolTravel(a, b), joints, objects});
            }

            void addPath(const ManipulationPath &path)
            {
                ompl::base::ScopedState<> between(path.getSpaceInformation()->getStateSpace());
                const std::vector<SegmentLabel> &labels = path.labels();
                for (std::size_t i = 0; i + 1 < path.getStateCount(); ++i)
                {
                    const ompl::base::State *a = path.getState(i), *b = path.getState(i + 1);
                    const std::size_t first = plan_.frames.size();
                    const auto steps = static_cast<std::size_t>(
                        std::max(1.0, std::ceil(segmentLength(a, b) / (VIEWER_SPEED * plan_.frameStep))));
                    for (std::size_t k = 0; k < steps; ++k)
                    {
                        space_.interpolate(a, b, static_cast<double>(k) / static_cast<double>(steps),
                                           between.get());
                        addFrame(between.get());
                    }
                    addSegment(labels[i], first);
                }
                addFrame(path.getState(path.getStateCount() - 1));
                if (!plan_.segments.empty())
                    plan_.segments.back().last = plan_.frames.size() - 1;
            }

            /** Starts a segment at frame first, or extends the last one when the label is the same. */
            void addSegment(const SegmentLabel &label, std::size_t first)
            {
                std::string text = primitiveKindName(label.kind);
                if (label.object >= 0)
                    text += " " + scene_.objects[static_cast<std::size_t>(label.object)].name;
                if (!plan_.segments.empty())
                {
                    plan_.segments.back().last = first;
                    if (plan_.segments.back().label == text)
                        return;
                }
                plan_.segments.push_back({first, first, text, primitiveColour(label.kind)});
                if (std::none_of(plan_.legend.begin(), plan_.legend.end(),
                                 [&](const auto &entry)
                                 { return entry.first == primitiveKindName(label.kind); }))
                    plan_.legend.push_back({primitiveKindName(label.kind), primitiveColour(label.kind)});
            }

            void addFrame(const ompl::base::State *state)
            {
                std::vector<Eigen::Isometry3d> links;
                robot_.forwardKinematics(space_.robotValues(state), scene_.robot.basePose, links);
                std::vector<Eigen::Isometry3d> poses;
                for (const std::size_t l : robotLinks_)
                    poses.push_back(links[l]);
                for (unsigned int i = 0; i < space_.objectCount(); ++i)
                    poses.push_back(space_.objectPose(state, i).frame());
                plan_.frames.push_back(poses);
                plan_.toolPath.push_back(space_.toolPosition(state));
            }

            const ManipulationStateSpace &space_;
            const Scene &scene_;
            const RobotModel &robot_;
            const ompl::base::State *start_{nullptr};
            std::vector<std::size_t> robotLinks_;  ///< links with shapes, in the order of plan_.moving
            ompl_core::ViewerPlan plan_;
        };
    }  // namespace

    ompl_core::ViewerPlan manipulationViewerPlan(const ManipulationSetup &setup, const ManipulationPath *path,
                                                 const std::string &title)
    {
        return ViewerPlanBuilder(setup, title).build(path);
    }

    void writeSceneHtml(std::ostream &out, const ManipulationSetup &setup, const ManipulationPath *path,
                        const std::string &title)
    {
        ompl_core::writePlanViewerPage(out, manipulationViewerPlan(setup, path, title));
    }
}  // namespace ompl_mm
