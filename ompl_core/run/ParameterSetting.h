/* Planner parameters set by a user, from a scene file or the command line, applied through OMPL's
   ParamSet: the one way by which any declared parameter of any planner is set, with errors that
   name where the setting came from. */
#pragma once

#include "ompl_core/io/SourceLocation.h"

#include <ompl/base/Planner.h>

#include <string>
#include <vector>

namespace ompl_core
{
    /** One parameter value as the user wrote it. */
    struct ParameterSetting
    {
        std::string name;      ///< a parameter declared by the planner (OMPL's declareParam)
        std::string value;     ///< its value as text, converted by OMPL's ParamSet
        SourceLocation where;  ///< the scene file line, or {"command line option --param", 0}
    };

    /** Reads "NAME=VALUE" given to the command-line option --param.
        @throws InputError when there is no '=' or the name is empty. */
    ParameterSetting parseParameterOption(const std::string &text);

    /** Sets each parameter on planner, in order (later settings win).
        @throws InputError naming a setting's place for an unknown name (listing the planner's
        parameters) or a value the planner rejects. */
    void applyParameters(ompl::base::Planner &planner, const std::vector<ParameterSetting> &settings);

    /** The planner's declared parameters as "name (range)" in name order, for help texts. */
    std::vector<std::string> describeParameters(const ompl::base::Planner &planner);
}  // namespace ompl_core
