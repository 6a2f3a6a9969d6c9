// Tests for LabelLayout: a label goes to its preferred side when free, else around its target, never
// over another label, a box kept free or the area's edge, and is left out when no place is free; a
// target under a kept box is labelled clear of both.
#include "ompl_mm/io/LabelLayout.h"

#include <gtest/gtest.h>

using namespace ompl_mm;

namespace
{
    const Eigen::AlignedBox2d AREA(Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(400.0, 300.0));

    Eigen::AlignedBox2d square(const Eigen::Vector2d &centre, double half)
    {
        return Eigen::AlignedBox2d(centre - Eigen::Vector2d::Constant(half),
                                   centre + Eigen::Vector2d::Constant(half));
    }

    /** True when the boxes share more than an edge. */
    bool overlaps(const Eigen::AlignedBox2d &a, const Eigen::AlignedBox2d &b)
    {
        return !a.intersection(b).isEmpty() && a.intersection(b).volume() > 0.0;
    }
}  // namespace

TEST(LabelLayout, PreferredSideFirst)
{
    LabelLayout layout(AREA, 12.0);
    const Eigen::AlignedBox2d target = square({200.0, 150.0}, 10.0);
    const auto above = layout.place("obj1", target, LabelLayout::Side::Above);
    ASSERT_TRUE(above.has_value());
    EXPECT_DOUBLE_EQ(above->x(), 200.0);
    EXPECT_LE(layout.placed().back().max().y(), target.min().y()) << "above the target, not over it";
    const auto below = layout.place("goal obj1", square({200.0, 250.0}, 10.0), LabelLayout::Side::Below);
    ASSERT_TRUE(below.has_value());
    EXPECT_GE(layout.placed().back().min().y(), 260.0);
}

TEST(LabelLayout, TextBoxGrowsWithTheTextAndHoldsTheBaseline)
{
    const LabelLayout layout(AREA, 12.0);
    const Eigen::AlignedBox2d short_ = layout.textBox("ab", {100.0, 100.0});
    const Eigen::AlignedBox2d long_ = layout.textBox("abcd", {100.0, 100.0});
    EXPECT_GT(long_.sizes().x(), short_.sizes().x() + 12.0);
    EXPECT_LT(short_.min().y(), 100.0 - 8.0) << "letters stand on the baseline";
    EXPECT_GT(short_.max().y(), 100.0) << "descenders reach below it";
    EXPECT_DOUBLE_EQ(short_.center().x(), 100.0);
    // a character is one code point, however many bytes UTF-8 spends on it
    EXPECT_DOUBLE_EQ(layout.textBox("\u2013\u2013", {0.0, 0.0}).sizes().x(), short_.sizes().x());
}

TEST(LabelLayout, CrowdedLabelsNeverOverlapAndTheLastAreLeftOut)
{
    LabelLayout layout(AREA, 12.0);
    layout.keepFree(square({200.0, 120.0}, 10.0));
    // ten labels on one spot under a kept box: each placed one avoids the others and the box
    std::size_t placed = 0;
    for (int i = 0; i < 10; ++i)
        if (layout.place("object" + std::to_string(i), square({200.0, 150.0}, 6.0), LabelLayout::Side::Above))
            ++placed;
    EXPECT_EQ(placed, layout.placed().size());
    EXPECT_LT(placed, 10u);
    EXPECT_GE(placed, 3u);
    for (std::size_t a = 0; a < layout.placed().size(); ++a)
    {
        EXPECT_TRUE(AREA.contains(layout.placed()[a]));
        EXPECT_FALSE(overlaps(layout.placed()[a], square({200.0, 120.0}, 10.0))) << a;
        for (std::size_t b = a + 1; b < layout.placed().size(); ++b)
            EXPECT_FALSE(overlaps(layout.placed()[a], layout.placed()[b])) << a << " " << b;
    }
}

TEST(LabelLayout, LabelsStayInsideTheArea)
{
    LabelLayout layout(AREA, 12.0);
    // a target at the top edge: above would leave the area, so the label goes below
    const Eigen::AlignedBox2d target = square({200.0, 8.0}, 6.0);
    ASSERT_TRUE(layout.place("obj", target, LabelLayout::Side::Above).has_value());
    EXPECT_GE(layout.placed().back().min().y(), target.max().y());
    // a target whose every side is outside: left out
    LabelLayout tiny(Eigen::AlignedBox2d(Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(20.0, 20.0)), 12.0);
    EXPECT_FALSE(tiny.place("a long name", square({10.0, 10.0}, 5.0), LabelLayout::Side::Above).has_value());
    EXPECT_TRUE(tiny.placed().empty());
}

TEST(LabelLayout, LabelClearsAKeptBoxOnItsTarget)
{
    // a goal symbol (kept free) larger than the object drawn on it: the object's name goes above both
    LabelLayout layout(AREA, 12.0);
    const Eigen::AlignedBox2d symbol = square({200.0, 150.0}, 10.0);
    layout.keepFree(symbol);
    ASSERT_TRUE(layout.place("cyl1", square({200.0, 150.0}, 6.7), LabelLayout::Side::Above).has_value());
    EXPECT_LE(layout.placed().back().max().y(), symbol.min().y());
    EXPECT_DOUBLE_EQ(layout.placed().back().center().x(), 200.0);
}

TEST(LabelLayout, FontSizeMustBePositive)
{
    EXPECT_THROW(LabelLayout(AREA, 0.0), ompl::Exception);
}
