#pragma once

#include "ompl_mm/primitives/Grasping.h"
#include "ompl_mm/primitives/Primitive.h"

#include <memory>

namespace ompl_mm
{
    /** Pickup (MOPL paper, section IV-C; cited at MOPL): an arm takes an object off its support
        surface. Grasp IK above the object (Grasping: the yaw free, the scene's grasp tilt), a
        transit to the approach pose short of it, the approach along the tool's axis, then the lift
        by the lift height with the object in the hand. */
    class Pickup : public Primitive
    {
    public:
        /** What a pickup does besides the grasp. */
        struct Settings
        {
            double liftHeight{0.1};        ///< how far the object is lifted, metres
            double minPlaneDistance{0.2};  ///< the least move in the plane that asks for a pickup, metres
        };

        /** A pickup in space grasping as `grasping` says (shared with other primitives, such as
            TransferRigid). @pre space outlives the primitive.
            @throws ompl::Exception when the lift height is not positive or the plane distance is
            negative. */
        Pickup(const ManipulationStateSpace *space, std::shared_ptr<Grasping> grasping, Settings settings);

        /** Primitive's hook: useful when every object rests in `from` and some object must rise:
            it is held in `to`, rests at another height, or moves more than minPlaneDistance in
            the plane. */
        bool isUseful(const ompl::base::State *from, const ompl::base::State *to) const override;
        /** Primitive's hook: picks up the qualifying object nearest to the tool: a transit to the
            approach pose (left out when the robot is there), a transit along the approach to the
            grasp, and a pickup segment lifting the object. False when none of Grasping::ATTEMPTS
            grasp solutions has both. */
        bool propagate(const ompl::base::State *from, const ompl::base::State *to,
                       Trajectory &trajectory) const override;
        /** Primitive's hook: as above, but stops searching soon after ptc becomes true (between
            inverse kinematics solves): then false, nothing appended, unless a solution was found. */
        bool propagate(const ompl::base::State *from, const ompl::base::State *to, Trajectory &trajectory,
                       const ompl::base::PlannerTerminationCondition &ptc) const override;
        /** Primitive's hook: a pickup segment when every object rests in `from`, exactly one
            moves, it is held in `to`, and it keeps its grasp (Grasping::sameGrasp). */
        std::optional<SegmentLabel> explain(const ompl::base::State *from,
                                            const ompl::base::State *to) const override;
        /** Primitive's hook: the time of the grasp's inverse kinematics. */
        double inverseKinematicsTime() const override { return grasping_->inverseKinematics().time(); }

        /** Sets the robot's joints in state (seeded by them) so that the tool grasps the object
            where state has it, as for a sample of an object in the air; the object's pose stays.
            False, state unchanged, when no grasp IK is found. */
        bool grasp(ompl::base::State *state, unsigned int object) const;

        /** The settings in force. */
        const Settings &settings() const { return settings_; }

    private:
        /** True when every object but `object` keeps its pose from a to b. */
        bool othersStay(const ompl::base::State *a, const ompl::base::State *b, unsigned int object) const;
        /** True when the object must be picked up to go from its pose in from to its pose in to. */
        bool mustRise(const ompl::base::State *from, const ompl::base::State *to, unsigned int object) const;

        std::shared_ptr<Grasping> grasping_;
        Settings settings_;
    };
}  // namespace ompl_mm
