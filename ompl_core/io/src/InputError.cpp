#include "ompl_core/io/InputError.h"

namespace ompl_core
{
    namespace
    {
        std::string located(const SourceLocation &where, const std::string &message)
        {
            if (where.file.empty())
                return message;
            if (where.line <= 0)
                return where.file + ": " + message;
            return where.str() + ": " + message;
        }
    }  // namespace

    InputError::InputError(const SourceLocation &where, const std::string &message)
        : ompl::Exception(located(where, message)), where_(where)
    {
    }

    InputError::InputError(const std::string &message) : ompl::Exception(message) {}
}  // namespace ompl_core
