#pragma once

#include "ompl_mm/setup/ManipulationSetup.h"

#include <ostream>

namespace ompl_mm
{
    /** Writes a top-down SVG picture of the setup's scene and, when given, its solution: obstacles
        and support surfaces, objects at the start (outlined) and at the end of the path (filled),
        the goals, the tool's path coloured by primitive, and pushes drawn as arrows. path may be
        null (scene only). @throws ompl::Exception when the setup has no start state. */
    void writeSceneSvg(std::ostream &out, const ManipulationSetup &setup, const ManipulationPath *path);
}  // namespace ompl_mm
