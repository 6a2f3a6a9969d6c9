/* Reads a physics scene file (XML, see docs/scene-format.md, "Physics scenes") into a
   PhysicsScene. Every error names the file and line: unknown elements or attributes, missing or
   malformed values, out-of-range parameters, duplicate names, a constraint on a body that is not
   constraint-oriented, a robot start or goal outside the robot's region. */
#pragma once

#include "ompl_phys/scene/PhysicsScene.h"

#include <string>

namespace ompl_phys
{
    /** Loads a physics scene file. @throws ompl_core::InputError with "file:line: message". */
    PhysicsScene loadPhysicsScene(const std::string &path);

    /** Parses physics scene XML text; sourceName names it in messages.
        @throws ompl_core::InputError with "sourceName:line: message". */
    PhysicsScene parsePhysicsScene(const std::string &xml, const std::string &sourceName);
}  // namespace ompl_phys
