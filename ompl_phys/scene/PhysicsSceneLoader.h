#pragma once

#include "ompl_phys/scene/PhysicsScene.h"

#include <string>

namespace ompl_phys
{
    /** Reads a physics scene file (XML, see docs/scene-format.md, "Physics scenes") into a
        PhysicsScene whose file is path. Every error names the file and line: unknown elements or
        attributes, missing or malformed values, out-of-range parameters, duplicate names, a
        constraint on a body that is not constraint-oriented, a robot start or goal outside the
        robot's region.
        @throws ompl_core::InputError with "file:line: message", also when the file is missing or
        unreadable. */
    PhysicsScene loadPhysicsScene(const std::string &path);

    /** Parses physics scene XML text with the checks of loadPhysicsScene(); sourceName names it in
        messages and becomes the scene's file.
        @throws ompl_core::InputError with "sourceName:line: message". */
    PhysicsScene parsePhysicsScene(const std::string &xml, const std::string &sourceName);
}  // namespace ompl_phys
