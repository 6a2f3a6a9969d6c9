/* What the planning pieces share about a problem: the robot's kinematics placed in the world,
   the tool point, the movable objects and the surfaces they rest on. It answers the questions
   every piece asks of a configuration: where is the tool. Whether an object rests, and on what,
   is the scene's rule (Scene::restingSurface). */
#pragma once

#include "ompl_mm/robot/RobotModel.h"
#include "ompl_mm/scene/Scene.h"

#include <memory>
#include <vector>

namespace ompl_mm
{
    class ManipulationModel;
    using ManipulationModelPtr = std::shared_ptr<const ManipulationModel>;

    /** Immutable after construction; shared by the state space, validity checker, metric and
        primitives through a ManipulationModelPtr. */
    class ManipulationModel
    {
    public:
        /** @throws ompl_core::InputError (naming the scene's <robot> line) when the tool link is unknown. */
        ManipulationModel(Scene scene, RobotModel robot);

        const Scene &scene() const { return scene_; }
        const RobotModel &robot() const { return robot_; }
        unsigned int dof() const { return robot_.dof(); }
        unsigned int objectCount() const { return static_cast<unsigned int>(scene_.objects.size()); }
        int toolLink() const { return toolLink_; }

        /** World frame of the tool point for joint values q. */
        Eigen::Isometry3d toolFrame(const double *q) const;

    private:
        Scene scene_;
        RobotModel robot_;
        int toolLink_{-1};
    };
}  // namespace ompl_mm
