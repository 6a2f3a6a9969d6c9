/* The exception for bad user input (scene files, URDF files, parameters): its message starts
   with "file:line: " when the place is known, so a user can jump to the fault. */
#pragma once

#include "ompl_mm/scene/Scene.h"

#include <ompl/util/Exception.h>

#include <string>

namespace ompl_mm
{
    class InputError : public ompl::Exception
    {
    public:
        /** where.file empty: the message stands alone; line 0: "file: message". */
        InputError(const SourceLocation &where, const std::string &message);
        explicit InputError(const std::string &message);
    };
}  // namespace ompl_mm
