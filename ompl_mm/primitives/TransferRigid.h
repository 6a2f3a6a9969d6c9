#pragma once

#include "ompl_mm/primitives/Grasping.h"
#include "ompl_mm/primitives/Primitive.h"

#include <memory>

namespace ompl_mm
{
    /** Transfer-Rigid (MOPL paper, section IV-C; cited at MOPL): the robot carries the object it
        holds, which keeps its pose in the tool frame all along. When the object's target lies on a
        support surface the transfer places it there (IK of the tool that puts it there, its yaw
        free) and the tool retreats along its axis by the approach distance; otherwise the robot
        goes to the target's joints and the object to where the grasp takes it (the target's pose
        when the target holds it the same way). */
    class TransferRigid : public Primitive
    {
    public:
        /** A transfer in space solving with `grasping` (shared with Pickup).
            @pre space outlives the primitive. */
        TransferRigid(const ManipulationStateSpace *space, std::shared_ptr<Grasping> grasping);

        /** Primitive's hook: useful when some object is held in `from`. */
        bool isUseful(const ompl::base::State *from, const ompl::base::State *to) const override;
        /** Primitive's hook: carries the held object towards its pose in `to` (see the class).
            False when none of Grasping::ATTEMPTS placing solutions has a short retreat, or the
            place is off by more than the grasp tolerance. */
        bool propagate(const ompl::base::State *from, const ompl::base::State *to,
                       Trajectory &trajectory) const override;
        /** Primitive's hook: a transfer segment when exactly one object is held in `from`, no
            other object moves, and it keeps its grasp (Grasping::sameGrasp). */
        std::optional<SegmentLabel> explain(const ompl::base::State *from,
                                            const ompl::base::State *to) const override;
        /** Primitive's hook: the time of the placing inverse kinematics. */
        double inverseKinematicsTime() const override { return grasping_->inverseKinematics().time(); }

    private:
        /** The object held in state, or -1 when none or more than one is. */
        int heldObject(const ompl::base::State *state) const;

        std::shared_ptr<Grasping> grasping_;
    };
}  // namespace ompl_mm
