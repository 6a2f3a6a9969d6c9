// A fuzz target for the two scene loaders: any input either loads or is rejected with an
// ompl_core::InputError; anything else (another exception, a crash, a sanitizer report, a hang) is a
// defect. Linked with scene_fuzz_driver.cpp, which mutates the shipped scenes for a fixed time; its
// entry point is libFuzzer's (see docs/architecture.md).
#include "ompl_core/io/InputError.h"
#include "ompl_mm/scene/SceneLoader.h"
#include "ompl_phys/scene/PhysicsSceneLoader.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const std::string xml(reinterpret_cast<const char *>(data), size);
    try
    {
        // the scene's URDF is resolved against this folder; the shipped robots are there
        ompl_mm::parseScene(xml, "fuzz.xml", OMPL_MM_SCENES_DIR);
    }
    catch (const ompl_core::InputError &)
    {
    }
    try
    {
        ompl_phys::parsePhysicsScene(xml, "fuzz.xml");
    }
    catch (const ompl_core::InputError &)
    {
    }
    return 0;
}
