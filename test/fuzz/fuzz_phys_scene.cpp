// Fuzz target: a physics scene's XML, read as ompl_phys_plan reads it (parsed, the ODE world and the
// control setup built from it).
#include "FuzzInput.h"
#include "ompl_phys/control/PhysicsSetup.h"
#include "ompl_phys/scene/PhysicsSceneLoader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    fuzz::readOrReject(
        [&]
        {
            const ompl_phys::PhysicsSetup setup(
                ompl_phys::parsePhysicsScene(fuzz::inputText(data, size), "fuzz.xml"));
        });
    return 0;
}
