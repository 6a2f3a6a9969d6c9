// Fuzz target: a robot's URDF, read as a scene's robot is (joints, mimics, collision shapes and
// meshes). The text is read as if it were a file beside the shipped Panda, so its mesh file names
// (the Panda's OBJ meshes among them) resolve as they do for that robot.
#include "FuzzInput.h"
#include "ompl_mm/robot/RobotModel.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    fuzz::readOrReject(
        [&]
        {
            ompl_mm::RobotModel::fromUrdfString(fuzz::inputText(data, size),
                                                OMPL_MM_SCENES_DIR "/robots/panda/franka_panda/fuzz.urdf");
        });
    return 0;
}
