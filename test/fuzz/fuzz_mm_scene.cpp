// Fuzz target: a manipulation scene's XML, read as ompl_mm_plan reads it (parsed, its robot's URDF
// and SRDF loaded, the setup wired with its primitives and problem checks). Relative file names in
// the scene resolve against the shipped scenes' folder, so inputs can name the shipped robots.
#include "FuzzInput.h"
#include "ompl_mm/scene/SceneLoader.h"
#include "ompl_mm/setup/ManipulationSetup.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    fuzz::readOrReject(
        [&]
        {
            const ompl_mm::ManipulationSetup setup(
                ompl_mm::parseScene(fuzz::inputText(data, size), "fuzz.xml", OMPL_MM_SCENES_DIR));
        });
    return 0;
}
