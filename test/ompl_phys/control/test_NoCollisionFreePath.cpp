// Tests for NoCollisionFreePath, a property of the benchmark scenes: with every body an obstacle at its
// start pose, scenes 2 and 3 have no collision-free path of the robot from its start to the goal (the robot
// must push the constraint-oriented cube), while scene 1 has one.
//
// The robot is a sphere of radius r resting on the floor, its centre at height r = 0.08 m; every body is
// an upright box or prism 0.2 m tall standing on the floor. The sphere's widest horizontal section is the
// disc of radius r at its centre's height, which lies within every body's height, and every other section
// is a smaller disc about the same vertical line. So the sphere overlaps a body exactly when the distance
// on the floor from its centre to the body's footprint is below r: the floor-plan test is exact in 3-D.
// The test checks that premise for each scene.
//
// The search is a flood fill over a grid of square cells of side h covering the robot region. A cell is
// free when the robot disc, shrunk by h*sqrt(2)/2, at the cell centre overlaps no footprint. Why "no path
// found" is then a proof that none exists: every point p of a collision-free path has distance >= r to
// every footprint and lies in some cell whose centre c is within h*sqrt(2)/2 of p (half the cell's
// diagonal), so the distance from c to every footprint is >= r - h*sqrt(2)/2: that cell is free. A
// continuous path passes from cell to cell through a shared side or a shared corner; at a corner it lies in
// all four cells, which are then all free, so the cells it visits form a 4-connected chain of free cells
// from the start's cell to a cell holding its end point, whose centre is within goal radius + h*sqrt(2)/2
// of the goal centre. A flood fill that finds no such chain rules every collision-free path out.
#include "ompl_phys/common/PhysicsTestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <deque>

using namespace ompl_phys;
using namespace ompl_phys::test;

namespace
{
    /** Cell side, m: small enough that the shrunk robot (diameter 0.16 - 0.007 = 0.153 m) cannot pass scene
        2's 0.15 m gap between wall1 and the constraint-oriented cube, nor its 0.12 m cube-to-prism gap. */
    constexpr double CELL = 0.005;

    /** Free cells of the robot region for a disc of radius `radius`: square cells of side h covering the
        region exactly, row-major. */
    struct FreeGrid
    {
        Eigen::Vector2d origin;  ///< lower corner of cell (0, 0)
        double h{CELL};
        int nx{0}, ny{0};
        std::vector<char> free;

        Eigen::Vector2d centre(int i, int j) const { return origin + h * Eigen::Vector2d(i + 0.5, j + 0.5); }
        bool isFree(int i, int j) const { return free[static_cast<std::size_t>(j * nx + i)] != 0; }
    };

    /** Bodies absent from the search (by name). */
    using Removed = std::vector<std::string>;

    FreeGrid freeGrid(const PhysicsScene &scene, double radius, const Removed &removed = {})
    {
        FreeGrid grid;
        const Eigen::AlignedBox2d &region = scene.limits.robotRegion;
        grid.origin = region.min();
        const Eigen::Vector2d size = region.sizes() / grid.h;
        grid.nx = static_cast<int>(std::lround(size.x()));
        grid.ny = static_cast<int>(std::lround(size.y()));
        // the cells must cover the region exactly, so that every cell centre lies in it
        EXPECT_NEAR(grid.nx * grid.h, region.sizes().x(), 1e-9);
        EXPECT_NEAR(grid.ny * grid.h, region.sizes().y(), 1e-9);
        std::vector<std::size_t> obstacles;
        for (std::size_t b = 0; b < scene.bodies.size(); ++b)
            if (std::find(removed.begin(), removed.end(), scene.bodies[b].name) == removed.end())
                obstacles.push_back(b);
        grid.free.assign(static_cast<std::size_t>(grid.nx * grid.ny), 0);
        for (int j = 0; j < grid.ny; ++j)
            for (int i = 0; i < grid.nx; ++i)
            {
                const Eigen::Vector2d c = grid.centre(i, j);
                bool free = true;
                for (std::size_t b : obstacles)
                    if (distanceToStartFootprint(scene, b, c) < radius)
                    {
                        free = false;
                        break;
                    }
                grid.free[static_cast<std::size_t>(j * grid.nx + i)] = free ? 1 : 0;
            }
        return grid;
    }

    /** The outcome of a flood fill from the start's cell. */
    struct Search
    {
        bool startFree{false};
        bool reachesGoal{false};
        std::size_t reached{0};  ///< free cells reached
    };

    /** 4-connected flood fill over the free cells from the cell holding start; the goal is reached when a
        reached cell centre lies within goalRadius of goalCentre. */
    Search floodFill(const FreeGrid &grid, const Eigen::Vector2d &start, const Eigen::Vector2d &goalCentre,
                     double goalRadius)
    {
        Search search;
        const Eigen::Vector2d cell = (start - grid.origin) / grid.h;
        const int si = std::min(grid.nx - 1, static_cast<int>(std::floor(cell.x())));
        const int sj = std::min(grid.ny - 1, static_cast<int>(std::floor(cell.y())));
        search.startFree = grid.isFree(si, sj);
        if (!search.startFree)
            return search;
        std::vector<char> seen(grid.free.size(), 0);
        std::deque<std::pair<int, int>> open{{si, sj}};
        seen[static_cast<std::size_t>(sj * grid.nx + si)] = 1;
        while (!open.empty())
        {
            const auto [i, j] = open.front();
            open.pop_front();
            ++search.reached;
            if ((grid.centre(i, j) - goalCentre).norm() <= goalRadius)
                search.reachesGoal = true;
            const int di[4] = {1, -1, 0, 0};
            const int dj[4] = {0, 0, 1, -1};
            for (int k = 0; k < 4; ++k)
            {
                const int ni = i + di[k];
                const int nj = j + dj[k];
                if (ni < 0 || nj < 0 || ni >= grid.nx || nj >= grid.ny || !grid.isFree(ni, nj))
                    continue;
                char &s = seen[static_cast<std::size_t>(nj * grid.nx + ni)];
                if (!s)
                {
                    s = 1;
                    open.emplace_back(ni, nj);
                }
            }
        }
        return search;
    }

    /** The proof's search: robot shrunk by half a cell diagonal, goal disc grown by it. */
    Search searchShrunk(const PhysicsScene &scene, const Removed &removed = {})
    {
        const double slack = CELL * std::sqrt(2.0) / 2.0;
        return floodFill(freeGrid(scene, scene.robot.radius - slack, removed), scene.robot.start.head<2>(),
                         scene.goal.centre, scene.goal.radius + slack);
    }

    /** Every body stands on the floor and spans the height of the robot's centre (the 3-D premise). */
    void expectBodiesSpanRobotCentreHeight(const PhysicsScene &scene)
    {
        const double centreHeight = scene.robot.start.z();
        ASSERT_DOUBLE_EQ(centreHeight, scene.robot.radius);
        for (const PhysicsBody &body : scene.bodies)
        {
            const Eigen::Matrix3d rotation = body.start.linear();
            // upright: rotated about the vertical only
            EXPECT_TRUE((rotation * Eigen::Vector3d::UnitZ()).isApprox(Eigen::Vector3d::UnitZ(), 1e-12))
                << body.name;
            EXPECT_TRUE(body.shape.kind == PhysicsShape::Kind::Box ||
                        body.shape.kind == PhysicsShape::Kind::Prism)
                << body.name;
            const double z = body.start.translation().z();
            EXPECT_LE(z - body.shape.halfHeight(), 0.0 + 1e-12) << body.name;
            EXPECT_GE(z + body.shape.halfHeight(), 2.0 * scene.robot.radius) << body.name;
        }
    }
}  // namespace

TEST(NoCollisionFreePath, BodiesSpanTheRobotsHeight)
{
    for (int n = 1; n <= 3; ++n)
    {
        SCOPED_TRACE("scene " + std::to_string(n));
        expectBodiesSpanRobotCentreHeight(benchmarkScene(n));
    }
}

TEST(NoCollisionFreePath, SceneTwoHasNone)
{
    const PhysicsScene scene = benchmarkScene(2);
    const Search search = searchShrunk(scene);
    ASSERT_TRUE(search.startFree);
    EXPECT_GT(search.reached, 1000u);  // the robot's half of the room is open
    EXPECT_FALSE(search.reachesGoal)
        << "scene 2 has a collision-free path: the scene does not block the passage";
}

TEST(NoCollisionFreePath, SceneThreeHasNone)
{
    const PhysicsScene scene = benchmarkScene(3);
    const Search search = searchShrunk(scene);
    ASSERT_TRUE(search.startFree);
    EXPECT_GT(search.reached, 1000u);
    EXPECT_FALSE(search.reachesGoal) << "scene 3 has a collision-free path to its occupied goal";
    // the cause when it does: the room the occupant leaves on the goal disc. The proof needs every point of
    // the disc to be closer than r - h*sqrt(2)/2 to cube4 (or another body).
    const std::size_t cube4 = scene.bodyIndex("cube4");
    double clearance = 0.0;
    Eigen::Vector2d best = scene.goal.centre;
    for (int ring = 0; ring <= 50; ++ring)
        for (int k = 0; k < 720; ++k)
        {
            const double angle = 2.0 * std::acos(-1.0) * k / 720.0;
            const Eigen::Vector2d at =
                scene.goal.centre +
                scene.goal.radius * ring / 50.0 * Eigen::Vector2d(std::cos(angle), std::sin(angle));
            const double d = distanceToStartFootprint(scene, cube4, at);
            if (d > clearance)
                clearance = d, best = at;
        }
    EXPECT_LT(clearance, scene.robot.radius - CELL * std::sqrt(2.0) / 2.0)
        << "the robot centre at (" << best.transpose() << "), in the goal disc, is " << clearance
        << " m from cube4: a robot of radius " << scene.robot.radius << " m fits there";
}

TEST(NoCollisionFreePath, TheConstrainedCubesAreWhatBlocks)
{
    // without the constraint-oriented cube, the same (generous) search finds the goal: the negative results
    // above come from the cube the robot has to push, not from a sealed room
    const Search scene2 = searchShrunk(benchmarkScene(2), {"cube3"});
    EXPECT_TRUE(scene2.reachesGoal);
    const Search scene3 = searchShrunk(benchmarkScene(3), {"cube4"});
    EXPECT_TRUE(scene3.reachesGoal);
}

TEST(NoCollisionFreePath, SceneOneHasOne)
{
    const PhysicsScene scene = benchmarkScene(1);
    // A demonstration, not a proof: the full-size robot fits at a 4-connected chain of cell centres from
    // the start's cell to the goal disc; the straight moves between neighbouring centres are not checked.
    const Search full = floodFill(freeGrid(scene, scene.robot.radius), scene.robot.start.head<2>(),
                                  scene.goal.centre, scene.goal.radius);
    ASSERT_TRUE(full.startFree);
    EXPECT_TRUE(full.reachesGoal);
    // This one is a proof: with the robot grown by half a cell diagonal, every point of the polyline from the
    // start through the chain of centres lies within that distance of a centre (or of the start), so the
    // polyline keeps the full-size robot clear of every body; the last centre lies in the goal disc.
    const double slack = CELL * std::sqrt(2.0) / 2.0;
    const Search grown = floodFill(freeGrid(scene, scene.robot.radius + slack), scene.robot.start.head<2>(),
                                   scene.goal.centre, scene.goal.radius);
    ASSERT_TRUE(grown.startFree);
    EXPECT_TRUE(grown.reachesGoal);
}
