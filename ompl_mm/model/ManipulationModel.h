#pragma once

#include "ompl_mm/robot/KinematicChain.h"
#include "ompl_mm/robot/RobotModel.h"
#include "ompl_mm/scene/Scene.h"

#include <memory>
#include <optional>
#include <vector>

namespace ompl_mm
{
    class ManipulationModel;
    /** Shared, read-only ownership of a ManipulationModel: every piece that holds one keeps the
        model alive. */
    using ManipulationModelPtr = std::shared_ptr<const ManipulationModel>;

    /** What the planning pieces share about a problem: the robot's kinematics placed in the world,
        the tool point, the movable objects and the surfaces they rest on. It answers the question
        every piece asks of a configuration: where is the tool. Whether an object rests, and on
        what, is the scene's rule (Scene::restingSurface). Immutable after construction; shared by
        the state space, validity checker, metric and primitives through a ManipulationModelPtr. */
    class ManipulationModel
    {
    public:
        /** Keeps its own copies of scene and robot.
            @throws ompl_core::InputError (naming the scene's robot element) when the tool link is
            unknown, or naming a tool frame's element when its link is. */
        ManipulationModel(Scene scene, RobotModel robot);

        /** The problem, as given to the constructor. */
        const Scene &scene() const { return scene_; }
        /** The robot's kinematic tree. */
        const RobotModel &robot() const { return robot_; }
        /** Number of moving joints of the robot. */
        unsigned int dof() const { return robot_.dof(); }
        /** Number of movable objects. */
        unsigned int objectCount() const { return static_cast<unsigned int>(scene_.objects.size()); }
        /** Index of the tool link in robot().links(). */
        int toolLink() const { return toolLink_; }

        /** World frame of the tool point for joint values q (size dof()): the tool link's frame
            moved to the scene's tool offset. */
        Eigen::Isometry3d toolFrame(const double *q) const;

        /** The kinematic chain of the scene's tool frame called name (RobotSpec::tools): its pose
            and Jacobian for joint values, the chain an IkSolver solves; the robot's root at the
            origin (pass the scene's base pose to the chain's functions).
            @throws ompl::Exception when the scene declares no such tool frame. */
        const KinematicChain &toolChain(const std::string &name) const;
        /** The kinematic chain of the tool point (toolFrame()), for inverse kinematics of the tool
            the scene's primitives carry objects with; the robot's root at the origin. */
        const KinematicChain &toolPointChain() const { return *toolPointChain_; }

    private:
        Scene scene_;
        RobotModel robot_;
        int toolLink_{-1};
        std::vector<std::pair<std::string, KinematicChain>> toolChains_;  ///< per declared tool frame
        std::optional<KinematicChain> toolPointChain_;                    ///< set by the constructor
    };
}  // namespace ompl_mm
