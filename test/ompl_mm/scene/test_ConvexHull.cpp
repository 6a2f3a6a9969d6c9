// Tests for computeConvexHull: closed, outward and holding every point (checked face by face);
// its volume against the analytic one (cube, L-shaped prism); its support in random directions
// against the points' own (random clouds, and gridded single-precision shapes as CAD meshes come);
// corners only (reflex corners, duplicates, points inside faces dropped); degenerate point sets
// throw naming why; TriangleMesh keeps one hull and names its file.
#include "ompl_mm/scene/ConvexHull.h"

#include "common/InputErrors.h"
#include "ompl_mm/scene/TriangleMesh.h"

#include <ompl/util/Exception.h>

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <utility>

using namespace ompl_mm;
using ompl_core::test::contains;
using ompl_core::test::exceptionOf;

namespace
{
    /** The 8 corners of the box [-half, half]. */
    std::vector<Eigen::Vector3d> boxCorners(const Eigen::Vector3d &half)
    {
        std::vector<Eigen::Vector3d> corners;
        for (int i = 0; i < 8; ++i)
            corners.emplace_back((i & 1 ? 1 : -1) * half.x(), (i & 2 ? 1 : -1) * half.y(),
                                 (i & 4 ? 1 : -1) * half.z());
        return corners;
    }

    /** The 12 corners of an L-shaped prism: the square [-1, 1]^2 without its quadrant x, y > 0,
        for z in [-0.5, 0.5]; (0, 0, +-0.5) are its reflex corners. Area 3, volume 3; its hull's
        area is 3.5 (the cut corner filled up to x + y = 1). */
    std::vector<Eigen::Vector3d> lPrism()
    {
        const double outline[6][2] = {{-1, -1}, {1, -1}, {1, 0}, {0, 0}, {0, 1}, {-1, 1}};
        std::vector<Eigen::Vector3d> points;
        for (double z : {-0.5, 0.5})
            for (const auto &p : outline)
                points.emplace_back(p[0], p[1], z);
        return points;
    }

    /** Volume enclosed by the hull's triangles (divergence theorem). */
    double volume(const ConvexHull &hull)
    {
        double sum = 0.0;
        for (const std::array<int, 3> &t : hull.triangles)
            sum += hull.vertices[t[0]].dot(hull.vertices[t[1]].cross(hull.vertices[t[2]]));
        return sum / 6.0;
    }

    /** Checks that the hull is a closed surface of proper triangles, each outward, with every
        point on the inner side of every face plane (within slack), and each corner one of points. */
    void expectHullOf(const std::vector<Eigen::Vector3d> &points, const ConvexHull &hull, double slack = 1e-9)
    {
        std::map<std::pair<int, int>, int> edges;  // directed edge -> how many faces use it
        for (const std::array<int, 3> &t : hull.triangles)
        {
            const Eigen::Vector3d &a = hull.vertices[t[0]];
            const Eigen::Vector3d normal = (hull.vertices[t[1]] - a).cross(hull.vertices[t[2]] - a);
            ASSERT_GT(normal.norm(), 1e-12) << "a proper triangle";
            for (const Eigen::Vector3d &p : points)
                EXPECT_LE(normal.normalized().dot(p - a), slack) << "outward, and p inside";
            for (int i = 0; i < 3; ++i)
                ++edges[{t[i], t[(i + 1) % 3]}];
        }
        for (const auto &[edge, count] : edges)
        {
            EXPECT_EQ(count, 1) << "one face per directed edge";
            EXPECT_EQ(edges.count({edge.second, edge.first}), 1u) << "and one on its other side";
        }
        std::vector<bool> used(hull.vertices.size(), false);
        for (const std::array<int, 3> &t : hull.triangles)
            for (int v : t)
                used[v] = true;
        for (std::size_t v = 0; v < hull.vertices.size(); ++v)
        {
            EXPECT_TRUE(used[v]) << "corner " << v << " is on a face";
            EXPECT_NE(std::find(points.begin(), points.end(), hull.vertices[v]), points.end())
                << "an input point";
        }
        EXPECT_EQ(hull.triangles.size(), 2 * hull.vertices.size() - 4) << "Euler: F = 2 V - 4";
    }
}  // namespace

TEST(ConvexHull, OfACubeMeshIsItsEightCornersAndTwelveOutwardTriangles)
{
    // as a mesh file gives it: each corner once per triangle that uses it, with face centres and
    // the centre thrown in
    std::vector<Eigen::Vector3d> points;
    const std::vector<Eigen::Vector3d> corners = boxCorners(Eigen::Vector3d(0.5, 0.5, 0.5));
    for (int copy = 0; copy < 4; ++copy)
        points.insert(points.end(), corners.begin(), corners.end());
    for (int axis = 0; axis < 3; ++axis)
        for (double side : {-0.5, 0.5})
            points.push_back(side * Eigen::Vector3d::Unit(axis));
    points.emplace_back(0.0, 0.0, 0.0);
    const ConvexHull hull = computeConvexHull(points);
    EXPECT_EQ(hull.vertices.size(), 8u);
    EXPECT_EQ(hull.triangles.size(), 12u);
    expectHullOf(points, hull);
    EXPECT_NEAR(volume(hull), 1.0, 1e-12);
}

TEST(ConvexHull, OfAnLShapedPrismDropsTheReflexCornersAndFillsTheNotch)
{
    const std::vector<Eigen::Vector3d> points = lPrism();
    const ConvexHull hull = computeConvexHull(points);
    EXPECT_EQ(hull.vertices.size(), 10u) << "all but (0, 0, +-0.5)";
    EXPECT_LT(hull.vertices.size(), points.size());
    for (const Eigen::Vector3d &v : hull.vertices)
        EXPECT_FALSE(v.head<2>().isZero()) << "a reflex corner is no hull corner";
    expectHullOf(points, hull);
    EXPECT_NEAR(volume(hull), 3.5, 1e-12) << "area 3.5 (the notch filled to x + y = 1), height 1";
}

TEST(ConvexHull, ReachesAsFarAsThePointsInEveryDirection)
{
    std::mt19937 random(7);
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const auto direction = [&]
    { return Eigen::Vector3d(normal(random), normal(random), normal(random)).normalized(); };
    const Eigen::Matrix3d turn =
        Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    const auto single = [](const Eigen::Vector3d &p) { return p.cast<float>().cast<double>(); };
    // a ball's cloud (few corners); a sphere's (every point a corner); as CAD meshes come, in
    // single precision (so their flat faces are only flat to rounding): a turned box with a
    // 10 x 10 grid on each face, and an off-centre cylinder of 48 sides with a middle ring
    for (const std::string cloud : {"ball", "sphere", "gridded box", "cylinder"})
    {
        SCOPED_TRACE(cloud);
        std::vector<Eigen::Vector3d> points;
        if (cloud == "ball" || cloud == "sphere")
            for (int i = 0; i < 500; ++i)
                points.push_back((cloud == "ball" ? std::cbrt(unit(random)) : 1.0) * direction());
        if (cloud == "gridded box")
            for (int i = 0; i <= 10; ++i)
                for (int j = 0; j <= 10; ++j)
                    for (int k = 0; k <= 10; ++k)
                        if (std::min({i, j, k}) == 0 || std::max({i, j, k}) == 10)
                            points.push_back(single(turn * Eigen::Vector3d(0.03 * i, 0.02 * j, 0.05 * k)));
        if (cloud == "cylinder")
            for (int i = 0; i < 48; ++i)
                for (double z : {-0.2, 0.0, 0.2})
                    points.push_back(single(Eigen::Vector3d(0.3 + 0.05 * std::cos(M_PI * i / 24),
                                                            -0.1 + 0.05 * std::sin(M_PI * i / 24), z)));
        Eigen::Vector3d largest = Eigen::Vector3d::Zero();
        for (const Eigen::Vector3d &p : points)
            largest = largest.cwiseMax(p.cwiseAbs());
        // what the hull may leave out: rounding noise up to its tolerance (none at the origin)
        const double slack = std::max(1e-9, 2.0 * ConvexHull::RELATIVE_TOLERANCE * largest.sum());
        const ConvexHull hull = computeConvexHull(points);
        expectHullOf(points, hull, slack);
        if (cloud == "sphere")
        {
            EXPECT_EQ(hull.vertices.size(), points.size()) << "every point of a sphere is a corner";
        }
        if (cloud == "gridded box")
        {
            EXPECT_LE(hull.vertices.size(), 12u) << "the 8 corners, not the grid (" << points.size() << ")";
        }
        if (cloud == "cylinder")
        {
            const auto ends = std::count_if(hull.vertices.begin(), hull.vertices.end(),
                                            [](const Eigen::Vector3d &v) { return std::abs(v.z()) > 0.1; });
            EXPECT_EQ(ends, 96) << "every corner of the end rings (the middle ring's lie on faces)";
            EXPECT_LT(hull.vertices.size(), points.size());
        }
        // the support function: the hull reaches as far as the points
        for (int i = 0; i < 200; ++i)
        {
            const Eigen::Vector3d d = direction();
            double reach = -std::numeric_limits<double>::infinity();
            double hullReach = reach;
            for (const Eigen::Vector3d &p : points)
                reach = std::max(reach, d.dot(p));
            for (const Eigen::Vector3d &v : hull.vertices)
                hullReach = std::max(hullReach, d.dot(v));
            EXPECT_NEAR(hullReach, reach, slack);
        }
    }
}

TEST(ConvexHull, PointsThatSpanNoVolumeThrowSayingWhy)
{
    const auto errorOf = [](const std::vector<Eigen::Vector3d> &points)
    { return exceptionOf([&] { computeConvexHull(points); }); };
    std::vector<Eigen::Vector3d> points = boxCorners(Eigen::Vector3d(1, 1, 1));
    points.resize(3);
    EXPECT_TRUE(contains(errorOf(points), "needs at least 4 points, got 3")) << errorOf(points);
    points.assign(5, Eigen::Vector3d(1, 2, 3));
    EXPECT_TRUE(contains(errorOf(points), "the 5 points coincide")) << errorOf(points);
    points.clear();
    for (int i = 0; i < 6; ++i)
        points.emplace_back(0.1 * i, 0.2 * i, -0.3 * i);
    EXPECT_TRUE(contains(errorOf(points), "the 6 points are collinear")) << errorOf(points);
    points = boxCorners(Eigen::Vector3d(1, 2, 0));  // a rectangle, each corner twice
    EXPECT_TRUE(contains(errorOf(points), "the 8 points are coplanar")) << errorOf(points);
    points = boxCorners(Eigen::Vector3d(1, 1, 1));
    points[3].y() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_TRUE(contains(errorOf(points), "not finite")) << errorOf(points);
    // a slab thin but not flat is a hull
    EXPECT_EQ(computeConvexHull(boxCorners(Eigen::Vector3d(1, 1, 1e-6))).vertices.size(), 8u);
}

TEST(ConvexHull, TriangleMeshComputesItsHullOnceAndNamesItsFileWhenFlat)
{
    TriangleMesh mesh;
    mesh.file = "l.stl";
    mesh.vertices = lPrism();
    const std::shared_ptr<const ConvexHull> hull = mesh.convexHull();
    EXPECT_EQ(hull->vertices.size(), 10u);
    EXPECT_EQ(mesh.convexHull().get(), hull.get()) << "kept";
    TriangleMesh flat;
    flat.file = "plate.stl";
    flat.vertices = boxCorners(Eigen::Vector3d(1, 1, 0));
    const std::string error = exceptionOf([&] { flat.convexHull(); });
    EXPECT_TRUE(
        ompl_core::test::startsWith(error, "mesh 'plate.stl': convex hull: the 8 points are coplanar"))
        << error;
}
