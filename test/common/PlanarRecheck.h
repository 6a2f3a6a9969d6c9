// An independent re-check of MOBILE BLOCKED plans: discs and boxes in the plane, no FCL, no labels,
// no library validity or motion checks. Used on MOPL's own solutions and on paths OMPL's
// simplifier changed.
#pragma once

#include "common/MobileBlocked.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace ompl_mm::test
{
    constexpr double PLANAR_RADIUS = 0.2;      // robot and objects are discs of this radius seen from above
    constexpr double PLANAR_TOLERANCE = 1e-6;  // FCL's distance precision: motions are checked continuously

    /** True when a disc at p overlaps the box footprint of an obstacle (axis-aligned here). */
    inline bool discHitsBox(const Eigen::Vector2d &p, const Obstacle &box)
    {
        const Eigen::Vector2d centre = box.pose.translation().head<2>();
        const Eigen::Vector2d half = 0.5 * box.shape.boxSize.head<2>();
        const Eigen::Vector2d closest = p.cwiseMax(centre - half).cwiseMin(centre + half);
        return (closest - p).norm() < PLANAR_RADIUS - PLANAR_TOLERANCE;
    }

    /** Independent validity of a MOBILE BLOCKED configuration in the plane. */
    inline std::string planarFault(const Eigen::Vector2d &robot, const std::vector<Eigen::Vector2d> &objects,
                                   const Scene &scene)
    {
        std::vector<Eigen::Vector2d> discs{robot};
        discs.insert(discs.end(), objects.begin(), objects.end());
        for (std::size_t a = 0; a < discs.size(); ++a)
        {
            for (const Obstacle &obstacle : scene.obstacles)
                if (discHitsBox(discs[a], obstacle))
                    return "disc " + std::to_string(a) + " hits " + obstacle.name;
            for (std::size_t b = a + 1; b < discs.size(); ++b)
                if ((discs[a] - discs[b]).norm() < 2 * PLANAR_RADIUS - PLANAR_TOLERANCE)
                    return "discs " + std::to_string(a) + " and " + std::to_string(b) + " overlap";
        }
        return {};
    }

    /** Re-checks a MOBILE BLOCKED solution from its states alone: it starts at the start; in every
        segment either no object moves, or one object moves and the robot is the standoff behind it
        on the line of its motion at both ends and moves with it (a push); every state, at 1 cm
        steps, is free in the planar model; it ends in the goal. Then the path's labels must say
        what moved. */
    inline void planarRecheck(const ManipulationStateSpace &space, const ManipulationPath &path,
                              const Scene &scene)
    {
        const unsigned int n = space.objectCount();
        auto robotAt = [&](const ompl::base::State *s)
        { return Eigen::Vector2d(space.robotValues(s)[0], space.robotValues(s)[1]); };
        auto objectsAt = [&](const ompl::base::State *s)
        {
            std::vector<Eigen::Vector2d> objects;
            for (unsigned int i = 0; i < n; ++i)
                objects.push_back(space.objectPosition(s, i).head<2>());
            return objects;
        };

        const ompl::base::State *first = path.getState(0);
        EXPECT_NEAR((robotAt(first) - Eigen::Vector2d(1.9, 1.9)).norm(), 0.0, 1e-12);
        for (unsigned int i = 0; i < n; ++i)
            EXPECT_NEAR((objectsAt(first)[i] - scene.objects[i].start.position.head<2>()).norm(), 0.0, 1e-12);

        const std::unique_ptr<ompl::base::State, std::function<void(ompl::base::State *)>> between(
            space.allocState(), [&space](ompl::base::State *s) { space.freeState(s); });
        for (std::size_t k = 0; k + 1 < path.getStateCount(); ++k)
        {
            const ompl::base::State *a = path.getState(k);
            const ompl::base::State *b = path.getState(k + 1);
            std::vector<unsigned int> moved;
            for (unsigned int i = 0; i < n; ++i)
                if ((objectsAt(a)[i] - objectsAt(b)[i]).norm() > 1e-9)
                    moved.push_back(i);
            ASSERT_LE(moved.size(), 1u) << "segment " << k << " moves several objects";
            if (!moved.empty())
            {
                const Eigen::Vector2d motion = objectsAt(b)[moved[0]] - objectsAt(a)[moved[0]];
                for (const ompl::base::State *s : {a, b})
                {
                    const Eigen::Vector2d offset = objectsAt(s)[moved[0]] - robotAt(s);
                    ASSERT_NEAR(offset.norm(), STANDOFF, 1e-6) << "push segment " << k;
                    ASSERT_NEAR(offset.normalized().dot(motion.normalized()), 1.0, 1e-9)
                        << "push segment " << k;
                }
                ASSERT_NEAR((robotAt(b) - robotAt(a) - motion).norm(), 0.0, 1e-6) << "push segment " << k;
            }
            const SegmentLabel expected = moved.empty()
                                              ? SegmentLabel{PrimitiveKind::Transit, -1}
                                              : SegmentLabel{PrimitiveKind::Push, static_cast<int>(moved[0])};
            EXPECT_TRUE(path.label(k) == expected) << "label of segment " << k;
            // waypoints, and the states between them at 1 cm, are free in the planar model
            const double length = std::max((robotAt(b) - robotAt(a)).norm(), 1e-3);
            const int steps = static_cast<int>(std::ceil(length / 0.01));
            for (int j = 0; j <= steps; ++j)
            {
                space.interpolate(a, b, static_cast<double>(j) / steps, between.get());
                const std::string fault =
                    planarFault(robotAt(between.get()), objectsAt(between.get()), scene);
                ASSERT_TRUE(fault.empty()) << "segment " << k << " step " << j << ": " << fault;
            }
        }

        // ends in the goal: robot at the centre, obj3 at (-0.9, -0.9)
        const ompl::base::State *last = path.getState(path.getStateCount() - 1);
        EXPECT_LT((robotAt(last) - Eigen::Vector2d(0.0, 0.0)).norm(), 0.011);
        EXPECT_LT((objectsAt(last)[2] - Eigen::Vector2d(-0.9, -0.9)).norm(), 0.011);
        for (unsigned int i = 0; i < n; ++i)
            EXPECT_NEAR(space.objectPosition(last, i).z(), 0.0, 1e-12) << "objects stay on the floor";
    }
}  // namespace ompl_mm::test
