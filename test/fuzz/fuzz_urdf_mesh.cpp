// Fuzz target: a mesh file a URDF names, read through assimp. The first byte picks the file's kind
// ('s' STL, 'o' OBJ, 'd' COLLADA; any other byte by its value), the rest is the file: it is written
// to a scratch folder beside a one-link URDF whose collision geometry names it.
#include "FuzzInput.h"
#include "ompl_mm/robot/RobotModel.h"

#include <array>

namespace
{
    const char *extensionOf(std::uint8_t selector)
    {
        switch (selector)
        {
            case 's':
                return "stl";
            case 'o':
                return "obj";
            case 'd':
                return "dae";
            default:
                return std::array<const char *, 3>{"stl", "obj", "dae"}[selector % 3];
        }
    }
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    if (size == 0)
        return 0;
    const std::string mesh = std::string("fuzz.") + extensionOf(data[0]);
    fuzz::writeScratchFile(mesh, fuzz::inputText(data + 1, size - 1));
    const std::string urdf = R"(<robot name="mesh"><link name="base"><collision><geometry>)"
                             R"(<mesh filename=")" +
                             mesh + R"(" scale="0.5 1 2"/></geometry></collision></link></robot>)";
    fuzz::readOrReject(
        [&] { ompl_mm::RobotModel::fromUrdfString(urdf, (fuzz::scratchFolder() / "mesh.urdf").string()); });
    return 0;
}
