// Tests for mesh collision geometry in URDF robots: STL and OBJ files (written by the test) are read
// through assimp, scaled, found relative to the URDF, through OMPL_MM_PACKAGE_PATH and the URDF's
// ancestors (package://), read once per file; bad meshes are errors at the URDF's line; and MOBILE
// BLOCKED with a mesh robot collides where the mesh is and is solved.
#include "ompl_mm/robot/RobotModel.h"

#include "common/InputErrors.h"
#include "common/MobileBlocked.h"
#include "common/ScratchDirectory.h"
#include "ompl_mm/scene/SceneLoader.h"
#include "ompl_mm/setup/ManipulationSetup.h"

#include <ompl/base/ScopedState.h>
#include <ompl/base/terminationconditions/IterationTerminationCondition.h>
#include <ompl/util/Console.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

using namespace ompl_mm;
using ompl_core::test::contains;
using ompl_core::test::inputErrorOf;

namespace
{
    namespace fs = std::filesystem;

    /** A unit cube centred at the origin, as ASCII STL (12 triangles). */
    void writeCubeStl(const fs::path &file)
    {
        fs::create_directories(file.parent_path());
        std::ofstream out(file);
        const double c[8][3] = {{-.5, -.5, -.5}, {.5, -.5, -.5}, {.5, .5, -.5}, {-.5, .5, -.5},
                                {-.5, -.5, .5},  {.5, -.5, .5},  {.5, .5, .5},  {-.5, .5, .5}};
        const int faces[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                                  {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
        out << "solid cube\n";
        for (const auto &f : faces)
        {
            out << "facet normal 0 0 0\nouter loop\n";
            for (int k : f)
                out << "vertex " << c[k][0] << " " << c[k][1] << " " << c[k][2] << "\n";
            out << "endloop\nendfacet\n";
        }
        out << "endsolid cube\n";
    }

    /** The same cube as OBJ with quads (assimp splits them into 12 triangles). */
    void writeCubeObj(const fs::path &file)
    {
        fs::create_directories(file.parent_path());
        std::ofstream out(file);
        out << "v -0.5 -0.5 -0.5\nv 0.5 -0.5 -0.5\nv 0.5 0.5 -0.5\nv -0.5 0.5 -0.5\n"
               "v -0.5 -0.5 0.5\nv 0.5 -0.5 0.5\nv 0.5 0.5 0.5\nv -0.5 0.5 0.5\n"
               "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
    }

    /** A mobile base like MOBILE BLOCKED's whose body is the mesh element given (line 20). */
    std::string mobileUrdf(const std::string &meshes)
    {
        return "<?xml version=\"1.0\"?>\n<robot name=\"mesh_disc\">\n  <link name=\"world\"/>\n"
               "  <joint name=\"x\" type=\"prismatic\">\n    <parent link=\"world\"/>\n    <child "
               "link=\"slider\"/>\n"
               "    <axis xyz=\"1 0 0\"/>\n    <limit lower=\"-2.5\" upper=\"2.5\" effort=\"1\" "
               "velocity=\"1\"/>\n"
               "  </joint>\n  <link name=\"slider\"/>\n"
               "  <joint name=\"y\" type=\"prismatic\">\n    <parent link=\"slider\"/>\n    <child "
               "link=\"body\"/>\n"
               "    <axis xyz=\"0 1 0\"/>\n    <limit lower=\"-2.5\" upper=\"2.5\" effort=\"1\" "
               "velocity=\"1\"/>\n"
               "  </joint>\n"
               "  <!-- line 17 -->\n"
               "  <!-- line 18 -->\n"
               "  <!-- line 19 -->\n"
               "  <link name=\"body\">\n" +
               meshes + "  </link>\n</robot>\n";
    }

    std::string collision(const std::string &filename, const std::string &scale, double z = 0.25)
    {
        return "    <collision><origin xyz=\"0 0 " + std::to_string(z) + "\"/><geometry><mesh filename=\"" +
               filename + "\" scale=\"" + scale + "\"/></geometry></collision>\n";
    }

    fs::path writeUrdf(const fs::path &dir, const std::string &text)
    {
        const fs::path file = dir / "robots" / "mesh_disc.urdf";
        fs::create_directories(file.parent_path());
        std::ofstream(file) << text;
        return file;
    }

    class MeshGeometry : public ::testing::Test
    {
    protected:
        void SetUp() override
        {
            dir_ = ompl_core::test::scratchDirectory("ompl_mm_test_MeshGeometry_scratch");
            writeCubeStl(dir_ / "robots" / "meshes" / "cube.stl");
            writeCubeObj(dir_ / "robots" / "meshes" / "cube.obj");
            unsetenv("OMPL_MM_PACKAGE_PATH");
        }
        void TearDown() override { unsetenv("OMPL_MM_PACKAGE_PATH"); }

        fs::path dir_;
    };
}  // namespace

TEST_F(MeshGeometry, RelativeStlAndObjFilesAreReadScaled)
{
    const fs::path urdf = writeUrdf(dir_, mobileUrdf(collision("meshes/cube.stl", "0.4 0.4 0.4") +
                                                     collision("meshes/cube.obj", "0.2 0.3 0.5", 0.8)));
    const RobotModel robot = RobotModel::fromUrdfFile(urdf.string());
    const Link &body = robot.links()[robot.linkIndex("body")];
    ASSERT_EQ(body.shapes.size(), 2u);
    for (const LinkShape &shape : body.shapes)
    {
        ASSERT_EQ(shape.shape.kind, Shape::Kind::Mesh);
        EXPECT_EQ(shape.shape.mesh->triangles.size(), 12u);
    }
    const TriangleMesh &stl = *body.shapes[0].shape.mesh;
    EXPECT_LT((stl.bounds.min() - Eigen::Vector3d(-0.2, -0.2, -0.2)).norm(), 1e-6);
    EXPECT_LT((stl.bounds.max() - Eigen::Vector3d(0.2, 0.2, 0.2)).norm(), 1e-6);
    EXPECT_NEAR(body.shapes[0].shape.height(), 0.4, 1e-6);
    EXPECT_NEAR(body.shapes[0].shape.footprintRadius(), std::sqrt(0.08), 1e-6);
    const TriangleMesh &obj = *body.shapes[1].shape.mesh;
    EXPECT_LT((obj.bounds.max() - Eigen::Vector3d(0.1, 0.15, 0.25)).norm(), 1e-6) << "scaled per axis";
    EXPECT_NEAR(body.shapes[1].shape.boundingRadius(), Eigen::Vector3d(0.1, 0.15, 0.25).norm(), 1e-6);
}

TEST_F(MeshGeometry, AFileUsedTwiceWithOneScaleIsReadOnce)
{
    const fs::path urdf = writeUrdf(
        dir_, mobileUrdf(collision("meshes/cube.stl", "1 1 1") + collision("meshes/cube.stl", "1 1 1", 0.9) +
                         collision("meshes/cube.stl", "2 2 2", 1.5)));
    const RobotModel robot = RobotModel::fromUrdfFile(urdf.string());
    const std::vector<LinkShape> &shapes = robot.links()[robot.linkIndex("body")].shapes;
    ASSERT_EQ(shapes.size(), 3u);
    EXPECT_EQ(shapes[0].shape.mesh.get(), shapes[1].shape.mesh.get());
    EXPECT_NE(shapes[0].shape.mesh.get(), shapes[2].shape.mesh.get());
}

TEST_F(MeshGeometry, PackageUrlsResolveThroughThePackagePathThenTheUrdfsAncestors)
{
    // through OMPL_MM_PACKAGE_PATH: <folder>/<package>/<path>
    writeCubeStl(dir_ / "elsewhere" / "my_robot" / "meshes" / "part.stl");
    const std::string url = collision("package://my_robot/meshes/part.stl", "1 1 1");
    const fs::path urdf = writeUrdf(dir_, mobileUrdf(url));
    EXPECT_TRUE(contains(inputErrorOf([&] { RobotModel::fromUrdfFile(urdf.string()); }), "not found"));
    setenv("OMPL_MM_PACKAGE_PATH", ("/nonexistent:" + (dir_ / "elsewhere").string()).c_str(), 1);
    RobotModel robot = RobotModel::fromUrdfFile(urdf.string());
    EXPECT_EQ(robot.links()[robot.linkIndex("body")].shapes[0].shape.mesh->file,
              (dir_ / "elsewhere" / "my_robot" / "meshes" / "part.stl").string());
    // without it, an ancestor of the URDF named like the package
    unsetenv("OMPL_MM_PACKAGE_PATH");
    writeCubeStl(dir_ / "my_robot" / "meshes" / "part.stl");
    const fs::path inside = dir_ / "my_robot" / "urdf";
    const fs::path file = writeUrdf(inside, mobileUrdf(url));
    robot = RobotModel::fromUrdfFile(file.string());
    EXPECT_EQ(robot.links()[robot.linkIndex("body")].shapes[0].shape.mesh->file,
              (dir_ / "my_robot" / "meshes" / "part.stl").string());
}

TEST_F(MeshGeometry, BadMeshesAreErrorsAtTheLinksLine)
{
    const auto errorFor = [&](const std::string &mesh)
    {
        const fs::path urdf = writeUrdf(dir_, mobileUrdf(mesh));
        return inputErrorOf([&] { RobotModel::fromUrdfFile(urdf.string()); });
    };
    const std::string urdf = (dir_ / "robots" / "mesh_disc.urdf").string();
    const std::string missing = errorFor(collision("meshes/none.stl", "1 1 1"));
    EXPECT_TRUE(
        ompl_core::test::startsWith(missing, urdf + ":20: link 'body': mesh 'meshes/none.stl' not found"))
        << missing;
    EXPECT_TRUE(contains(missing, (dir_ / "robots" / "meshes" / "none.stl").string())) << "where it looked";
    std::ofstream(dir_ / "robots" / "meshes" / "garbage.stl") << "this is no mesh at all\n";
    const std::string garbage = errorFor(collision("meshes/garbage.stl", "1 1 1"));
    EXPECT_TRUE(ompl_core::test::startsWith(garbage, urdf + ":20: link 'body': mesh '")) << garbage;
    EXPECT_TRUE(contains(garbage, "garbage.stl' cannot be read: ")) << garbage;
    EXPECT_EQ(errorFor(collision("meshes/cube.stl", "1 0 1")),
              urdf + ":20: link 'body': mesh 'meshes/cube.stl': scale must be positive, got 1 0 1");
}

TEST_F(MeshGeometry, MobileBlockedWithAMeshRobotCollidesWhereTheMeshIsAndIsSolved)
{
    // the scene's disc replaced by a mesh cube of 0.24 m at the same height (within the pushes'
    // standoff: its bounding sphere, 0.208 m, is as wide as the disc)
    writeUrdf(dir_, mobileUrdf(collision("meshes/cube.stl", "0.24 0.24 0.24")));
    std::ifstream in(std::string(OMPL_MM_SCENES_DIR) + "/mobile_blocked.xml");
    std::string scene((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string disc = "robots/mobile_disc.urdf";
    scene.replace(scene.find(disc), disc.size(), "robots/mesh_disc.urdf");
    std::ofstream(dir_ / "scene.xml") << scene;
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    ManipulationSetup setup(loadScene((dir_ / "scene.xml").string()));
    const ManipulationStateSpace &space = *setup.manipulationSpace();
    ompl::base::ScopedState<> state(setup.getStateSpace());
    space.copyState(state.get(), setup.getProblemDefinition()->getStartState(0));
    EXPECT_TRUE(setup.getSpaceInformation()->isValid(state.get()));
    // block1 spans x [-1.5, -0.5]: the cube's faces are 0.12 m from its centre, a sphere's would be 0.2
    test::setRobot(space, state.get(), -0.4, 0.0);
    EXPECT_FALSE(setup.getSpaceInformation()->isValid(state.get())) << "the cube overlaps block1";
    test::setRobot(space, state.get(), -0.35, 0.0);
    EXPECT_TRUE(setup.getSpaceInformation()->isValid(state.get())) << "clear of block1 and block2";
    setup.mopl()->setSeed(1);
    ASSERT_EQ(setup.solve(ompl::base::IterationTerminationCondition(40000)),
              ompl::base::PlannerStatus::EXACT_SOLUTION);
    EXPECT_TRUE(setup.manipulationPath().check());
}
