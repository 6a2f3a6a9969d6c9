#pragma once

#include "ompl_mm/primitives/Primitive.h"
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
        /** Reads the parameters of spec, which it keeps by reference. @pre spec outlives it. */
        explicit PrimitiveParameters(const PrimitiveSpec &spec);

        /** The value of a parameter, which counts as read; `fallback` when absent.
            @throws ompl_core::InputError when present but not a finite number. */
        double number(const std::string &name, double fallback) const;
        /** The value of a parameter, which counts as read; nothing when absent.
            @throws ompl_core::InputError when present but not a finite number. */
        std::optional<double> optionalNumber(const std::string &name) const;
        /** The value of a required parameter. @throws ompl_core::InputError when absent or malformed. */
        double number(const std::string &name) const;
        /** @throws ompl_core::InputError naming the first parameter that no number() call asked for. */
        void rejectUnread() const;

        /** The primitive's spec as written in the scene. */
        const PrimitiveSpec &spec() const { return spec_; }

    private:
        const PrimitiveSpec &spec_;
        mutable std::vector<std::string> read_;
    };

    /** Builds primitives from the primitives section of a scene. Each type name maps to a builder;
        applications and users can register their own primitive types next to the built-in ones
        ("transit", "push_mobile"). */
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

        /** Builds one primitive per spec, in order; the space must outlive the primitives.
            @throws ompl_core::InputError at the spec's scene line for an unknown type, an unknown or bad
            parameter, or a primitive that does not fit the robot. */
        std::vector<PrimitivePtr> build(const std::vector<PrimitiveSpec> &specs,
                                        const ManipulationStateSpace *space) const;

    private:
        std::map<std::string, Builder> builders_;
    };
}  // namespace ompl_mm
