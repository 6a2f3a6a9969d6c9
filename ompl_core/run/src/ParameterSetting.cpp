#include "ompl_core/run/ParameterSetting.h"

#include "ompl_core/io/InputError.h"
#include "ompl_core/io/TextFormat.h"

namespace ompl_core
{
    namespace
    {
        const char *const COMMAND_LINE = "command line option --param";
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
            std::string why;
            try
            {
                accepted = params.setParam(setting.name, setting.value);
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
