#pragma once

#include <string>

namespace ompl_core
{
    /** Where a value came from: a file and a line, so that a check made long after reading can
        still name the place of a bad value. No file for values set in code or on the command line. */
    struct SourceLocation
    {
        std::string file;  ///< scene, URDF or config file; empty for values set in code
        int line{0};       ///< 1-based line, 0 when unknown

        /** "file:line", the line written even when it is 0 (InputError leaves it out then). */
        std::string str() const { return file + ":" + std::to_string(line); }
    };
}  // namespace ompl_core
