#pragma once

#include "ompl_mm/scene/Scene.h"

#include <string>

namespace ompl_mm
{
    /** Loads a scene file (XML, see docs/scene-format.md); relative paths inside it (the URDF) are
        relative to the file. Checks that need the robot model or collision geometry (joint counts,
        start in collision) are left to ManipulationSetup, which reports the same locations.
        @throws ompl_core::InputError with "file:line: message" on any fault: unknown elements or
        attributes, missing or malformed values, duplicate or unknown names, missing files. */
    Scene loadScene(const std::string &path);

    /** Parses scene XML text as loadScene() does; sourceName names it in messages and baseDir
        resolves relative paths.
        @throws ompl_core::InputError with "sourceName:line: message" on any fault. */
    Scene parseScene(const std::string &xml, const std::string &sourceName, const std::string &baseDir);
}  // namespace ompl_mm
