#pragma once

#include "ompl_mm/primitives/Grasping.h"
#include "ompl_mm/primitives/Primitive.h"

#include <memory>

namespace ompl_mm
{
    /** Transfer-Rigid (MOPL paper, section IV-C; cited at MOPL): the robot carries the object it
        holds, which keeps its pose in the tool frame all along. When the object's target lies on a
        support surface the transfer places it there (IK of the tool that puts it there, its yaw
        free) and the tool retreats along its axis by the approach distance; with a place height,
        the object comes straight down onto its place from that far above it (so that it clears
        the edges it is carried over). Otherwise the robot goes to the target's joints and the
        object to where the grasp takes it (the target's pose when the target holds it the same
        way). */
    class TransferRigid : public Primitive
    {
    public:
        /** A transfer in space solving with `grasping` (shared with Pickup), placing from
            placeHeight metres above the place (0: straight to it).
            @pre space outlives the primitive.
            @throws ompl::Exception when placeHeight is negative or not finite. */
        TransferRigid(const ManipulationStateSpace *space, std::shared_ptr<Grasping> grasping,
                      double placeHeight = 0.0);

        /** How far above its place the object starts its way straight down, metres. */
        double placeHeight() const { return placeHeight_; }

        /** Primitive's hook: useful when some object is held in `from`. */
        bool isUseful(const ompl::base::State *from, const ompl::base::State *to) const override;
        /** Primitive's hook: carries the held object towards its pose in `to` (see the class).
            False when none of Grasping::ATTEMPTS placing solutions has a short retreat, or the
            place is off by more than the grasp tolerance. */
        bool propagate(const ompl::base::State *from, const ompl::base::State *to,
                       Trajectory &trajectory) const override;
        /** Primitive's hook: as above, but stops searching soon after ptc becomes true (between
            inverse kinematics solves): then false, nothing appended, unless a solution was found. */
        bool propagate(const ompl::base::State *from, const ompl::base::State *to, Trajectory &trajectory,
                       const ompl::base::PlannerTerminationCondition &ptc) const override;
        /** Primitive's hook: a transfer segment when exactly one object is held in `from`, no
            other object moves, and it keeps its grasp (Grasping::sameGrasp). */
        std::optional<SegmentLabel> explain(const ompl::base::State *from,
                                            const ompl::base::State *to) const override;
        /** Primitive's hook: the time of the placing inverse kinematics. */
        double inverseKinematicsTime() const override { return grasping_->inverseKinematics().time(); }

    private:
        /** The object held in state, or -1 when none or more than one is. */
        int heldObject(const ompl::base::State *state) const;
        /** Fills solution (its vector 0 holding the seed) with the joints that place an object
            held by `grasp` at `place`, then of the retreat and, with a place height, of the pose
            above the place. False when that fails or ptc is true after the placing solve. */
        bool solvePlace(const Eigen::Isometry3d &grasp, const ObjectPose &place, Grasping::Solution &solution,
                        const ompl::base::PlannerTerminationCondition &ptc) const;

        std::shared_ptr<Grasping> grasping_;
        double placeHeight_;
    };
}  // namespace ompl_mm
