#pragma once

#include "ompl_core/io/SourceLocation.h"

#include <ompl/base/Planner.h>

#include <string>
#include <vector>

namespace ompl_core
{
    /** One planner parameter value as the user wrote it, in a scene file or on the command line.
        Settings are applied through OMPL's ParamSet (applyParameters()): the one way by which any
        declared parameter of any planner is set, with errors that name where the setting came
        from. */
    struct ParameterSetting
    {
        std::string name;      ///< a parameter declared by the planner (OMPL's declareParam)
        std::string value;     ///< its value as text, converted by OMPL's ParamSet
        SourceLocation where;  ///< the scene file line, or {"command line option --param", 0}
    };

    /** Reads "NAME=VALUE" given to the command-line option --param; the value may be empty or hold
        further '='.
        @throws InputError when there is no '=' or the name is empty. */
    ParameterSetting parseParameterOption(const std::string &text);

    /** Sets each parameter on planner, in order (later settings win). Before OMPL converts a
        value, it is checked against the parameter's type and declared range: a number must be a
        finite decimal ("0x10", "inf" and "nan" are not), a parameter of an integer type takes whole
        numbers within its type ("-1" does not wrap, "1.5" is not truncated), a boolean takes 0, 1,
        true or false, and a value must lie within the range suggestion "LOW:STEP:HIGH" or
        "LOW:HIGH" (bounds included), or be one of the values of a list "A,B,C".
        @throws InputError naming a setting's place for an unknown name (listing the planner's
        parameters) or a value that fails these checks or that the planner rejects (with the
        parameter's range when it has one). */
    void applyParameters(ompl::base::Planner &planner, const std::vector<ParameterSetting> &settings);

    /** The planner's declared parameters as "name = value (range)" in name order, with their
        current values, for help texts; the range is left out when the planner suggests none. */
    std::vector<std::string> describeParameters(const ompl::base::Planner &planner);
}  // namespace ompl_core
