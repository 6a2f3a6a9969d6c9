/* The configuration space of a manipulation problem: the robot's joints times one upright pose
   (x, y, z, yaw) per movable object. Interpolation is mode-aware: an object held by the robot
   (resting on no surface at either end of a motion) moves with the tool frame, so any two
   consecutive waypoints of a manipulation path interpolate the way the primitive moved them. */
#pragma once

#include "ompl_mm/model/ManipulationModel.h"

#include <ompl/base/StateSpace.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SO2StateSpace.h>

namespace ompl_mm
{
    /** A CompoundStateSpace with subspaces "robot" (RealVector, one dimension per moving joint),
        then per object "<name>_position" (RealVector 3: base centre) and "<name>_yaw" (SO2).
        Object position bounds enclose all support surfaces and sampling regions.
        Not copyable (OMPL state spaces are shared through pointers). */
    class ManipulationStateSpace : public ompl::base::CompoundStateSpace
    {
    public:
        using StateType = ompl::base::CompoundStateSpace::StateType;

        explicit ManipulationStateSpace(ManipulationModelPtr model);

        const ManipulationModelPtr &model() const { return model_; }
        unsigned int objectCount() const { return model_->objectCount(); }
        unsigned int robotDimension() const { return model_->dof(); }

        double *robotValues(ompl::base::State *state) const;
        const double *robotValues(const ompl::base::State *state) const;

        Eigen::Vector3d objectPosition(const ompl::base::State *state, unsigned int object) const;
        double objectYaw(const ompl::base::State *state, unsigned int object) const;
        ObjectPose objectPose(const ompl::base::State *state, unsigned int object) const;
        void setObjectPose(ompl::base::State *state, unsigned int object, const ObjectPose &pose) const;

        /** Copies the object's pose from source to destination. */
        void copyObject(ompl::base::State *destination, const ompl::base::State *source,
                        unsigned int object) const;
        /** Copies the robot's joints from source to destination. */
        void copyRobot(ompl::base::State *destination, const ompl::base::State *source) const;

        /** True when the object's pose differs between a and b (beyond 1e-9). */
        bool objectMoves(const ompl::base::State *a, const ompl::base::State *b, unsigned int object) const;
        /** True when some object's pose differs between a and b. */
        bool anyObjectMoves(const ompl::base::State *a, const ompl::base::State *b) const;
        /** True when the robot's joints differ between a and b (beyond 1e-9). */
        bool robotMoves(const ompl::base::State *a, const ompl::base::State *b) const;

        /** Support surface the object rests on in this state, or -1 when held. */
        int restingSurface(const ompl::base::State *state, unsigned int object) const;

        /** World position of the tool point. */
        Eigen::Vector3d toolPosition(const ompl::base::State *state) const;

        /** Sets every subspace's resolution so that motion checks step at most `step` in each
            (metres for positions and prismatic joints, radians for revolute joints and yaw), and
            sets the space up again so that the new resolution is in force at once. */
        void setCollisionResolution(double step);

        void interpolate(const ompl::base::State *from, const ompl::base::State *to, double t,
                         ompl::base::State *state) const override;
        void printState(const ompl::base::State *state, std::ostream &out) const override;

    private:
        /** True when the object moves between from and to and is held at either end. */
        bool isCarried(const ompl::base::State *from, const ompl::base::State *to, unsigned int object) const;
        /** Pose at time t of an object carried from one pose to another while the tool moves. */
        static ObjectPose carriedPose(const ObjectPose &from, const ObjectPose &to,
                                      const Eigen::Isometry3d &toolFrom, const Eigen::Isometry3d &toolTo,
                                      const Eigen::Isometry3d &toolAt, double t);

        ManipulationModelPtr model_;
    };

    using ManipulationStateSpacePtr = std::shared_ptr<ManipulationStateSpace>;
}  // namespace ompl_mm
