// Tests for Scene's support surfaces: where an object rests, and the margin of that.
#include <gtest/gtest.h>

#include <random>

#include "ompl_mm/scene/Scene.h"

using namespace ompl_mm;

namespace
{
    /** A table top and, listed before it, a mat lying on part of it at the same height: where
        they overlap an object rests on the mat. */
    Scene matOnTable()
    {
        Scene scene;
        scene.surfaces.push_back({"mat", {0.4, -0.1}, {0.6, 0.1}, 0.43, "", {}});
        scene.surfaces.push_back({"table", {0.25, -0.25}, {0.75, 0.25}, 0.43, "table_top", {}});
        return scene;
    }
}  // namespace

TEST(SceneRest, TheFirstSurfaceThatSupportsABaseIsWhereItRests)
{
    const Scene scene = matOnTable();
    EXPECT_EQ(scene.restingSurface({0.5, 0.0, 0.43}), 0);
    EXPECT_EQ(scene.restingSurface({0.3, 0.0, 0.43}), 1);
    EXPECT_EQ(scene.restingSurface({0.3, 0.0, 0.43 + 2.0 * SupportSurface::REST_TOLERANCE}), -1);
    EXPECT_EQ(scene.restingSurface({0.8, 0.0, 0.43}), -1);
    // on the table's edge and a little past it, within the tolerance: resting
    EXPECT_EQ(scene.restingSurface({0.75, 0.0, 0.43}), 1);
    EXPECT_EQ(scene.restingSurface({0.75 + 0.5 * SupportSurface::REST_TOLERANCE, 0.0, 0.43}), 1);
    EXPECT_EQ(scene.restingSurface({0.75 + 2.0 * SupportSurface::REST_TOLERANCE, 0.0, 0.43}), -1);
}

TEST(SceneRest, TheMarginIsPositiveExactlyWhereTheObjectRestsThereAndNoSteeperThanTheBase)
{
    const Scene scene = matOnTable();
    std::mt19937 random(7);
    // bases around the surfaces and within a few rest tolerances of their height
    std::uniform_real_distribution<double> x(0.2, 0.8), y(-0.3, 0.3),
        z(0.43 - 3.0 * SupportSurface::REST_TOLERANCE, 0.43 + 3.0 * SupportSurface::REST_TOLERANCE);
    std::normal_distribution<double> nudge(0.0, SupportSurface::REST_TOLERANCE);
    unsigned int positive[2] = {0, 0};
    for (int k = 0; k < 20000; ++k)
    {
        const Eigen::Vector3d base(x(random), y(random), z(random));
        const Eigen::Vector3d near = base + Eigen::Vector3d(nudge(random), nudge(random), nudge(random));
        for (int surface = 0; surface < 2; ++surface)
        {
            const auto isSurface = [surface](int s) { return s == surface; };
            const double margin = scene.restMargin(base, isSurface);
            if (margin > 0.0)
            {
                EXPECT_EQ(scene.restingSurface(base), surface) << base.transpose();
                ++positive[surface];
            }
            else if (margin < 0.0)
            {
                EXPECT_NE(scene.restingSurface(base), surface) << base.transpose();
            }
            EXPECT_LE(std::abs(scene.restMargin(near, isSurface) - margin), (near - base).norm() + 1e-12)
                << base.transpose() << " to " << near.transpose();
        }
    }
    // both surfaces are rested on in a fair share of the samples
    EXPECT_GT(positive[0], 500u);
    EXPECT_GT(positive[1], 3000u);
}
