#include "ompl_core/run/ParameterSetting.h"

#include "ompl_core/io/InputError.h"
#include "ompl_core/io/NumberText.h"
#include "ompl_core/io/TextFormat.h"

#include <ompl/base/GenericParam.h>

#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

namespace ompl_core
{
    namespace
    {
        const char *const COMMAND_LINE = "command line option --param";

        template <typename T>
        bool holds(const ompl::base::GenericParam &param)
        {
            return dynamic_cast<const ompl::base::SpecificParam<T> *>(&param) != nullptr;
        }

        /** The whole numbers a parameter of an integer type can take, or nothing for another type. */
        std::optional<std::pair<double, double>> integerLimits(const ompl::base::GenericParam &param)
        {
            const auto limits = [](auto value)
            {
                using T = decltype(value);
                return std::make_pair(static_cast<double>(std::numeric_limits<T>::min()),
                                      static_cast<double>(std::numeric_limits<T>::max()));
            };
            if (holds<int>(param))
                return limits(int());
            if (holds<unsigned int>(param))
                return limits(0u);
            if (holds<long>(param))
                return limits(0L);
            if (holds<unsigned long>(param))
                return limits(0UL);
            if (holds<long long>(param))
                return limits(0LL);
            if (holds<unsigned long long>(param))
                return limits(0ULL);
            return std::nullopt;
        }

        /** The parts of OMPL's range suggestion "LOW:STEP:HIGH", "LOW:HIGH" or "A,B,C". */
        std::vector<std::string> split(const std::string &text, char separator)
        {
            std::vector<std::string> parts;
            std::stringstream stream(text);
            for (std::string part; std::getline(stream, part, separator);)
                parts.push_back(part);
            return parts;
        }

        /** What is wrong with value as text for param, checked before OMPL converts it (OMPL's
            conversion wraps "-1" to a huge unsigned, reads "1.5" as 1 and accepts "inf"), or ""
            when it is fine; the text OMPL gets is left in normalised. */
        std::string valueProblem(const ompl::base::GenericParam &param, const std::string &value,
                                 std::string &normalised)
        {
            normalised = value;
            const std::string &range = param.getRangeSuggestion();
            if (holds<bool>(param))
            {
                if (value == "true" || value == "false")
                    normalised = value == "true" ? "1" : "0";
                return normalised == "0" || normalised == "1" ? "" : "must be 0 or 1 (or true/false)";
            }
            if (holds<std::string>(param))
                return "";
            const std::optional<double> number = parseNumber(value);
            if (!number)
                return "not a finite decimal number";
            if (const auto limits = integerLimits(param))
            {
                if (*number != std::floor(*number))
                    return "must be a whole number";
                if (*number < limits->first || *number > limits->second)
                    return "out of the range of its type";
                std::ostringstream whole;
                whole << static_cast<long long>(*number);
                normalised = whole.str();
            }
            if (range.find(',') != std::string::npos)
            {
                for (const std::string &allowed : split(range, ','))
                    if (parseNumber(allowed) == number)
                        return "";
                return "must be one of " + range;
            }
            const std::vector<std::string> bounds = split(range, ':');
            if (bounds.size() == 2 || bounds.size() == 3)
            {
                const std::optional<double> low = parseNumber(bounds.front()),
                                            high = parseNumber(bounds.back());
                if (low && high && (*number < *low || *number > *high))
                    return "out of range";
            }
            return "";
        }
    }  // namespace

    ParameterSetting parseParameterOption(const std::string &text)
    {
        const std::size_t equals = text.find('=');
        if (equals == std::string::npos || equals == 0)
            throw InputError(SourceLocation{COMMAND_LINE, 0}, "expected NAME=VALUE, got '" + text + "'");
        return {text.substr(0, equals), text.substr(equals + 1), SourceLocation{COMMAND_LINE, 0}};
    }

    void applyParameters(ompl::base::Planner &planner, const std::vector<ParameterSetting> &settings)
    {
        ompl::base::ParamSet &params = planner.params();
        for (const ParameterSetting &setting : settings)
        {
            if (!params.hasParam(setting.name))
            {
                std::vector<std::string> names;
                params.getParamNames(names);
                throw InputError(setting.where, "unknown parameter '" + setting.name + "' of planner " +
                                                    planner.getName() + " (known: " + joinedNames(names) +
                                                    ")");
            }
            bool accepted = false;
            std::string normalised;
            std::string why = valueProblem(params[setting.name], setting.value, normalised);
            if (!why.empty())
                why = ": " + why;
            else
                try
                {
                    accepted = params.setParam(setting.name, normalised);
                }
                catch (const std::exception &e)  // setters and OMPL's string conversion throw
                {
                    why = std::string(": ") + e.what();
                }
            if (!accepted)
            {
                const std::string &range = params[setting.name].getRangeSuggestion();
                throw InputError(setting.where, "bad value '" + setting.value + "' for parameter '" +
                                                    setting.name + "' of planner " + planner.getName() +
                                                    (range.empty() ? "" : " (range " + range + ")") + why);
            }
        }
    }

    std::vector<std::string> describeParameters(const ompl::base::Planner &planner)
    {
        std::vector<std::string> described;
        for (const auto &[name, param] : planner.params().getParams())
        {
            const std::string &range = param->getRangeSuggestion();
            described.push_back(name + " = " + param->getValue() +
                                (range.empty() ? "" : " (range " + range + ")"));
        }
        return described;
    }
}  // namespace ompl_core
