// Tests for clusterVertices and reduceMesh: on small meshes the clusters, dropped triangles and means
// are those counted by hand; a finely tessellated sphere reduced below a vertex budget keeps every
// vertex within a cell diagonal of the sphere, inside the original's bounding box, which it still
// nearly fills; small meshes are kept as they are; the Franka Panda's visual meshes shrink to the
// budget within the same bounds.
#include "ompl_mm/io/MeshReduction.h"

#include "common/InputErrors.h"
#include "ompl_mm/robot/VisualModel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

using namespace ompl_mm;

namespace
{
    /** A UV sphere of radius r about the origin: rings x segments quads, poles as fans. */
    std::shared_ptr<TriangleMesh> uvSphere(double r, int rings, int segments)
    {
        auto mesh = std::make_shared<TriangleMesh>();
        mesh->vertices.emplace_back(0.0, 0.0, r);
        for (int i = 1; i < rings; ++i)
            for (int j = 0; j < segments; ++j)
            {
                const double theta = M_PI * i / rings, phi = 2.0 * M_PI * j / segments;
                mesh->vertices.emplace_back(r * std::sin(theta) * std::cos(phi),
                                            r * std::sin(theta) * std::sin(phi), r * std::cos(theta));
            }
        mesh->vertices.emplace_back(0.0, 0.0, -r);
        const auto ring = [&](int i, int j) { return 1 + (i - 1) * segments + (j % segments); };
        const int south = static_cast<int>(mesh->vertices.size()) - 1;
        for (int j = 0; j < segments; ++j)
        {
            mesh->triangles.push_back({0, ring(1, j), ring(1, j + 1)});
            mesh->triangles.push_back({south, ring(rings - 1, j + 1), ring(rings - 1, j)});
            for (int i = 1; i + 1 < rings; ++i)
            {
                mesh->triangles.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
                mesh->triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
            }
        }
        mesh->measure();
        return mesh;
    }

    Eigen::AlignedBox3d boxOf(const std::vector<Eigen::Vector3d> &points)
    {
        Eigen::AlignedBox3d box;
        for (const Eigen::Vector3d &p : points)
            box.extend(p);
        return box;
    }
}  // namespace

TEST(MeshReduction, ClustersByHand)
{
    // a strip of three triangles along x; cells 1 wide from x = 0: vertices 0 and 1 share cell 0
    const std::vector<Eigen::Vector3d> vertices = {
        {0.0, 0.0, 0.0}, {0.5, 0.0, 0.0}, {1.5, 0.0, 0.0}, {0.2, 1.5, 0.0}, {1.5, 1.5, 0.0}};
    const std::vector<std::array<int, 3>> triangles = {{0, 1, 3}, {1, 2, 3}, {2, 4, 3}, {4, 2, 3}};
    const ompl_core::ViewerMesh reduced = clusterVertices(vertices, triangles, 1.0);
    // {0, 1, 3} has two corners in cell (0, 0): it vanishes; {4, 2, 3} is {2, 4, 3} again: dropped
    ASSERT_EQ(reduced.triangles.size(), 2u);
    ASSERT_EQ(reduced.vertices.size(), 4u);
    // the first kept triangle's first corner is the cluster of vertices 0 and 1, at their mean
    EXPECT_TRUE(reduced.vertices[static_cast<std::size_t>(reduced.triangles[0][0])].isApprox(
        Eigen::Vector3d(0.25, 0.0, 0.0)));
    EXPECT_TRUE(reduced.vertices[static_cast<std::size_t>(reduced.triangles[0][1])].isApprox(vertices[2]));
    EXPECT_TRUE(reduced.vertices[static_cast<std::size_t>(reduced.triangles[0][2])].isApprox(vertices[3]));
    // a fine grid keeps everything but the repeated triangle
    EXPECT_EQ(clusterVertices(vertices, triangles, 0.1).triangles.size(), 3u);
}

TEST(MeshReduction, BadInputThrows)
{
    const std::vector<Eigen::Vector3d> vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    EXPECT_THROW(clusterVertices(vertices, {{0, 1, 2}}, 0.0), ompl::Exception);
    EXPECT_THROW(clusterVertices(vertices, {{0, 1, 2}}, std::nan("")), ompl::Exception);
    EXPECT_TRUE(ompl_core::test::contains(ompl_core::test::exceptionOf(
                                              [&] {
                                                  clusterVertices(vertices, {{0, 1, 3}}, 0.1);
                                              }),
                                          "vertex 3 of 3"));
    MeshReduction none;
    none.maxVertices = 2;
    EXPECT_THROW(reduceMesh(*uvSphere(1.0, 4, 4), none), ompl::Exception);
}

TEST(MeshReduction, SmallMeshIsKeptAsItIs)
{
    const auto sphere = uvSphere(0.1, 8, 12);
    const ReducedMesh kept = reduceMesh(*sphere);
    EXPECT_EQ(kept.cellSize, 0.0);
    EXPECT_EQ(kept.mesh.vertices, sphere->vertices);
    EXPECT_EQ(kept.mesh.triangles, sphere->triangles);
}

TEST(MeshReduction, ReducedSphereStaysOnTheSphereWithinACellDiagonal)
{
    const double radius = 0.1;
    const auto sphere = uvSphere(radius, 100, 160);  // 15 842 vertices
    MeshReduction budget;
    budget.maxVertices = 800;
    const ReducedMesh reduced = reduceMesh(*sphere, budget);
    ASSERT_GT(reduced.cellSize, 0.0);
    EXPECT_LE(reduced.mesh.vertices.size(), 800u);
    EXPECT_GT(reduced.mesh.vertices.size(), 200u) << "the finest grid under the budget, not a coarser one";
    // a vertex is the mean of sphere points in one cell: within a cell diagonal of the surface
    const double diagonal = std::sqrt(3.0) * reduced.cellSize;
    for (const Eigen::Vector3d &v : reduced.mesh.vertices)
    {
        EXPECT_LE(std::abs(v.norm() - radius), diagonal) << v.transpose();
        EXPECT_TRUE(sphere->bounds.contains(v)) << v.transpose();
    }
    // and the reduced sphere still reaches within a cell diagonal of each side of the box
    const Eigen::AlignedBox3d box = boxOf(reduced.mesh.vertices);
    for (int k = 0; k < 3; ++k)
    {
        EXPECT_LE(box.min()[k], -radius + diagonal) << k;
        EXPECT_GE(box.max()[k], radius - diagonal) << k;
    }
    // every triangle names three distinct vertices, each set once
    std::set<std::array<int, 3>> faces;
    for (std::array<int, 3> t : reduced.mesh.triangles)
    {
        std::sort(t.begin(), t.end());
        EXPECT_TRUE(t[0] != t[1] && t[1] != t[2]);
        EXPECT_TRUE(faces.insert(t).second);
    }
}

TEST(MeshReduction, FrankaPandaMeshesShrinkToTheBudgetWithinTheirBounds)
{
    const std::string urdf = OMPL_MM_SCENES_DIR "/robots/panda/franka_panda/panda.urdf";
    const VisualModel model = VisualModel::fromUrdfFile(urdf, RobotModel::fromUrdfFile(urdf));
    std::size_t before = 0, after = 0;
    std::set<const TriangleMesh *> seen;
    for (const LinkVisual &link : model.links())
        for (const VisualShape &shape : link.shapes)
        {
            if (!seen.insert(shape.shape.mesh.get()).second)
                continue;
            const ReducedMesh reduced = reduceMesh(*shape.shape.mesh);
            EXPECT_LE(reduced.mesh.vertices.size(), MeshReduction().maxVertices);
            const Eigen::AlignedBox3d box = boxOf(reduced.mesh.vertices);
            const Eigen::AlignedBox3d &original = shape.shape.mesh->bounds;
            EXPECT_TRUE(original.contains(box)) << shape.shape.mesh->file;
            // no side of the box recedes by more than a cell diagonal
            const double diagonal = std::sqrt(3.0) * reduced.cellSize + 1e-12;
            EXPECT_LE((box.min() - original.min()).maxCoeff(), diagonal) << shape.shape.mesh->file;
            EXPECT_LE((original.max() - box.max()).maxCoeff(), diagonal) << shape.shape.mesh->file;
            before += shape.shape.mesh->triangles.size();
            after += reduced.mesh.triangles.size();
        }
    EXPECT_LT(after, before * 6 / 10) << before << " triangles before";
}
