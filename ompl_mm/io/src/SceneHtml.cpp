#include "ompl_mm/io/SceneHtml.h"

#include "ompl_mm/io/MeshReduction.h"
#include "ompl_mm/io/PlanColours.h"
#include "ompl_mm/io/ScenePicture.h"
#include "ompl_mm/robot/VisualModel.h"

#include <ompl/base/ScopedState.h>
#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>

namespace ompl_mm
{
    namespace
    {
        /** Support surfaces are drawn as slabs this thick, metres, SURFACE_RISE above their height:
            an obstacle whose top the surface is then ends inside the slab, so the two faces never
            fight for the same pixels, and objects resting on the surface sink in by SURFACE_RISE. */
        constexpr double SURFACE_THICKNESS = 0.004;
        /** How far a surface's slab stands above the surface, metres. */
        constexpr double SURFACE_RISE = 0.001;
        /** Opacity of goal poses. */
        constexpr double GOAL_OPACITY = 0.3;
        /** Opacity of the companions of the objects (CompanionPoses): seen through, unlike the objects. */
        constexpr double COMPANION_OPACITY = 0.5;

        /** "#rrggbb" of a colour's red, green and blue. */
        std::string cssColour(const Rgba &colour)
        {
            char text[8];
            std::snprintf(text, sizeof text, "#%02x%02x%02x",
                          static_cast<int>(std::lround(255.0 * colour[0])),
                          static_cast<int>(std::lround(255.0 * colour[1])),
                          static_cast<int>(std::lround(255.0 * colour[2])));
            return text;
        }

        /** The viewer's solids for shapes; a mesh reduced for the page (reduceMesh()) once, however
            many solids use it. */
        class ViewerSolids
        {
        public:
            ompl_core::ViewerSolid of(const Shape &shape, const Eigen::Isometry3d &pose)
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
                        solid.mesh = reduced(*shape.mesh);
                        break;
                }
                return solid;
            }

        private:
            std::shared_ptr<const ompl_core::ViewerMesh> reduced(const TriangleMesh &mesh)
            {
                std::shared_ptr<const ompl_core::ViewerMesh> &entry = meshes_[&mesh];
                if (!entry)
                    entry = std::make_shared<const ompl_core::ViewerMesh>(reduceMesh(mesh).mesh);
                return entry;
            }

            std::map<const TriangleMesh *, std::shared_ptr<const ompl_core::ViewerMesh>> meshes_;
        };

        /** How the robot looks: its URDF's visuals, or its collision shapes without a URDF file. */
        VisualModel robotLook(const Scene &scene, const RobotModel &robot)
        {
            return scene.robot.urdfFile.empty() ? VisualModel::fromCollision(robot)
                                                : VisualModel::fromUrdfFile(scene.robot.urdfFile, robot);
        }

        /** Builds the plan: the bodies, then the frames of the path. */
        class ViewerPlanBuilder
        {
        public:
            ViewerPlanBuilder(const ManipulationSetup &setup, const std::string &title,
                              const CompanionPoses *companions)
                : companions_(companions),
                  space_(*setup.manipulationSpace()),
                  scene_(space_.model()->scene()),
                  robot_(space_.model()->robot()),
                  look_(robotLook(scene_, robot_))
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
                {
                    if (companions_ && companions_->poses.size() != path->getStateCount())
                        throw ompl::Exception("manipulationViewerPlan",
                                              "companion poses need one entry per waypoint");
                    addPath(*path);
                }
                else
                    addFrame(start_, 0, 0.0);
                return plan_;
            }

        private:
            void addWorld()
            {
                // floor slabs light, so that what stands on them shows
                for (const Obstacle &obstacle : scene_.obstacles)
                    plan_.fixed.push_back(
                        {obstacle.name,
                         picture::isFloorSlab(scene_, obstacle) ? FLOOR_COLOUR : OBSTACLE_COLOUR,
                         1.0,
                         {solids_.of(obstacle.shape, obstacle.pose)}});
                for (const SupportSurface &surface : scene_.surfaces)
                {
                    ompl_core::ViewerSolid slab;
                    slab.size = Eigen::Vector3d(surface.max.x() - surface.min.x(),
                                                surface.max.y() - surface.min.y(), SURFACE_THICKNESS);
                    const Eigen::Vector2d centre = (surface.min + surface.max) / 2;
                    slab.pose = Eigen::Translation3d(centre.x(), centre.y(),
                                                     surface.height + SURFACE_RISE - SURFACE_THICKNESS / 2);
                    plan_.fixed.push_back({surface.name, SURFACE_COLOUR, 1.0, {slab}});
                }
                plan_.legend.push_back({"obstacle", OBSTACLE_COLOUR});
                plan_.legend.push_back({"support surface", SURFACE_COLOUR});
            }

            /** The robot's links that have shapes (visual, or else collision), then the objects. */
            void addMovingBodies()
            {
                bool coloured = false;
                for (std::size_t l = 0; l < robot_.links().size(); ++l)
                {
                    const LinkVisual &look = look_.links()[l];
                    if (look.shapes.empty())
                        continue;
                    ompl_core::ViewerBody body{robot_.links()[l].name, ROBOT_COLOUR, 1.0, {}};
                    for (const VisualShape &shape : look.shapes)
                    {
                        body.solids.push_back(solids_.of(shape.shape, shape.origin));
                        if (shape.colour)
                            body.solids.back().colour = cssColour(*shape.colour);
                        coloured = coloured || shape.colour.has_value();
                    }
                    plan_.moving.push_back(body);
                    robotLinks_.push_back(l);
                }
                // a robot in colours of its own is no grey line in the legend
                if (!coloured)
                    plan_.legend.push_back({"robot", ROBOT_COLOUR});
                for (unsigned int i = 0; i < scene_.objects.size(); ++i)
                {
                    plan_.moving.push_back(
                        {scene_.objects[i].name, objectColour(i), 1.0, {objectSolid(scene_.objects[i])}});
                    plan_.legend.push_back({scene_.objects[i].name, objectColour(i)});
                }
                if (!companions_)
                    return;
                for (unsigned int i = 0; i < scene_.objects.size(); ++i)
                {
                    plan_.tracks.push_back(plan_.moving.size() - scene_.objects.size());
                    plan_.tracks.push_back(plan_.moving.size());
                    plan_.moving.push_back({scene_.objects[i].name + " (" + companions_->label + ")",
                                            objectColour(i),
                                            COMPANION_OPACITY,
                                            {objectSolid(scene_.objects[i])}});
                }
                plan_.legend.push_back({companions_->label + ": translucent twins", ROBOT_COLOUR});
            }

            /** The object's solid in its frame: the shape's centre lies half its height above the base. */
            ompl_core::ViewerSolid objectSolid(const MovableObject &object)
            {
                return solids_.of(object.shape, Eigen::Isometry3d(Eigen::Translation3d(
                                                    0.0, 0.0, object.shape.height() / 2)));
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
                    for (const VisualShape &shape : look_.links()[l].shapes)
                        body.solids.push_back(solids_.of(shape.shape, frames[l] * shape.origin));
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
                        const double t = static_cast<double>(k) / static_cast<double>(steps);
                        space_.interpolate(a, b, t, between.get());
                        addFrame(between.get(), i, t);
                    }
                    addSegment(labels[i], first);
                }
                addFrame(path.getState(path.getStateCount() - 1), path.getStateCount() - 1, 0.0);
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

            /** The frame of state, which lies t of the way from waypoint `waypoint` to the next. */
            void addFrame(const ompl::base::State *state, std::size_t waypoint, double t)
            {
                std::vector<Eigen::Isometry3d> links;
                robot_.forwardKinematics(space_.robotValues(state), scene_.robot.basePose, links);
                std::vector<Eigen::Isometry3d> poses;
                for (const std::size_t l : robotLinks_)
                    poses.push_back(links[l]);
                for (unsigned int i = 0; i < space_.objectCount(); ++i)
                    poses.push_back(space_.objectPose(state, i).frame());
                if (companions_)
                    for (unsigned int i = 0; i < space_.objectCount(); ++i)
                    {
                        const std::vector<std::vector<ObjectPose>> &at = companions_->poses;
                        const ObjectPose &from = at[waypoint][i];
                        const ObjectPose &to = at[std::min(waypoint + 1, at.size() - 1)][i];
                        ObjectPose pose;
                        pose.position = from.position + t * (to.position - from.position);
                        pose.yaw = from.yaw + t * std::remainder(to.yaw - from.yaw, 2.0 * M_PI);
                        poses.push_back(pose.frame());
                    }
                plan_.frames.push_back(poses);
                plan_.toolPath.push_back(space_.toolPosition(state));
            }

            const CompanionPoses *companions_;  ///< may be null
            const ManipulationStateSpace &space_;
            const Scene &scene_;
            const RobotModel &robot_;
            const VisualModel look_;  ///< how the robot's links look
            ViewerSolids solids_;
            const ompl::base::State *start_{nullptr};
            std::vector<std::size_t> robotLinks_;  ///< links with shapes, in the order of plan_.moving
            ompl_core::ViewerPlan plan_;
        };
    }  // namespace

    ompl_core::ViewerPlan manipulationViewerPlan(const ManipulationSetup &setup, const ManipulationPath *path,
                                                 const std::string &title, const CompanionPoses *companions)
    {
        return ViewerPlanBuilder(setup, title, companions).build(path);
    }

    void writeSceneHtml(std::ostream &out, const ManipulationSetup &setup, const ManipulationPath *path,
                        const std::string &title, const CompanionPoses *companions)
    {
        ompl_core::writePlanViewerPage(out, manipulationViewerPlan(setup, path, title, companions));
    }
}  // namespace ompl_mm
