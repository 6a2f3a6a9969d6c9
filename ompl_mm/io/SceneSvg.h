/* Top-down SVG picture of a manipulation scene and, when given, its solution: obstacles and
   support surfaces, objects at the start (outlined) and at the end of the path (filled), the
   tool's path coloured by primitive, and pushes drawn as arrows. */
#pragma once

#include "ompl_mm/setup/ManipulationSetup.h"

#include <ostream>

namespace ompl_mm
{
    /** Writes the picture; path may be null (scene only). */
    void writeSceneSvg(std::ostream &out, const ManipulationSetup &setup, const ManipulationPath *path);
}  // namespace ompl_mm
