/* A push whose outcome ODE decides while planning: the scene's model="physics" on a push primitive. */
#pragma once

#include "ompl_mm/primitives/Primitive.h"
#include "ompl_mmphys/simulation/PhysicsCheck.h"

#include <functional>
#include <vector>

namespace ompl_mmphys
{
    /** A physics-aware push: the robot moves as a kinematic push primitive (PushMobile, ArmPush)
        would move it, but where the object goes is simulated in a PlanWorld that holds the robot,
        the pushed object and the static scene, with the same rules as the check of a whole plan
        (MotionExecution), so the tree holds the object where physics puts it, not where the push
        line says. After each push the tool backs away (the kinematic push's own retreat, or
        `retreat` metres back along the push) and the world settles; while the object is farther
        than `precision` from its target, the push is corrected from where the object lies, at
        most `corrections` times. A push ends before the object slides around the pusher farther
        than `slip` from the tool's heading (simulated again, ending at the waypoint before). A push
        that tips the object over or pushes it off its surface fails. The waypoints along a push
        are recorded every `sampleSpacing` metres of tool travel, the object kept at least the
        kinematic standoff from the tool point (it touches the robot in the simulation, which the
        collision checks would not allow), so that collision checks see its real track; at the
        end, the tool backed away, the object lies exactly where the simulation left it. Its
        motions do not end where asked (endsWhereAsked() is false); explain() accepts the
        segments it made (and pieces of them) and no other. Not thread-safe. */
    class PhysicsPush : public ompl_mm::Primitive
    {
    public:
        /** How pushes are simulated and corrected. */
        struct Settings
        {
            SimulationSettings simulation;  ///< as the whole plan's check simulates
            double precision{0.005};        ///< metres: pushing stops this near the target
            double maxPushDistance{10.0};   ///< metres: longest single push before re-aiming
            unsigned int corrections{3};    ///< pushes beyond those maxPushDistance needs
            double sampleSpacing{0.1};      ///< metres of tool travel between recorded waypoints
            double retreat{0.02};           ///< metres the tool backs away, when the push does not
            /** radians from upright at the end beyond which a push fails: the check's tolerance */
            double tilt{CheckTolerances{}.tilt};
            /** radians: how far the object may slide around the pusher, from the tool's heading
                (seen from the tool point, in the plane); the push ends before it slides farther,
                where what physics makes of it would no longer be repeatable */
            double slip{M_PI / 4.0};
            /** radians from upright that the object may tilt at any time during a push: a push
                that rocks it farther fails, since where a rocking object lands is not repeatable */
            double rock{M_PI / 18.0};
        };

        /** Simulates the pushes of `kinematic`, whose tool point stands `standoff(object)` metres
            from an object's axis while it pushes. @pre space outlives the primitive.
            @throws ompl::Exception when a distance in settings is not positive. */
        PhysicsPush(const ompl_mm::ManipulationStateSpace *space, ompl_mm::PrimitivePtr kinematic,
                    std::function<double(unsigned int)> standoff, const Settings &settings);

        /** Primitive's hook: as the kinematic push. */
        bool isUseful(const ompl::base::State *from, const ompl::base::State *to) const override;
        /** Primitive's hook: pushes and corrects (see the class) without a time limit. */
        bool propagate(const ompl::base::State *from, const ompl::base::State *to,
                       ompl_mm::Trajectory &trajectory) const override;
        /** Primitive's hook: pushes and corrects (see the class); stops correcting once ptc is true. */
        bool propagate(const ompl::base::State *from, const ompl::base::State *to,
                       ompl_mm::Trajectory &trajectory,
                       const ompl::base::PlannerTerminationCondition &ptc) const override;
        /** Primitive's hook: the label of a segment this primitive made, or of a piece of one. */
        std::optional<ompl_mm::SegmentLabel> explain(const ompl::base::State *from,
                                                     const ompl::base::State *to) const override;
        /** Primitive's hook: the kinematic push's inverse kinematics time. */
        double inverseKinematicsTime() const override { return kinematic_->inverseKinematicsTime(); }
        /** Primitive's hook: false, physics decides where the object ends. */
        bool endsWhereAsked() const override { return false; }
        /** Primitive's hook: the kinematic push it simulates. */
        ompl_mm::PrimitivePtr kinematicModel() const override { return kinematic_; }
        /** Primitive's hook: the checker goes to the kinematic push too (its inverse kinematics). */
        void setStateValidityChecker(ompl::base::StateValidityCheckerPtr checker) override;

        /** Seconds spent simulating since the primitive was made. */
        double simulationTime() const { return simulationTime_; }
        /** Pushes simulated since the primitive was made. */
        unsigned long simulations() const { return simulations_; }

    private:
        /** A segment this primitive made: its ends' values (copyToReals) and label. */
        struct Made
        {
            std::vector<double> from, to;
            ompl_mm::SegmentLabel label;
        };

        /** What one push came to. */
        enum class Outcome
        {
            Pushed,      ///< the push, simulated, is appended
            Cut,         ///< the push, ended early where the object began to slide off, is appended
            Approached,  ///< only the valid part of the way to the push start is appended
            Failed       ///< nothing is appended
        };
        /** One push (the kinematic push's motion, cut where a state turns invalid, simulated) from
            `from` towards `to`, appended to trajectory. */
        Outcome pushOnce(const ompl::base::State *from, const ompl::base::State *to,
                         ompl_mm::Trajectory &trajectory,
                         const ompl::base::PlannerTerminationCondition &ptc) const;
        /** Where a simulated push left its object. */
        struct SimulatedPush
        {
            std::vector<ompl_mm::ObjectPose> poses;  ///< per waypoint
            double tilt{0.0};                        ///< radians from upright at the end
            double maxTilt{0.0};                     ///< radians from upright, the most on the way
        };
        /** Simulates the robot along waypoints (a push from its start, labelled push) with the
            objects where `from` has them, only the pushed one in the world. */
        SimulatedPush simulate(const std::vector<ompl::base::State *> &waypoints,
                               const ompl::base::State *from, ompl_mm::SegmentLabel push) const;
        /** The first of waypoints 1 … pushEnd at which the object, at poses, lies more than
            Settings::slip from the tool's heading, or 0. */
        std::size_t slipWaypoint(const std::vector<ompl::base::State *> &waypoints,
                                 const std::vector<ompl_mm::ObjectPose> &poses, std::size_t pushEnd) const;
        /** A new state: end with the tool backed away `retreat` metres towards before (at most to
            before). */
        ompl::base::State *retreatFrom(const ompl::base::State *before, const ompl::base::State *end) const;
        /** The part of motion whose states the validity checker accepts (checked every
            CHECK_SPACING metres of tool travel), as the planner's walk would keep it: nothing
            beyond an invalid state is worth simulating. */
        ompl_mm::Trajectory reachablePart(const ompl_mm::Trajectory &motion) const;
        /** Keeps object at least its standoff from the tool point in state (moving it away from the
            tool point in the plane). */
        void keepStandoff(ompl::base::State *state, unsigned int object) const;
        /** Appends state to trajectory with label (and whether other motions may start there),
            remembering the segment. */
        void appendMade(ompl_mm::Trajectory &trajectory, const ompl::base::State *state,
                        ompl_mm::SegmentLabel label, bool branchable) const;
        /** True when from and to lie on made, from before to (pieces of it, as interpolation
            makes them). */
        bool liesOn(const Made &made, const std::vector<double> &from, const std::vector<double> &to) const;

        ompl_mm::PrimitivePtr kinematic_;
        std::function<double(unsigned int)> standoff_;
        Settings settings_;
        mutable std::vector<std::vector<Made>> made_;  ///< per object pushed
        mutable double simulationTime_{0.0};
        mutable unsigned long simulations_{0};
    };
}  // namespace ompl_mmphys
