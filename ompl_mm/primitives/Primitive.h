#pragma once

#include "ompl_mm/primitives/Trajectory.h"

#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/base/StateValidityChecker.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>

namespace ompl_mm
{
    class Primitive;
    /** Shared ownership of a primitive: the setup, the planner and its empty-space planner hold the
        same primitives. */
    using PrimitivePtr = std::shared_ptr<Primitive>;

    /** A manipulation primitive in the sense of the MOPL paper (Definition III.1): given a start and
        a target configuration it says whether it applies (isUseful, cheap, no inverse kinematics)
        and, if so, produces waypoints from the start towards the target (propagate), ignoring
        obstacles. The empty-space planner chains primitives; collisions are checked afterwards.
        Shared through PrimitivePtr; not copyable. */
    class Primitive
    {
    public:
        /** A primitive called name, of the given kind, in space. @pre space outlives the primitive. */
        Primitive(const ManipulationStateSpace *space, std::string name, PrimitiveKind kind);
        /** Subclasses are destroyed through this base. */
        virtual ~Primitive() = default;
        Primitive(const Primitive &) = delete;             ///< not copyable
        Primitive &operator=(const Primitive &) = delete;  ///< not copyable

        /** The primitive's name, e.g. "transit". */
        const std::string &name() const { return name_; }
        /** The kind of action it performs; its main segments carry this kind. */
        PrimitiveKind kind() const { return kind_; }

        /** True when the primitive can move from `from` towards `to`. */
        virtual bool isUseful(const ompl::base::State *from, const ompl::base::State *to) const = 0;

        /** Appends waypoints that move from trajectory.back() (which equals from) towards `to`.
            Returns false, appending nothing, when the primitive cannot act (e.g. no IK). */
        virtual bool propagate(const ompl::base::State *from, const ompl::base::State *to,
                               Trajectory &trajectory) const = 0;
        /** As propagate(from, to, trajectory), but stops searching soon after ptc becomes true
            (then false, nothing appended, unless it has found its motion already): so a planner's
            time limit reaches into the primitive's own search (inverse kinematics attempts).
            EmptySpacePlanner calls this one. The default ignores ptc, which suits primitives whose
            propagation is quick (no inverse kinematics, no collision checks: Transit, PushMobile);
            primitives that search override it and implement the other overload with a condition
            that never ends. */
        virtual bool propagate(const ompl::base::State *from, const ompl::base::State *to,
                               Trajectory &trajectory,
                               const ompl::base::PlannerTerminationCondition &ptc) const
        {
            static_cast<void>(ptc);
            return propagate(from, to, trajectory);
        }

        /** The label of a segment this primitive could have made from `from` to `to` (straight
            interpolation in the manipulation space), or nothing when its motion cannot move
            things that way, e.g. an object moving with no push or grasp. Motion checks and path
            relabelling (ManipulationMotionValidator) ask each primitive in turn; collisions are
            not its concern. */
        virtual std::optional<SegmentLabel> explain(const ompl::base::State *from,
                                                    const ompl::base::State *to) const = 0;

        /** Why the primitive last turned a state of its own down (e.g. "robot link 'hand' and object
            'cyl1' collide"), or "" when it has not since the last call; clears it. A planner asks
            after a propagate that found no motion (PrimitiveTally). */
        std::string takeRejection() const { return std::exchange(rejection_, std::string()); }

        /** Seconds the primitive has spent in inverse kinematics since it was made (0 for those
            that need none); planners report it (MOPL's time_ik_s). */
        virtual double inverseKinematicsTime() const { return 0.0; }

        /** True (the default) when propagate's motions put what they move exactly at the target's
            values, as kinematic primitives do; false for a primitive whose outcome a simulation
            decides (a physics-aware push). MOPL's goal tree, whose motions must end exactly at its
            vertices, leaves such primitives out, and the empty-space planner takes where they
            leave an object as that object's target from then on. */
        virtual bool endsWhereAsked() const { return true; }
        /** For a primitive that does not end where asked, the kinematic primitive whose motions it
            simulates, for questions a simulation cannot answer cheaply (can the goal be reached at
            all?); nullptr for the others, which are their own model. */
        virtual PrimitivePtr kinematicModel() const { return nullptr; }

        /** Lets the primitive turn down inverse kinematics solutions whose states `checker` finds
            invalid (say, the arm folded into itself) and try another, so that the waypoints it
            makes are worth connecting; obstacles along its motions stay the connect step's
            concern. Without a checker (the default) every solution is accepted. */
        virtual void setStateValidityChecker(ompl::base::StateValidityCheckerPtr checker)
        {
            checker_ = std::move(checker);
        }

    protected:
        /** True when every object rests on a support surface in state. */
        bool allObjectsRest(const ompl::base::State *state) const;
        /** True when `holds` is true for some object. */
        bool anyObject(const std::function<bool(unsigned int)> &holds) const;
        /** Of the objects for which `qualifies` is true, the one nearest to the tool in state (the
            first of equals), or -1 when none qualifies: the object a primitive acts on when
            several could be (MOPL's rule). */
        int nearestToTool(const ompl::base::State *state,
                          const std::function<bool(unsigned int)> &qualifies) const;
        /** True when a push could go from a to b: every object rests in both and some object
            slides between them (moves in x, y only, as a push moves it). */
        bool pushable(const ompl::base::State *a, const ompl::base::State *b) const;
        /** Of the objects that slide from a to b, the one nearest to the tool in a (the object a
            push acts on), or -1 when none slides. */
        int nearestSlidingObject(const ompl::base::State *a, const ompl::base::State *b) const;
        /** The object a push from a to b moves: every object rests at both ends, exactly one moves,
            and it slides (slides()) keeping its yaw; -1 when that is not so. */
        int onlySlidingObject(const ompl::base::State *a, const ompl::base::State *b) const;

        /** Keeps why the primitive turned a motion down, for takeRejection(). */
        void rejectBecause(std::string why) const { rejection_ = std::move(why); }
        /** True when no checker is set or the checker finds state valid; otherwise keeps why for
            takeRejection(). */
        bool acceptable(const ompl::base::State *state) const;

        const ManipulationStateSpace *space_;  ///< the space the primitive plans in, not owned

    private:
        /** True when the object slides on its surface from a to b: it moves in x, y only (its
            height the same within 1e-9 m), as a push moves it. */
        bool slides(const ompl::base::State *a, const ompl::base::State *b, unsigned int object) const;

        std::string name_;
        PrimitiveKind kind_;
        ompl::base::StateValidityCheckerPtr checker_;
        mutable std::string rejection_;  ///< see takeRejection()
    };

}  // namespace ompl_mm
