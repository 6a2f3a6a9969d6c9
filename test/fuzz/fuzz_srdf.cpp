// Fuzz target: a robot's SRDF, read as the shipped Panda scene reads its own (groups, end effectors,
// disabled pairs, named states, fixed joints) against the Panda's URDF: the input is written as the
// scene's SRDF file and the scene's robot loaded.
#include "FuzzInput.h"
#include "ompl_mm/scene/SceneLoader.h"
#include "ompl_mm/setup/SceneRobot.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    static const ompl_mm::Scene pandaScene = []
    {
        ompl_mm::Scene scene = ompl_mm::loadScene(OMPL_MM_SCENES_DIR "/panda_table.xml");
        scene.robot.srdfFile = (fuzz::scratchFolder() / "panda.srdf").string();
        return scene;
    }();
    fuzz::writeScratchFile("panda.srdf", fuzz::inputText(data, size));
    fuzz::readOrReject([&] { ompl_mm::loadSceneRobot(pandaScene); });
    return 0;
}
