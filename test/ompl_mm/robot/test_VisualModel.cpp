// Tests for VisualModel: a URDF (written by the test) with visual boxes, cylinders, spheres and an OBJ
// mesh of two materials gives each link its shapes, origins and colours (the .mtl's per material, else
// the URDF material's, named or inline); a file used twice is read once; a missing visual mesh falls
// back to the link's collision shapes with a warning naming file:line, as a link without <visual>
// does silently; bad visuals are errors at their line; the shipped Franka Panda reads whole.
#include "ompl_mm/robot/VisualModel.h"

#include "common/InputErrors.h"
#include "common/ScratchDirectory.h"

#include <ompl/util/Console.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

using namespace ompl_mm;
using ompl_core::test::contains;
using ompl_core::test::inputErrorOf;

namespace
{
    namespace fs = std::filesystem;

    const char *const COLLISION = "<collision><geometry><box size=\"0.1 0.1 0.1\"/></geometry></collision>";

    /** A unit cube as OBJ: its bottom (z = -0.5) in material "dark", the rest in "light" (the .mtl's
        Kd colours), so the file reads as two parts of 2 and 10 triangles. */
    void writeTwoMaterialCube(const fs::path &folder)
    {
        std::ofstream mtl(folder / "cube.mtl");
        mtl << "newmtl dark\nKd 0.25 0.25 0.25\nnewmtl light\nKd 1.0 0.5 0.0\n";
        std::ofstream obj(folder / "cube.obj");
        obj << "mtllib cube.mtl\n"
               "v -0.5 -0.5 -0.5\nv 0.5 -0.5 -0.5\nv 0.5 0.5 -0.5\nv -0.5 0.5 -0.5\n"
               "v -0.5 -0.5 0.5\nv 0.5 -0.5 0.5\nv 0.5 0.5 0.5\nv -0.5 0.5 0.5\n"
               "usemtl dark\nf 1 4 3 2\n"
               "usemtl light\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
    }

    /** The same cube without materials. */
    void writePlainCube(const fs::path &folder)
    {
        std::ofstream obj(folder / "plain.obj");
        obj << "v -0.5 -0.5 -0.5\nv 0.5 -0.5 -0.5\nv 0.5 0.5 -0.5\nv -0.5 0.5 -0.5\n"
               "v -0.5 -0.5 0.5\nv 0.5 -0.5 0.5\nv 0.5 0.5 0.5\nv -0.5 0.5 0.5\n"
               "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
    }

    /** A chain of links joined by fixed joints, each link's body given. Without materials, link 0
        is on line 2 and link 1 starts on line 3 (its joint follows it). */
    std::string chainUrdf(const std::vector<std::pair<std::string, std::string>> &links,
                          const std::string &materials = "")
    {
        std::string urdf = "<robot name=\"look\">\n" + materials;
        for (std::size_t i = 0; i < links.size(); ++i)
        {
            urdf += "<link name=\"" + links[i].first + "\">" + links[i].second + "</link>\n";
            if (i > 0)
                urdf += "<joint name=\"j" + std::to_string(i) + "\" type=\"fixed\"><parent link=\"" +
                        links[i - 1].first + "\"/><child link=\"" + links[i].first + "\"/></joint>\n";
        }
        return urdf + "</robot>\n";
    }

    fs::path writeUrdf(const fs::path &folder, const std::string &text)
    {
        const fs::path file = folder / "robot.urdf";
        std::ofstream(file) << text;
        return file;
    }

    VisualModel readBoth(const fs::path &urdf)
    {
        return VisualModel::fromUrdfFile(urdf.string(), RobotModel::fromUrdfFile(urdf.string()));
    }

    void expectColour(const std::optional<Rgba> &colour, const Rgba &expected)
    {
        ASSERT_TRUE(colour.has_value());
        EXPECT_LT((*colour - expected).norm(), 1e-6) << colour->transpose();
    }

    class VisualModelFiles : public ::testing::Test
    {
    protected:
        void SetUp() override
        {
            ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);  // the fallback's warning, expected
            folder_ = ompl_core::test::scratchDirectory("ompl_mm_test_VisualModel");
            fs::create_directories(folder_ / "meshes");
            writeTwoMaterialCube(folder_ / "meshes");
            writePlainCube(folder_ / "meshes");
        }

        fs::path folder_;
    };
}  // namespace

TEST_F(VisualModelFiles, PrimitivesKeepTheirOriginsAndUrdfColours)
{
    const std::string materials = "<material name=\"blue\"><color rgba=\"0 0 1 1\"/></material>\n";
    const fs::path urdf = writeUrdf(
        folder_,
        chainUrdf(
            {{"base", std::string("<visual><origin xyz=\"0.1 0.2 0.3\" rpy=\"0 0 1.5707963267948966\"/>"
                                  "<geometry><box size=\"0.4 0.5 0.6\"/></geometry>"
                                  "<material name=\"blue\"/></visual>") +
                          COLLISION},
             {"arm", std::string("<visual><geometry><cylinder radius=\"0.05\" length=\"0.3\"/></geometry>"
                                 "<material name=\"red\"><color rgba=\"1 0 0 1\"/></material></visual>"
                                 "<visual><origin xyz=\"0 0 0.2\"/><geometry><sphere radius=\"0.07\"/>"
                                 "</geometry></visual>") +
                         COLLISION},
             {"hand", std::string("<visual><geometry><sphere radius=\"0.02\"/></geometry>"
                                  "<material name=\"red\"/></visual>") +
                          COLLISION}},
            materials));
    const VisualModel model = readBoth(urdf);
    ASSERT_EQ(model.links().size(), 3u);
    EXPECT_TRUE(model.warnings().empty());

    const LinkVisual &base = model.links()[0];
    EXPECT_FALSE(base.fromCollision);
    ASSERT_EQ(base.shapes.size(), 1u);
    EXPECT_EQ(base.shapes[0].shape.kind, Shape::Kind::Box);
    EXPECT_TRUE(base.shapes[0].shape.boxSize.isApprox(Eigen::Vector3d(0.4, 0.5, 0.6)));
    EXPECT_TRUE(base.shapes[0].origin.translation().isApprox(Eigen::Vector3d(0.1, 0.2, 0.3)));
    // a quarter turn about z takes x to y
    EXPECT_TRUE(
        (base.shapes[0].origin.linear() * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitY()));
    expectColour(base.shapes[0].colour, Rgba(0, 0, 1, 1));  // named under <robot>

    const LinkVisual &arm = model.links()[1];
    ASSERT_EQ(arm.shapes.size(), 2u);
    EXPECT_EQ(arm.shapes[0].shape.kind, Shape::Kind::Cylinder);
    EXPECT_DOUBLE_EQ(arm.shapes[0].shape.radius, 0.05);
    EXPECT_DOUBLE_EQ(arm.shapes[0].shape.length, 0.3);
    expectColour(arm.shapes[0].colour, Rgba(1, 0, 0, 1));  // given inline
    EXPECT_EQ(arm.shapes[1].shape.kind, Shape::Kind::Sphere);
    EXPECT_FALSE(arm.shapes[1].colour.has_value()) << "no material, no colour";
    EXPECT_TRUE(arm.shapes[1].origin.translation().isApprox(Eigen::Vector3d(0, 0, 0.2)));

    // the colour defined inside another link's visual, named here
    expectColour(model.links()[2].shapes.at(0).colour, Rgba(1, 0, 0, 1));
}

TEST_F(VisualModelFiles, MeshesSplitByMaterialWithTheirFileColoursAndScale)
{
    const std::string green = "<material name=\"green\"><color rgba=\"0 1 0 1\"/></material>";
    const fs::path urdf = writeUrdf(
        folder_, chainUrdf({{"a",
                             "<visual><geometry><mesh filename=\"meshes/cube.obj\" scale=\"0.1 0.2 0.3\"/>"
                             "</geometry>" +
                                 green + "</visual>" + COLLISION},
                            {"b",
                             "<visual><geometry><mesh filename=\"meshes/cube.obj\" scale=\"0.1 0.2 0.3\"/>"
                             "</geometry></visual>" +
                                 std::string(COLLISION)},
                            {"c",
                             "<visual><geometry><mesh filename=\"meshes/plain.obj\"/></geometry>"
                             "<material name=\"green\"/></visual>" +
                                 std::string(COLLISION)}}));
    const VisualModel model = readBoth(urdf);
    EXPECT_TRUE(model.warnings().empty());
    const std::vector<VisualShape> &a = model.links()[0].shapes;
    ASSERT_EQ(a.size(), 2u) << "one shape per material";
    std::size_t triangles = 0;
    for (const VisualShape &part : a)
    {
        ASSERT_EQ(part.shape.kind, Shape::Kind::Mesh);
        triangles += part.shape.mesh->triangles.size();
        // the file's colours win over the URDF's green
        const bool dark = part.shape.mesh->triangles.size() == 2;
        expectColour(part.colour, dark ? Rgba(0.25, 0.25, 0.25, 1) : Rgba(1, 0.5, 0, 1));
        if (dark)
        {
            EXPECT_NEAR(part.shape.mesh->bounds.max().z(), -0.15, 1e-9) << "the bottom face, scaled";
        }
    }
    EXPECT_EQ(triangles, 12u);
    Eigen::AlignedBox3d bounds;
    for (const VisualShape &part : a)
        bounds.extend(part.shape.mesh->bounds);
    EXPECT_TRUE(bounds.max().isApprox(Eigen::Vector3d(0.05, 0.1, 0.15))) << bounds.max().transpose();

    // the second link's parts are the first's: the file is read once
    const std::vector<VisualShape> &b = model.links()[1].shapes;
    ASSERT_EQ(b.size(), 2u);
    std::set<const TriangleMesh *> first{a[0].shape.mesh.get(), a[1].shape.mesh.get()};
    EXPECT_EQ(first.count(b[0].shape.mesh.get()) + first.count(b[1].shape.mesh.get()), 2u);

    // a file without materials takes the URDF's colour
    const std::vector<VisualShape> &c = model.links()[2].shapes;
    ASSERT_EQ(c.size(), 1u);
    EXPECT_EQ(c[0].shape.mesh->triangles.size(), 12u);
    expectColour(c[0].colour, Rgba(0, 1, 0, 1));
}

TEST_F(VisualModelFiles, MissingMeshFallsBackToCollisionShapesWithAWarning)
{
    const fs::path urdf =
        writeUrdf(folder_, chainUrdf({{"plain", COLLISION},
                                      {"lost",
                                       "<visual><geometry><box size=\"1 1 1\"/></geometry></visual>"
                                       "<visual><geometry><mesh filename=\"meshes/gone.obj\"/></geometry>"
                                       "</visual>" +
                                           std::string(COLLISION)}}));
    const VisualModel model = readBoth(urdf);
    const LinkVisual &plain = model.links()[0];
    EXPECT_TRUE(plain.fromCollision) << "no <visual>: the collision shapes";
    EXPECT_TRUE(plain.warning.empty());
    ASSERT_EQ(plain.shapes.size(), 1u);
    EXPECT_TRUE(plain.shapes[0].shape.boxSize.isApprox(Eigen::Vector3d::Constant(0.1)));

    const LinkVisual &lost = model.links()[1];
    EXPECT_TRUE(lost.fromCollision);
    ASSERT_EQ(lost.shapes.size(), 1u) << "the collision box alone, not the visual box beside the lost mesh";
    EXPECT_TRUE(lost.shapes[0].shape.boxSize.isApprox(Eigen::Vector3d::Constant(0.1)));
    EXPECT_FALSE(lost.shapes[0].colour.has_value());
    // link "lost", and so its mesh element, is on line 3 (chainUrdf)
    EXPECT_TRUE(
        contains(lost.warning, urdf.string() + ":3: link 'lost': visual mesh 'meshes/gone.obj' not found"))
        << lost.warning;
    EXPECT_TRUE(contains(lost.warning, "showing its collision shapes")) << lost.warning;
    EXPECT_EQ(model.warnings(), std::vector<std::string>{lost.warning});
}

TEST_F(VisualModelFiles, UnreadableMeshFallsBackToo)
{
    std::ofstream(folder_ / "meshes" / "broken.stl") << "solid nothing\nthis is no mesh\n";
    const fs::path urdf = writeUrdf(
        folder_,
        chainUrdf({{"a", "<visual><geometry><mesh filename=\"meshes/broken.stl\"/></geometry></visual>" +
                             std::string(COLLISION)}}));
    const VisualModel model = readBoth(urdf);
    EXPECT_TRUE(model.links()[0].fromCollision);
    EXPECT_TRUE(contains(model.links()[0].warning, "cannot be read")) << model.links()[0].warning;
}

TEST_F(VisualModelFiles, ColladaWithALetterInAnIndexListFallsBackNamingItsLine)
{
    // assimp 5.2's COLLADA reader never stops on such a list, filling the memory
    std::ofstream(folder_ / "meshes" / "letter.dae")
        << "<?xml version=\"1.0\"?>\n"
           "<COLLADA version=\"1.4.1\"><library_geometries><geometry id=\"g\"><mesh>\n"
           "<source id=\"s\"><float_array id=\"f\" count=\"9\">0 0 0 1 0 0 0 1 0</float_array></source>\n"
           "<vertices id=\"v\"><input semantic=\"POSITION\" source=\"#s\"/></vertices>\n"
           "<triangles count=\"1\"><input semantic=\"VERTEX\" source=\"#v\" offset=\"0\"/><p>0 1 "
           "x</p></triangles>\n"
           "</mesh></geometry></library_geometries></COLLADA>\n";
    const fs::path urdf = writeUrdf(
        folder_,
        chainUrdf({{"a", "<visual><geometry><mesh filename=\"meshes/letter.dae\"/></geometry></visual>" +
                             std::string(COLLISION)}}));
    const VisualModel model = readBoth(urdf);
    EXPECT_TRUE(model.links()[0].fromCollision);
    EXPECT_TRUE(
        contains(model.links()[0].warning, "cannot be read (line 5: <p> holds 'x', not a whole number)"))
        << model.links()[0].warning;
}

TEST_F(VisualModelFiles, BadVisualsAreErrorsAtTheirLine)
{
    // the robot from a file without visuals (urdfdom would refuse some of the bad ones first)
    const fs::path clean = writeUrdf(folder_, chainUrdf({{"a", COLLISION}, {"b", COLLISION}}));
    const RobotModel robot = RobotModel::fromUrdfFile(clean.string());
    const auto errorOf = [&](const std::string &visual)
    {
        const fs::path urdf =
            writeUrdf(folder_, chainUrdf({{"a", COLLISION}, {"b", "\n" + visual + COLLISION}}));
        return inputErrorOf([&] { VisualModel::fromUrdfFile(urdf.string(), robot); });
    };
    // link b starts on line 3 (chainUrdf), its visual after a line break on line 4
    const std::string where = (folder_ / "robot.urdf").string() + ":4: ";
    EXPECT_TRUE(contains(errorOf("<visual><geometry><box size=\"1 0 1\"/></geometry></visual>"),
                         where + "link 'b': box size must be positive"));
    EXPECT_TRUE(contains(errorOf("<visual><geometry><sphere radius=\"-1\"/></geometry></visual>"), where));
    EXPECT_TRUE(
        contains(errorOf("<visual><geometry><capsule radius=\"1\" length=\"1\"/></geometry></visual>"),
                 "unknown visual geometry <capsule>"));
    EXPECT_TRUE(contains(
        errorOf("<visual><origin xyz=\"0 0\"/><geometry><sphere radius=\"1\"/></geometry></visual>"), where));
    EXPECT_TRUE(contains(errorOf("<visual><geometry><sphere radius=\"1\"/></geometry>"
                                 "<material name=\"m\"><color rgba=\"2 0 0 1\"/></material></visual>"),
                         where + "colour components must lie between 0 and 1"));
}

TEST(VisualModel, FromCollisionShowsEveryLinksCollisionShapes)
{
    const RobotModel robot = RobotModel::fromUrdfFile(OMPL_MM_SCENES_DIR "/robots/kuka_lwr.urdf");
    const VisualModel model = VisualModel::fromCollision(robot);
    ASSERT_EQ(model.links().size(), robot.links().size());
    for (std::size_t l = 0; l < robot.links().size(); ++l)
    {
        EXPECT_TRUE(model.links()[l].fromCollision);
        EXPECT_EQ(model.links()[l].shapes.size(), robot.links()[l].shapes.size()) << robot.links()[l].name;
    }
}

TEST(VisualModel, FrankaPandaReadsItsVisualMeshesInTheirColours)
{
    const std::string urdf = OMPL_MM_SCENES_DIR "/robots/panda/franka_panda/panda.urdf";
    const RobotModel robot = RobotModel::fromUrdfFile(urdf);
    const VisualModel model = VisualModel::fromUrdfFile(urdf, robot);
    EXPECT_TRUE(model.warnings().empty());
    std::set<std::string> colours;
    std::size_t vertices = 0;
    for (std::size_t l = 0; l < robot.links().size(); ++l)
    {
        const LinkVisual &look = model.links()[l];
        // links with collision shapes have visual ones (panda_link8 and the grasp target have neither)
        EXPECT_EQ(look.fromCollision, robot.links()[l].shapes.empty()) << robot.links()[l].name;
        EXPECT_EQ(look.shapes.empty(), robot.links()[l].shapes.empty()) << robot.links()[l].name;
        for (const VisualShape &shape : look.shapes)
        {
            ASSERT_TRUE(shape.colour.has_value()) << robot.links()[l].name;
            colours.insert(std::to_string(std::lround(shape.colour->x() * 255)));
            vertices += shape.shape.mesh->vertices.size();
        }
    }
    // white links with dark grey joints (the .mtl's Kd 0.25), not the URDF's all-white panda_white
    EXPECT_TRUE(colours.count("255") == 1 && colours.count("64") == 1) << colours.size();
    // the two fingers share one file's meshes
    const LinkVisual &left = model.links()[static_cast<std::size_t>(robot.linkIndex("panda_leftfinger"))];
    const LinkVisual &right = model.links()[static_cast<std::size_t>(robot.linkIndex("panda_rightfinger"))];
    ASSERT_EQ(left.shapes.size(), right.shapes.size());
    for (std::size_t k = 0; k < left.shapes.size(); ++k)
        EXPECT_EQ(left.shapes[k].shape.mesh, right.shapes[k].shape.mesh);
    EXPECT_GT(vertices, 40000u) << "the detailed visual meshes, not the collision ones";
}
