#pragma once

#include "ompl_mm/primitives/Primitive.h"
#include "ompl_mm/robot/InverseKinematics.h"
#include "ompl_mm/scene/Scene.h"

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace ompl_mm
{
    /** Reads a primitive's parameters, reporting faults at the primitive's scene line. */
    class PrimitiveParameters
    {
    public:
        /** Reads the parameters of spec, which it keeps by reference, for primitives whose
            inverse kinematics `inverseKinematics` makes (empty: IkSolver).
            @pre spec and inverseKinematics outlive it. */
        explicit PrimitiveParameters(const PrimitiveSpec &spec,
                                     const InverseKinematicsFactory &inverseKinematics = {});

        /** The value of a parameter, which counts as read; `fallback` when absent.
            @throws ompl_core::InputError when present but not a finite number. */
        double number(const std::string &name, double fallback) const;
        /** The value of a parameter, which counts as read; nothing when absent.
            @throws ompl_core::InputError when present but not a finite number. */
        std::optional<double> optionalNumber(const std::string &name) const;
        /** The value of a required parameter. @throws ompl_core::InputError when absent or malformed. */
        double number(const std::string &name) const;
        /** An angle in radians (written in radians, or in degrees with "deg"), which counts as
            read; `fallback` when absent. @throws ompl_core::InputError when present but malformed. */
        double angle(const std::string &name, double fallback) const;
        /** A whole number in [low, high], which counts as read; `fallback` when absent.
            @throws ompl_core::InputError when present but not such a number. */
        unsigned int count(const std::string &name, unsigned int fallback, unsigned int low,
                           unsigned int high) const;
        /** A parameter's text, which counts as read; `fallback` when absent. */
        std::string text(const std::string &name, const std::string &fallback) const;
        /** A parameter that is true or false (also 1 or 0); `fallback` when absent.
            @throws ompl_core::InputError naming the line when it is anything else. */
        bool flag(const std::string &name, bool fallback) const;

        /** Makes the inverse kinematics solvers of the primitives built (empty: IkSolver). */
        const InverseKinematicsFactory &inverseKinematics() const { return inverseKinematics_; }
        /** @throws ompl_core::InputError naming the first parameter that no number() call asked for. */
        void rejectUnread() const;

        /** The primitive's spec as written in the scene. */
        const PrimitiveSpec &spec() const { return spec_; }

    private:
        const PrimitiveSpec &spec_;
        const InverseKinematicsFactory &inverseKinematics_;
        mutable std::vector<std::string> read_;
    };

    /** Builds primitives from the primitives section of a scene. Each type name maps to a builder;
        applications and users can register their own primitive types next to the built-in ones
        ("transit", "push_mobile", "pickup", "transfer_rigid"), and plug in their own inverse
        kinematics for the primitives that need it. */
    class PrimitiveFactory
    {
    public:
        /** Makes one primitive in a space from its parameters; may throw ompl_core::InputError or
            ompl::Exception (reported at the spec's scene line). */
        using Builder =
            std::function<PrimitivePtr(const ManipulationStateSpace *, const PrimitiveParameters &)>;

        /** A factory that knows the built-in primitive types. */
        PrimitiveFactory();

        /** Adds or replaces a primitive type. */
        void registerType(const std::string &type, Builder builder);
        /** The builder of a primitive type (empty when the type is unknown): to wrap it in another. */
        Builder builder(const std::string &type) const;
        /** Makes the primitives' inverse kinematics solvers with factory instead of IkSolver (their
            time still counts as the planner's IK time). */
        void setInverseKinematics(InverseKinematicsFactory factory)
        {
            inverseKinematics_ = std::move(factory);
        }

        /** Builds one primitive per spec, in order; the space must outlive the primitives.
            @throws ompl_core::InputError at the spec's scene line for an unknown type, an unknown or bad
            parameter, or a primitive that does not fit the robot. */
        std::vector<PrimitivePtr> build(const std::vector<PrimitiveSpec> &specs,
                                        const ManipulationStateSpace *space) const;

    private:
        std::map<std::string, Builder> builders_;
        InverseKinematicsFactory inverseKinematics_;
    };
}  // namespace ompl_mm
