#pragma once

#include "ompl_core/io/SourceLocation.h"

#include <ompl/util/Exception.h>

#include <string>

namespace ompl_core
{
    /** The exception for bad user input (scene files, URDF files, parameters, command lines): its
        message starts with "file:line: " when the place is known, so a user can jump to the fault.
        An ompl::Exception, so code that catches OMPL's exceptions catches it too. */
    class InputError : public ompl::Exception
    {
    public:
        /** The message is prefixed with "file:line: ", or "file: " when where.line is 0, or nothing
            when where.file is empty. */
        InputError(const SourceLocation &where, const std::string &message);

        /** A message that names no file (for a command-line option, say). */
        explicit InputError(const std::string &message);

        /** Where the fault is: file and line, or an empty file when it names none. */
        const SourceLocation &where() const { return where_; }

    private:
        SourceLocation where_;
    };
}  // namespace ompl_core
