#include "ompl_mm/primitives/PrimitiveFactory.h"

#include "ompl_core/io/InputError.h"
#include "ompl_core/io/NumberText.h"
#include "ompl_mm/primitives/ArmPush.h"
#include "ompl_mm/primitives/Pickup.h"
#include "ompl_mm/primitives/PushMobile.h"
#include "ompl_mm/primitives/TransferRigid.h"
#include "ompl_mm/primitives/Transit.h"
#include "ompl_mm/robot/IkSolver.h"

#include <algorithm>
#include <cmath>

namespace ompl_mm
{
    namespace
    {
        /** Inverse kinematics of a grasping primitive: the factory's solver, or an IkSolver with
            the primitive's budget (ik_iterations, ik_restarts); its grasp depth (pickup's). */
        std::shared_ptr<Grasping> makeGrasping(const ManipulationStateSpace *space,
                                               const PrimitiveParameters &params, double tilt,
                                               std::optional<double> depth = std::nullopt)
        {
            Grasping::Settings settings;
            settings.tool = params.text("tool", "");
            settings.tilt = tilt;
            settings.approachDistance = params.number("approach_distance", settings.approachDistance);
            settings.depth = depth;
            const unsigned int iterations = params.count("ik_iterations", 20, 1, 10000);
            const unsigned int restarts = params.count("ik_restarts", 20, 0, 100000);
            const bool anyYaw = params.flag("ik_any_yaw", false);
            InverseKinematicsFactory factory = params.inverseKinematics();
            if (!factory)
                factory =
                    [iterations, restarts, anyYaw](const KinematicChain &chain, const Eigen::Isometry3d &base)
                {
                    auto solver = std::make_unique<IkSolver>(chain, base);
                    solver->iterations = iterations;
                    solver->restarts = restarts;
                    solver->anyYaw = anyYaw;
                    return std::unique_ptr<InverseKinematics>(std::move(solver));
                };
            return std::make_shared<Grasping>(space, settings, factory);
        }

        /** Reads a push's `model`: "kinematic" (the default) is this library's push; "physics",
            a push simulated while planning, is built by ompl_mmphys's factory, not this one.
            @throws ompl_core::InputError at the push's line for any other model. */
        void requireKinematicModel(const PrimitiveParameters &params)
        {
            const std::string model = params.text("model", "kinematic");
            const PrimitiveSpec &spec = params.spec();
            if (model == "physics")
                throw ompl_core::InputError(
                    spec.where, "<" + spec.type +
                                    " model=\"physics\"> simulates every push while planning, which needs "
                                    "the physics library: build the setup with ompl_mmphys's "
                                    "physicsPrimitiveFactory() (ompl_mm_plan, ompl_mm_benchmark and the "
                                    "Python module do)");
            if (model != "kinematic")
                throw ompl_core::InputError(spec.where, "<" + spec.type +
                                                            "> parameter 'model' must be kinematic or "
                                                            "physics, got '" +
                                                            model + "'");
        }

        /** An arm push called type whose hand pose defaults to `hand` (its tilts and turn). */
        PrimitiveFactory::Builder armPush(const std::string &type, ArmPush::Settings hand)
        {
            return [type, hand](const ManipulationStateSpace *space, const PrimitiveParameters &params)
            {
                requireKinematicModel(params);
                ArmPush::Settings settings = hand;
                settings.standoff = params.number("standoff", settings.standoff);
                settings.heightOffset = params.number("height_offset", settings.heightOffset);
                settings.inwardTilt = params.angle("inward_tilt", settings.inwardTilt);
                settings.downwardTilt = params.angle("downward_tilt", settings.downwardTilt);
                settings.handRoll = params.angle("hand_roll", settings.handRoll);
                settings.maxPushDistance = params.number("max_push_distance", settings.maxPushDistance);
                settings.maxPushJointDistance =
                    params.angle("max_push_joint_distance", settings.maxPushJointDistance);
                settings.approachDistance = params.number("approach_distance", settings.approachDistance);
                return std::make_shared<ArmPush>(space, type, makeGrasping(space, params, 0.0), settings);
            };
        }

        /** The hand of a push with its given tilts and roll. */
        ArmPush::Settings hand(double inwardDegrees, double downwardDegrees, double rollDegrees)
        {
            ArmPush::Settings settings;
            settings.inwardTilt = inwardDegrees * M_PI / 180.0;
            settings.downwardTilt = downwardDegrees * M_PI / 180.0;
            settings.handRoll = rollDegrees * M_PI / 180.0;
            return settings;
        }
    }  // namespace

    PrimitiveParameters::PrimitiveParameters(const PrimitiveSpec &spec,
                                             const InverseKinematicsFactory &inverseKinematics)
        : spec_(spec), inverseKinematics_(inverseKinematics)
    {
    }

    double PrimitiveParameters::angle(const std::string &name, double fallback) const
    {
        read_.push_back(name);
        const auto it = spec_.params.find(name);
        if (it == spec_.params.end())
            return fallback;
        const std::optional<double> value = ompl_core::parseAngle(it->second);
        if (!value)
            throw ompl_core::InputError(
                spec_.where, "<" + spec_.type + "> parameter '" + name +
                                 "' must be an angle (radians, or degrees as in 45deg), got '" + it->second +
                                 "'");
        return *value;
    }

    unsigned int PrimitiveParameters::count(const std::string &name, unsigned int fallback, unsigned int low,
                                            unsigned int high) const
    {
        const std::optional<double> value = optionalNumber(name);
        if (!value)
            return fallback;
        if (*value != std::floor(*value) || *value < low || *value > high)
            throw ompl_core::InputError(spec_.where, "<" + spec_.type + "> parameter '" + name +
                                                         "' must be a whole number in [" +
                                                         std::to_string(low) + ", " + std::to_string(high) +
                                                         "], got '" + spec_.params.at(name) + "'");
        return static_cast<unsigned int>(*value);
    }

    bool PrimitiveParameters::flag(const std::string &name, bool fallback) const
    {
        const std::string value = text(name, fallback ? "true" : "false");
        if (value == "true" || value == "1")
            return true;
        if (value == "false" || value == "0")
            return false;
        throw ompl_core::InputError(spec_.where, "<" + spec_.type + "> parameter '" + name +
                                                     "' must be true or false, got '" + value + "'");
    }

    std::string PrimitiveParameters::text(const std::string &name, const std::string &fallback) const
    {
        read_.push_back(name);
        const auto it = spec_.params.find(name);
        return it == spec_.params.end() ? fallback : it->second;
    }

    double PrimitiveParameters::number(const std::string &name, double fallback) const
    {
        return optionalNumber(name).value_or(fallback);
    }

    std::optional<double> PrimitiveParameters::optionalNumber(const std::string &name) const
    {
        read_.push_back(name);
        const auto it = spec_.params.find(name);
        if (it == spec_.params.end())
            return std::nullopt;
        std::size_t used = 0;
        double value = 0.0;
        try
        {
            value = std::stod(it->second, &used);
        }
        catch (const std::exception &)
        {
            used = 0;
        }
        if (used == 0 || used != it->second.size() || !std::isfinite(value))
            throw ompl_core::InputError(spec_.where, "<" + spec_.type + "> parameter '" + name +
                                                         "' must be a finite number, got '" + it->second +
                                                         "'");
        return value;
    }

    double PrimitiveParameters::number(const std::string &name) const
    {
        if (spec_.params.count(name) == 0)
            throw ompl_core::InputError(spec_.where,
                                        "<" + spec_.type + "> needs the parameter '" + name + "'");
        return number(name, 0.0);
    }

    void PrimitiveParameters::rejectUnread() const
    {
        for (const auto &[name, value] : spec_.params)
            if (std::find(read_.begin(), read_.end(), name) == read_.end())
                throw ompl_core::InputError(spec_.where,
                                            "unknown parameter '" + name + "' for <" + spec_.type + ">");
    }

    PrimitiveFactory::PrimitiveFactory()
    {
        registerType("transit", [](const ManipulationStateSpace *space, const PrimitiveParameters &)
                     { return std::make_shared<Transit>(space); });
        registerType("push_mobile",
                     [](const ManipulationStateSpace *space, const PrimitiveParameters &params)
                     {
                         requireKinematicModel(params);
                         return std::make_shared<PushMobile>(space, params.optionalNumber("standoff"));
                     });
        // the hands of the MOPL paper's KUKA scenes
        registerType("push_interior", armPush("push_interior", hand(0.0, 65.0, 0.0)));
        registerType("push_exterior", armPush("push_exterior", hand(0.0, 65.0, 180.0)));
        registerType("push_frontal", armPush("push_frontal", hand(30.0, 0.0, 0.0)));
        registerType(
            "pickup",
            [](const ManipulationStateSpace *space, const PrimitiveParameters &params)
            {
                Pickup::Settings settings;
                settings.liftHeight = params.number("lift_height", settings.liftHeight);
                settings.minPlaneDistance = params.number("min_plane_distance", settings.minPlaneDistance);
                return std::make_shared<Pickup>(space,
                                                makeGrasping(space, params, params.angle("grasp_tilt", 0.0),
                                                             params.optionalNumber("grasp_depth")),
                                                settings);
            });
        registerType("transfer_rigid",
                     [](const ManipulationStateSpace *space, const PrimitiveParameters &params)
                     {
                         return std::make_shared<TransferRigid>(space, makeGrasping(space, params, 0.0),
                                                                params.number("place_height", 0.0));
                     });
    }

    void PrimitiveFactory::registerType(const std::string &type, Builder builder)
    {
        builders_[type] = std::move(builder);
    }

    PrimitiveFactory::Builder PrimitiveFactory::builder(const std::string &type) const
    {
        const auto it = builders_.find(type);
        return it == builders_.end() ? Builder() : it->second;
    }

    std::vector<PrimitivePtr> PrimitiveFactory::build(const std::vector<PrimitiveSpec> &specs,
                                                      const ManipulationStateSpace *space) const
    {
        std::vector<PrimitivePtr> primitives;
        for (const PrimitiveSpec &spec : specs)
        {
            const auto it = builders_.find(spec.type);
            if (it == builders_.end())
            {
                std::string known;
                for (const auto &entry : builders_)
                    known += (known.empty() ? "" : ", ") + entry.first;
                throw ompl_core::InputError(spec.where,
                                            "unknown primitive <" + spec.type + "> (known: " + known + ")");
            }
            const PrimitiveParameters params(spec, inverseKinematics_);
            try
            {
                primitives.push_back(it->second(space, params));
            }
            catch (const ompl_core::InputError &)
            {
                throw;
            }
            catch (const ompl::Exception &e)
            {
                throw ompl_core::InputError(spec.where, e.what());
            }
            params.rejectUnread();
        }
        return primitives;
    }
}  // namespace ompl_mm
