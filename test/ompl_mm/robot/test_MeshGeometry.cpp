// Tests for mesh collision geometry in URDF robots: STL, OBJ and COLLADA files (written by the test)
// are read through assimp, scaled (COLLADA z up, in its unit), found relative to the URDF, through
// OMPL_MM_PACKAGE_PATH and the URDF's ancestors (package://), read once per file; bad meshes are
// errors at the URDF's line; MOBILE BLOCKED with a mesh robot collides where the mesh is and is
// solved; the scene's meshes="convex_hull" fills a concave link's notch, exact meshes leave it free, and
// their answers (checked through their hulls first) are the triangles' own.
#include "ompl_mm/robot/RobotModel.h"

#include "common/InputErrors.h"
#include "common/MobileBlocked.h"
#include "common/MoplIterations.h"
#include "common/ScratchDirectory.h"
#include "ompl_mm/collision/CollisionWorld.h"
#include "ompl_mm/scene/SceneLoader.h"
#include "ompl_mm/setup/ManipulationSetup.h"

#include <ompl/base/ScopedState.h>
#include <ompl/util/Console.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

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

    /** An L-shaped prism as ASCII STL: the square [-1, 1]^2 without its quadrant x, y > 0 (the
        notch), for z in [-0.5, 0.5]; 20 triangles, outward. */
    void writeLPrismStl(const fs::path &file)
    {
        fs::create_directories(file.parent_path());
        const double outline[6][2] = {{-1, -1}, {1, -1}, {1, 0},
                                      {0, 0},   {0, 1},  {-1, 1}};  // counter-clockwise
        std::vector<std::array<Eigen::Vector3d, 3>> triangles;
        const auto corner = [&](int i, double z)
        { return Eigen::Vector3d(outline[i % 6][0], outline[i % 6][1], z); };
        for (int i : {4, 5, 0, 1})  // a fan from the reflex corner 3 (the L is star-shaped about it)
        {
            triangles.push_back({corner(3, 0.5), corner(i, 0.5), corner(i + 1, 0.5)});
            triangles.push_back({corner(3, -0.5), corner(i + 1, -0.5), corner(i, -0.5)});
        }
        for (int i = 0; i < 6; ++i)
        {
            triangles.push_back({corner(i, -0.5), corner(i + 1, -0.5), corner(i + 1, 0.5)});
            triangles.push_back({corner(i, -0.5), corner(i + 1, 0.5), corner(i, 0.5)});
        }
        std::ofstream out(file);
        out << "solid l\n";
        for (const auto &t : triangles)
        {
            out << "facet normal 0 0 0\nouter loop\n";
            for (const Eigen::Vector3d &v : t)
                out << "vertex " << v.x() << " " << v.y() << " " << v.z() << "\n";
            out << "endloop\nendfacet\n";
        }
        out << "endsolid l\n";
    }

    /** A flat square plate (z = 0) as ASCII STL: 2 triangles. */
    void writePlateStl(const fs::path &file)
    {
        fs::create_directories(file.parent_path());
        std::ofstream(file)
            << "solid plate\nfacet normal 0 0 1\nouter loop\nvertex -1 -1 0\nvertex 1 -1 0\n"
               "vertex 1 1 0\nendloop\nendfacet\nfacet normal 0 0 1\nouter loop\nvertex -1 -1 0\n"
               "vertex 1 1 0\nvertex -1 1 0\nendloop\nendfacet\nendsolid plate\n";
    }

    /** A box of half sizes half (in the file's unit) as COLLADA, z up, with the given unit in
        metres: one geometry of 12 triangles on 8 positions, instanced by a node of a visual scene. */
    std::string boxDae(const Eigen::Vector3d &half, double meter)
    {
        std::ostringstream positions;
        for (int i : {0, 1, 3, 2, 4, 5, 7, 6})  // counter-clockwise about z, bottom then top
            positions << (i & 1 ? 1 : -1) * half.x() << " " << (i & 2 ? 1 : -1) * half.y() << " "
                      << (i & 4 ? 1 : -1) * half.z() << " ";
        return "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
               "<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">\n"
               "  <asset><unit name=\"unit\" meter=\"" +
               std::to_string(meter) +
               "\"/><up_axis>Z_UP</up_axis></asset>\n"
               "  <library_geometries>\n"
               "    <geometry id=\"box-mesh\" name=\"box\">\n"
               "      <mesh>\n"
               "        <source id=\"box-positions\">\n"
               "          <float_array id=\"box-positions-array\" count=\"24\">" +
               positions.str() +
               "</float_array>\n"
               "          <technique_common>\n"
               "            <accessor source=\"#box-positions-array\" count=\"8\" stride=\"3\">\n"
               "              <param name=\"X\" type=\"float\"/><param name=\"Y\" type=\"float\"/>"
               "<param name=\"Z\" type=\"float\"/>\n"
               "            </accessor>\n"
               "          </technique_common>\n"
               "        </source>\n"
               "        <vertices id=\"box-vertices\"><input semantic=\"POSITION\" "
               "source=\"#box-positions\"/></vertices>\n"
               "        <triangles count=\"12\">\n"
               "          <input semantic=\"VERTEX\" source=\"#box-vertices\" offset=\"0\"/>\n"
               "          <p>0 2 1 0 3 2 4 5 6 4 6 7 0 1 5 0 5 4 1 2 6 1 6 5 2 3 7 2 7 6 3 0 4 3 4 7</p>\n"
               "        </triangles>\n"
               "      </mesh>\n"
               "    </geometry>\n"
               "  </library_geometries>\n"
               "  <library_visual_scenes>\n"
               "    <visual_scene id=\"scene\" name=\"scene\">\n"
               "      <node id=\"box\" name=\"box\"><instance_geometry url=\"#box-mesh\"/></node>\n"
               "    </visual_scene>\n"
               "  </library_visual_scenes>\n"
               "  <scene><instance_visual_scene url=\"#scene\"/></scene>\n"
               "</COLLADA>\n";
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

    /** MOBILE BLOCKED with the robot of robots/mesh_disc.urdf, attributes added to <robot>, and
        a 2 cm cube obstacle "peg" at (0.54, 1.54, 0.25), clear of everything else; written as
        dir/scene.xml, whose path it returns. */
    fs::path pegScene(const fs::path &dir, const std::string &attributes)
    {
        std::ifstream in(std::string(OMPL_MM_SCENES_DIR) + "/mobile_blocked.xml");
        std::string scene((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        const std::string robot = "<robot urdf=\"robots/mobile_disc.urdf\"";
        scene.replace(scene.find(robot), robot.size(), "<robot urdf=\"robots/mesh_disc.urdf\" " + attributes);
        const std::string floor = "  <!-- the floor";
        scene.insert(scene.find(floor),
                     "  <obstacle name=\"peg\"><origin xyz=\"0.54 1.54 0.25\"/>"
                     "<box size=\"0.02 0.02 0.02\"/></obstacle>\n");
        std::ofstream(dir / "scene.xml") << scene;
        return dir / "scene.xml";
    }

    /** Validity of the robot at (x, y) (objects at their start), and of the straight motion from
        (x, y) to (x2, y2), by the setup's checkers. */
    class RobotProbe
    {
    public:
        explicit RobotProbe(ManipulationSetup &setup)
            : setup_(setup), from_(setup.getStateSpace()), to_(setup.getStateSpace())
        {
            space().copyState(from_.get(), setup.getProblemDefinition()->getStartState(0));
            space().copyState(to_.get(), from_.get());
        }

        bool valid(double x, double y)
        {
            test::setRobot(space(), from_.get(), x, y);
            return setup_.getSpaceInformation()->isValid(from_.get());
        }

        bool motionValid(double x, double y, double x2, double y2)
        {
            test::setRobot(space(), from_.get(), x, y);
            test::setRobot(space(), to_.get(), x2, y2);
            return setup_.getSpaceInformation()->checkMotion(from_.get(), to_.get());
        }

    private:
        const ManipulationStateSpace &space() const { return *setup_.manipulationSpace(); }

        ManipulationSetup &setup_;
        ompl::base::ScopedState<> from_;
        ompl::base::ScopedState<> to_;
    };

    /** The line of the first line of text that contains part (1-based). */
    int lineOf(const fs::path &file, const std::string &part)
    {
        std::ifstream in(file);
        std::string line;
        for (int number = 1; std::getline(in, line); ++number)
            if (contains(line, part))
                return number;
        return 0;
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
    ASSERT_EQ(setup.solve(test::moplIterations(setup, 40000)), ompl::base::PlannerStatus::EXACT_SOLUTION);
    EXPECT_TRUE(setup.manipulationPath().check());
}

TEST_F(MeshGeometry, ConvexHullsFillAConcaveLinksNotchWhereExactMeshesLeaveItFree)
{
    // the L spans x, y in [-0.12, 0.12] and z in [0.19, 0.31] about the robot, but for its notch
    // x, y > 0; its hull also holds the notch's part with x + y <= 0.12
    writeLPrismStl(dir_ / "robots" / "meshes" / "l.stl");
    writeUrdf(dir_, mobileUrdf(collision("meshes/l.stl", "0.12 0.12 0.12")));
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    for (const std::string meshes : {"", "meshes=\"exact\"", "meshes=\"convex_hull\""})
    {
        SCOPED_TRACE(meshes);
        const Scene scene = loadScene(pegScene(dir_, meshes).string());
        const bool hull = meshes == "meshes=\"convex_hull\"";
        EXPECT_EQ(scene.robot.meshCollision, hull ? MeshCollision::ConvexHull : MeshCollision::Exact);
        const RobotModel robot = RobotModel::fromUrdfFile(scene.robot.urdfFile);
        const TriangleMesh &mesh = *robot.links()[robot.linkIndex("body")].shapes[0].shape.mesh;
        EXPECT_EQ(mesh.convexHull()->vertices.size(), 10u) << "the L's 12 corners but the notch's two";
        EXPECT_LT(mesh.convexHull()->vertices.size(), mesh.vertices.size());
        ManipulationSetup setup(scene);
        RobotProbe probe(setup);
        // the peg 3-5 cm deep in the notch (at x, y in [0.03, 0.05] about the robot), 3 cm from the L
        EXPECT_EQ(probe.valid(0.5, 1.5), !hull);
        EXPECT_EQ(probe.valid(0.51, 1.51), !hull);
        EXPECT_EQ(probe.motionValid(0.5, 1.5, 0.51, 1.51), !hull) << "and along the way";
        // the peg through the L's wall at x = -0.12; wholly inside the L, where only the hull is
        // solid (an exact mesh is its triangles, a surface); clear of the hull
        EXPECT_FALSE(probe.valid(0.66, 1.6));
        EXPECT_EQ(probe.valid(0.64, 1.64), !hull);
        EXPECT_TRUE(probe.valid(0.5, 1.3));
        EXPECT_FALSE(probe.motionValid(0.5, 1.3, 0.64, 1.64)) << "through the L's wall";
    }
}

TEST_F(MeshGeometry, AMeshesAttributeOtherThanExactOrConvexHullIsAnErrorAtItsLine)
{
    writeUrdf(dir_, mobileUrdf(collision("meshes/cube.stl", "0.24 0.24 0.24")));
    const fs::path file = pegScene(dir_, "meshes=\"hull\"");
    const std::string error = inputErrorOf([&] { loadScene(file.string()); });
    EXPECT_EQ(error, file.string() + ":" + std::to_string(lineOf(file, "<robot urdf=")) +
                         ": attribute 'meshes' of <robot> must be \"exact\" or \"convex_hull\", got 'hull'");
}

TEST_F(MeshGeometry, AFlatMeshHasNoConvexHullAndSaysSoAtTheScenesRobot)
{
    writePlateStl(dir_ / "robots" / "meshes" / "plate.stl");
    writeUrdf(dir_, mobileUrdf(collision("meshes/plate.stl", "0.1 0.1 0.1")));
    const fs::path file = pegScene(dir_, "meshes=\"convex_hull\"");
    const Scene scene = loadScene(file.string());
    const std::string error = inputErrorOf([&] { CollisionWorld world(test::makeModel(scene)); });
    const std::string mesh = (dir_ / "robots" / "meshes" / "plate.stl").string();
    EXPECT_TRUE(ompl_core::test::startsWith(
        error, file.string() + ":" + std::to_string(lineOf(file, "<robot urdf=")) +
                   ": robot link 'body': mesh '" + mesh + "': convex hull: the "))
        << error;
    EXPECT_TRUE(contains(error, "points are coplanar")) << error;
    EXPECT_TRUE(contains(error, "meshes=\"exact\"")) << "the way out: " << error;
    // exact, the plate is a mesh like any other
    EXPECT_NO_THROW(CollisionWorld(test::makeModel(loadScene(pegScene(dir_, "").string()))));
}

TEST_F(MeshGeometry, ColladaMeshesAreReadZUpInTheirUnitAndCollideWhereTheyAre)
{
    // a box 0.1 x 0.2 x 0.3 m, once in metres and once in half metres (assimp would turn z up
    // into y up and swap the box's y and z sizes)
    std::ofstream(dir_ / "robots" / "meshes" / "box.dae") << boxDae(Eigen::Vector3d(0.05, 0.1, 0.15), 1.0);
    std::ofstream(dir_ / "robots" / "meshes" / "box_half_metres.dae")
        << boxDae(Eigen::Vector3d(0.1, 0.2, 0.3), 0.5);
    for (const std::string name : {"box.dae", "box_half_metres.dae"})
    {
        SCOPED_TRACE(name);
        const fs::path urdf = writeUrdf(dir_, mobileUrdf(collision("meshes/" + name, "1 1 1")));
        const RobotModel robot = RobotModel::fromUrdfFile(urdf.string());
        const Shape &shape = robot.links()[robot.linkIndex("body")].shapes[0].shape;
        ASSERT_EQ(shape.kind, Shape::Kind::Mesh);
        EXPECT_EQ(shape.mesh->triangles.size(), 12u);
        EXPECT_LT((shape.mesh->bounds.max() - Eigen::Vector3d(0.05, 0.1, 0.15)).norm(), 1e-6);
        EXPECT_LT((shape.mesh->bounds.min() + Eigen::Vector3d(0.05, 0.1, 0.15)).norm(), 1e-6);
        EXPECT_NEAR(shape.height(), 0.3, 1e-6);
        EXPECT_NEAR(shape.footprintRadius(), std::hypot(0.05, 0.1), 1e-6);
    }
    // the box (z in [0.1, 0.4] about the robot) against the peg (x, y in [0.53, 0.55]), as
    // triangles and as its hull (the same box)
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    for (const std::string meshes : {"", "meshes=\"convex_hull\""})
    {
        SCOPED_TRACE(meshes);
        ManipulationSetup setup(loadScene(pegScene(dir_, meshes).string()));
        RobotProbe probe(setup);
        EXPECT_TRUE(probe.valid(0.47, 1.54)) << "x up to 0.52";
        EXPECT_FALSE(probe.valid(0.49, 1.54)) << "x up to 0.54";
        EXPECT_TRUE(probe.valid(0.54, 1.42)) << "y up to 1.52";
        EXPECT_FALSE(probe.valid(0.54, 1.44)) << "y up to 1.54";
        EXPECT_FALSE(probe.motionValid(0.47, 1.54, 0.54, 1.42)) << "past the peg's corner";
    }
}

TEST_F(MeshGeometry, MalformedColladaIsAnErrorAtTheLinksLineNamingTheFile)
{
    const std::string valid = boxDae(Eigen::Vector3d(0.05, 0.1, 0.15), 1.0);
    std::string badIndex = valid;
    badIndex.replace(badIndex.find("<p>0 2 1"), 8, "<p>0 2 9");
    for (const auto &[name, text] :
         {std::pair<std::string, std::string>{"truncated.dae", valid.substr(0, 700)},
          {"bad_index.dae", badIndex}})
    {
        SCOPED_TRACE(name);
        const fs::path mesh = dir_ / "robots" / "meshes" / name;
        std::ofstream(mesh) << text;
        const fs::path urdf = writeUrdf(dir_, mobileUrdf(collision("meshes/" + name, "1 1 1")));
        const std::string error = inputErrorOf([&] { RobotModel::fromUrdfFile(urdf.string()); });
        const std::string prefix =
            urdf.string() + ":20: link 'body': mesh '" + mesh.string() + "' cannot be read: ";
        EXPECT_TRUE(ompl_core::test::startsWith(error, prefix)) << error;
        EXPECT_GT(error.size(), prefix.size()) << "with assimp's reason";
    }
}

TEST_F(MeshGeometry, ColladaThatAssimpWouldMisreadIsAnErrorAtItsLine)
{
    // assimp 5.2's COLLADA reader never stops on a letter in an index list (filling the memory),
    // crashes on an array without a count or of count 0 with values and on short strips, aborts on
    // primitives without their <p>, and reads past an array's end for an accessor or a count
    // larger than the array
    const std::string valid = boxDae(Eigen::Vector3d(0.05, 0.1, 0.15), 1.0);
    const auto at = [&valid](const std::string &text)
    {
        const std::string before = valid.substr(0, valid.find(text));
        return "line " + std::to_string(1 + std::count(before.begin(), before.end(), '\n')) + ": ";
    };
    const std::string array = "<float_array id=\"box-positions-array\" count=\"24\">";
    const std::string accessor = "<accessor source=\"#box-positions-array\" count=\"8\"";
    const std::string head = valid.substr(0, valid.find("<COLLADA"));
    const std::string indices =
        valid.substr(valid.find("<p>0 2 1"), valid.find("</p>") + 4 - valid.find("<p>0 2 1"));
    const std::string triangles =
        valid.substr(valid.find("<triangles"), valid.find("</triangles>") + 12 - valid.find("<triangles"));
    const std::string input = "<input semantic=\"VERTEX\" source=\"#box-vertices\" offset=\"0\"/>";
    // what is replaced, by what, and the message
    const std::vector<std::array<std::string, 3>> cases = {
        {"<p>0 2 1", "<p>0 2 2.5", at("<p>0 2 1") + "<p> holds '2.5', not a whole number"},
        {"<p>0 2 1", "<p>0 2 x", at("<p>0 2 1") + "<p> holds 'x', not a whole number"},
        {"<p>0 2 1", "<p>0 2 1e3", at("<p>0 2 1") + "<p> holds '1e3', not a whole number"},
        {array, "<float_array id=\"box-positions-array\" count=\"0\">",
         at(array) + "<float_array> count=\"0\" but it holds 24 values"},
        {array, "<float_array id=\"box-positions-array\" count=\"1x\">",
         at(array) + "<float_array> count=\"1x\" is not a count"},
        {array, "<float_array id=\"box-positions-array\">",
         at(array) + "<float_array> has no count (COLLADA requires it)"},
        {accessor, "<accessor source=\"#box-positions-array\" count=\"9\"",
         at(accessor) + "<accessor> reads 27 values of 'box-positions-array', which holds 24"},
        {indices, "", at("<triangles") + "<triangles> of count 12 has 0 <p>, not one"},
        {triangles, "<tristrips count=\"1\">" + input + "<p>0 2</p></tristrips>",
         at("<triangles") + "<p> holds 2 indices: not 3 vertices or more of 1 each"},
        {triangles, "<polygons count=\"2\">" + input + "<p>0 2 1</p></polygons>",
         at("<triangles") + "<polygons> count=\"2\" but it has 1 <p>"},
        {valid, "<!-- no element -->", "no <COLLADA> element"},
        {valid, head + "<collada/>", at("<COLLADA") + "<collada> is not <COLLADA>"}};
    for (const auto &[text, replacement, message] : cases)
    {
        SCOPED_TRACE(replacement.substr(0, 60));
        std::string bad = valid;
        bad.replace(bad.find(text), text.size(), replacement);
        const fs::path mesh = dir_ / "robots" / "meshes" / "misread.dae";
        std::ofstream(mesh) << bad;
        const fs::path urdf = writeUrdf(dir_, mobileUrdf(collision("meshes/misread.dae", "1 1 1")));
        EXPECT_EQ(
            inputErrorOf([&] { RobotModel::fromUrdfFile(urdf.string()); }),
            urdf.string() + ":20: link 'body': mesh '" + mesh.string() + "' cannot be read: " + message);
    }
}

TEST_F(MeshGeometry, ExactMeshAnswersAreTheTrianglesOwnAroundTheNotch)
{
    // the checks go through the L's hull first; their answers must be those of the triangles
    // themselves, which FCL gives here directly
    writeLPrismStl(dir_ / "robots" / "meshes" / "l.stl");
    writeUrdf(dir_, mobileUrdf(collision("meshes/l.stl", "0.12 0.12 0.12")));
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    ManipulationSetup setup(loadScene(pegScene(dir_, "").string()));
    RobotProbe probe(setup);
    const RobotModel &robot = setup.manipulationSpace()->model()->robot();
    const TriangleMesh &mesh = *robot.links()[robot.linkIndex("body")].shapes[0].shape.mesh;
    auto triangles = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
    std::vector<fcl::Triangle> faces;
    for (const std::array<int, 3> &t : mesh.triangles)
        faces.emplace_back(t[0], t[1], t[2]);
    triangles->beginModel();
    triangles->addSubModel(mesh.vertices, faces);
    triangles->endModel();
    fcl::CollisionObjectd body(triangles);
    fcl::CollisionObjectd peg(std::make_shared<fcl::Boxd>(0.02, 0.02, 0.02));
    peg.setTranslation(Eigen::Vector3d(0.54, 1.54, 0.25));
    peg.computeAABB();
    const auto trianglesFree = [&](double x, double y)
    {
        body.setTranslation(Eigen::Vector3d(x, y, 0.25));
        body.computeAABB();
        fcl::CollisionRequestd request;
        fcl::CollisionResultd result;
        return fcl::collide(&body, &peg, request, result) == 0;
    };
    int free = 0, blocked = 0;
    for (int i = 0; i <= 20; ++i)
        for (int j = 0; j <= 20; ++j)
        {
            const double x = 0.38 + 0.016 * i, y = 1.38 + 0.016 * j;
            const bool expected = trianglesFree(x, y);
            ASSERT_EQ(probe.valid(x, y), expected) << x << " " << y;
            (expected ? free : blocked) += 1;
        }
    EXPECT_GT(free, 50);
    EXPECT_GT(blocked, 50);
    // motions: one it accepts is free at every millimetre; one it refuses meets the peg
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> around(0.38, 0.70);
    int accepted = 0, refused = 0;
    for (int trial = 0; trial < 200; ++trial)
    {
        const double x1 = around(rng), y1 = around(rng) + 1.0, x2 = around(rng), y2 = around(rng) + 1.0;
        if (!trianglesFree(x1, y1) || !trianglesFree(x2, y2))
            continue;
        const int samples = 1 + static_cast<int>(1000.0 * std::hypot(x2 - x1, y2 - y1));
        bool alongFree = true;
        for (int k = 0; k <= samples; ++k)
        {
            const double t = static_cast<double>(k) / samples;
            alongFree = alongFree && trianglesFree(x1 + t * (x2 - x1), y1 + t * (y2 - y1));
        }
        const bool motion = probe.motionValid(x1, y1, x2, y2);
        if (motion)
            EXPECT_TRUE(alongFree) << x1 << " " << y1 << " -> " << x2 << " " << y2;
        else if (alongFree)
            ADD_FAILURE() << "refused a free motion " << x1 << " " << y1 << " -> " << x2 << " " << y2
                          << " (it may only graze the peg by micrometres)";
        (motion ? accepted : refused) += 1;
    }
    EXPECT_GT(accepted, 20);
    EXPECT_GT(refused, 20);
}
