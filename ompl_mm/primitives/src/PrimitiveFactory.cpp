#include "ompl_mm/primitives/PrimitiveFactory.h"

#include "ompl_core/io/InputError.h"
#include "ompl_mm/primitives/PushMobile.h"
#include "ompl_mm/primitives/Transit.h"

#include <algorithm>
#include <cmath>

namespace ompl_mm
{
    PrimitiveParameters::PrimitiveParameters(const PrimitiveSpec &spec) : spec_(spec) {}

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
        registerType("push_mobile", [](const ManipulationStateSpace *space, const PrimitiveParameters &params)
                     { return std::make_shared<PushMobile>(space, params.optionalNumber("standoff")); });
    }

    void PrimitiveFactory::registerType(const std::string &type, Builder builder)
    {
        builders_[type] = std::move(builder);
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
            const PrimitiveParameters params(spec);
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
