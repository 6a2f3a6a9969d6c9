#pragma once

#include "ompl_mm/model/ManipulationModel.h"

#include <ompl/base/StateSpace.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SO2StateSpace.h>

#include <cstddef>
#include <string>

namespace ompl_mm
{
    /** Coordinates (metres, radians) that differ by no more than this count as the same: an object
        or joint that changes by no more does not move. */
    constexpr double SAME_COORDINATE = 1e-9;

    /** The configuration space of a manipulation problem: the robot's joints times one upright pose
        (x, y, z, yaw) per movable object. A CompoundStateSpace with subspaces "robot" (RealVector,
        one dimension per moving joint, bounded by the joint limits), then per object
        "NAME_position" (RealVector 3: base centre in the world, metres) and "NAME_yaw" (SO2,
        radians). Object position bounds enclose all support surfaces and sampling regions.
        Interpolation is mode-aware: an object held by the robot (resting on no surface at either
        end of a motion) moves with the tool frame (keeping its own yaw when it turns freely, like
        a cylinder), so any two consecutive waypoints of a
        manipulation path interpolate the way the primitive moved them. Not copyable (OMPL state
        spaces are shared through pointers). */
    class ManipulationStateSpace : public ompl::base::CompoundStateSpace
    {
    public:
        /** The state type: a compound state of the subspaces above. */
        using StateType = ompl::base::CompoundStateSpace::StateType;

        /** Builds and locks the subspaces for the model's robot and objects; shares the model. */
        explicit ManipulationStateSpace(ManipulationModelPtr model);

        /** A state in one block of memory: OMPL's compound state makes two or three allocations per
            subspace, and search trees hold many states. Free it with freeState() of this space
            (never a subspace's freeState() on a component). */
        ompl::base::State *allocState() const override;
        /** Frees a state of allocState(). */
        void freeState(ompl::base::State *state) const override;

        /** The problem this space describes. */
        const ManipulationModelPtr &model() const { return model_; }
        /** Number of movable objects. */
        unsigned int objectCount() const { return model_->objectCount(); }
        /** Number of robot coordinates (moving joints). */
        unsigned int robotDimension() const { return model_->dof(); }

        /** The robot's joint values in state (robotDimension() of them), writable. */
        double *robotValues(ompl::base::State *state) const;
        /** The robot's joint values in state (robotDimension() of them). */
        const double *robotValues(const ompl::base::State *state) const;

        /** The object's base centre in the world, metres. */
        Eigen::Vector3d objectPosition(const ompl::base::State *state, unsigned int object) const;
        /** The object's rotation about world z, radians. */
        double objectYaw(const ompl::base::State *state, unsigned int object) const;
        /** The object's pose (base centre and yaw). */
        ObjectPose objectPose(const ompl::base::State *state, unsigned int object) const;
        /** Sets the object's pose; the yaw is wrapped into [-pi, pi). */
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

        /** World position of the tool point, metres. */
        Eigen::Vector3d toolPosition(const ompl::base::State *state) const;
        /** Length of the path the tool point travels as `from` interpolates to `to`, metres
            (straight lines between states sampled at the segment resolution). */
        double toolTravel(const ompl::base::State *from, const ompl::base::State *to) const;

        /** Sets every subspace's longest valid segment so that OMPL's discretisations (path
            interpolation, validSegmentCount) and toolTravel() step at most `step` in each
            (metres for positions and prismatic joints, radians for revolute joints and yaw), and
            sets the space up again so that the new resolution is in force at once. */
        void setSegmentResolution(double step);

        /** OMPL's hook: the state a fraction t of the way from `from` to `to`. Objects carried at
            either end move with the tool (their grasp interpolated between the ends' grasps), the
            rest interpolate per subspace; t = 0 and t = 1 give `from` and `to` exactly (bit for
            bit, so a joint at its limit stays within it). state may be from or to. */
        void interpolate(const ompl::base::State *from, const ompl::base::State *to, double t,
                         ompl::base::State *state) const override;
        /** What interpolate() needs of a motion's ends, for a motion interpolated many times (as
            a continuous collision check does): computed once by motionEnds(). */
        struct MotionEnds
        {
            bool carries{false};         ///< some object is carried at either end
            Eigen::Isometry3d toolFrom;  ///< the tool frame at `from`, when carries
            Eigen::Isometry3d toolTo;    ///< the tool frame at `to`, when carries
        };
        /** The ends of the motion from `from` to `to`, for interpolate(from, to, t, state, ends). */
        MotionEnds motionEnds(const ompl::base::State *from, const ompl::base::State *to) const;
        /** interpolate() along a motion whose ends are known (motionEnds(from, to)). */
        void interpolate(const ompl::base::State *from, const ompl::base::State *to, double t,
                         ompl::base::State *state, const MotionEnds &ends) const;
        /** OMPL's hook: a ManipulationStateSampler (near samples move only the robot). */
        ompl::base::StateSamplerPtr allocDefaultStateSampler() const override;
        /** OMPL's hook: prints the joints and each object's name, position and yaw on one line. */
        void printState(const ompl::base::State *state, std::ostream &out) const override;

        /** Pose at time t of an object carried from one pose to another while the tool moves from
            toolFrom to toolTo (at toolAt now): its grasp moves linearly between the two ends'
            grasps; the yaw of an object that turnsFreely (Shape::turnsFreely) interpolates on its
            own. */
        static ObjectPose carriedPose(const ObjectPose &from, const ObjectPose &to,
                                      const Eigen::Isometry3d &toolFrom, const Eigen::Isometry3d &toolTo,
                                      const Eigen::Isometry3d &toolAt, double t, bool turnsFreely);

    private:
        /** True when the object moves between from and to and is held at either end. */
        bool isCarried(const ompl::base::State *from, const ompl::base::State *to, unsigned int object) const;

        ManipulationModelPtr model_;
        std::size_t stateBytes_{0};  ///< the size of a state's block (allocState), fixed by the subspaces
    };

    /** Shared ownership of a ManipulationStateSpace, as OMPL passes state spaces around. */
    using ManipulationStateSpacePtr = std::shared_ptr<ManipulationStateSpace>;

    /** space as a ManipulationStateSpace, for a class that works only on one.
        @throws ompl::Exception "<user>: needs a ManipulationStateSpace, got <name>" when it is another. */
    const ManipulationStateSpace *manipulationSpaceOf(const ompl::base::StateSpace *space,
                                                      const std::string &user);
}  // namespace ompl_mm
