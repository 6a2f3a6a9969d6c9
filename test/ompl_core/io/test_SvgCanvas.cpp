// Tests for SvgCanvas: an empty world box is rejected; world points map to pixels with y flipped below
// the title strip; numbers, the header and the elements are written as exact text.
#include "ompl_core/io/SvgCanvas.h"

#include "common/InputErrors.h"

#include <ompl/util/Exception.h>

#include <gtest/gtest.h>

#include <sstream>
#include <string>

using namespace ompl_core;
using ompl_core::test::exceptionOf;

namespace
{
    /** The world x in [-1, 3], y in [-2, 0] on an 800 px wide picture: 200 px per metre. */
    SvgCanvas canvas()
    {
        return SvgCanvas(Eigen::AlignedBox2d(Eigen::Vector2d(-1.0, -2.0), Eigen::Vector2d(3.0, 0.0)),
                         SvgCanvas::Layout{800.0, 32.0, 36.0});
    }

}  // namespace

TEST(SvgCanvas, RejectsAnEmptyWorldBox)
{
    const SvgCanvas::Layout layout;
    const std::string empty = "SvgCanvas: the world box to draw is empty";
    EXPECT_EQ(exceptionOf([&] { SvgCanvas(Eigen::AlignedBox2d(), layout); }), empty);
    // min above max in y, or in x
    EXPECT_EQ(
        exceptionOf(
            [&] { SvgCanvas(Eigen::AlignedBox2d(Eigen::Vector2d(0, 1), Eigen::Vector2d(1, 0)), layout); }),
        empty);
    EXPECT_EQ(
        exceptionOf(
            [&] { SvgCanvas(Eigen::AlignedBox2d(Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 1)), layout); }),
        empty);
    // zero width cannot be scaled
    EXPECT_EQ(
        exceptionOf(
            [&] { SvgCanvas(Eigen::AlignedBox2d(Eigen::Vector2d(1, 0), Eigen::Vector2d(1, 1)), layout); }),
        empty);
    // just inside: the thinnest width, and zero height (the picture is the two strips)
    EXPECT_EQ(
        exceptionOf(
            [&]
            { SvgCanvas(Eigen::AlignedBox2d(Eigen::Vector2d(1, 0), Eigen::Vector2d(1 + 1e-9, 1)), layout); }),
        "");
    const SvgCanvas flat(Eigen::AlignedBox2d(Eigen::Vector2d(0, 5), Eigen::Vector2d(2, 5)), layout);
    EXPECT_DOUBLE_EQ(flat.height(), layout.titlePx + layout.legendPx);
}

TEST(SvgCanvas, SizeFollowsTheWorldsAspectRatio)
{
    const SvgCanvas c = canvas();
    EXPECT_DOUBLE_EQ(c.width(), 800.0);
    EXPECT_DOUBLE_EQ(c.scale(), 200.0);
    EXPECT_DOUBLE_EQ(c.height(), 32.0 + 2.0 * 200.0 + 36.0);
}

TEST(SvgCanvas, MapsWorldPointsWithYFlippedBelowTheTitleStrip)
{
    const SvgCanvas c = canvas();
    // the world's top-left corner is the drawing band's top-left corner, just below the title strip
    EXPECT_TRUE(c.map(Eigen::Vector2d(-1.0, 0.0)).isApprox(Eigen::Vector2d(0.0, 32.0)));
    // its bottom-right corner is just above the legend strip
    EXPECT_TRUE(c.map(Eigen::Vector2d(3.0, -2.0)).isApprox(Eigen::Vector2d(800.0, 432.0)));
    EXPECT_TRUE(c.map(Eigen::Vector2d(1.0, -1.0)).isApprox(Eigen::Vector2d(400.0, 232.0)));
    // up in the world is up in the picture: a smaller pixel y
    EXPECT_LT(c.map(Eigen::Vector2d(0.0, -0.5)).y(), c.map(Eigen::Vector2d(0.0, -0.6)).y());
    // points outside the world map outside the band, linearly
    EXPECT_TRUE(c.map(Eigen::Vector2d(-1.5, 0.5)).isApprox(Eigen::Vector2d(-100.0, -68.0)));
}

TEST(SvgCanvas, NumbersHaveTwoDecimalsAndNoNegativeZero)
{
    EXPECT_EQ(SvgCanvas::number(2.5), "2.50");
    EXPECT_EQ(SvgCanvas::number(-1.234), "-1.23");
    EXPECT_EQ(SvgCanvas::number(1234567.0), "1234567.00");
    EXPECT_EQ(SvgCanvas::number(-0.004), "0.00");
    EXPECT_EQ(SvgCanvas::number(-0.0), "0.00");
    EXPECT_EQ(SvgCanvas::number(-0.006), "-0.01");
}

TEST(SvgCanvas, WritesExactText)
{
    const SvgCanvas c = canvas();
    EXPECT_EQ(c.pointList({Eigen::Vector2d(-1.0, 0.0), Eigen::Vector2d(3.0, -2.0)}),
              "0.00,32.00 800.00,432.00");
    EXPECT_EQ(c.pointList({}), "");

    std::ostringstream out;
    c.writeHeader(out, "");
    c.writePolygon(out, {Eigen::Vector2d(1.0, -1.0), Eigen::Vector2d(3.0, 0.0)}, "class=\"a\"");
    c.writePolyline(out, {Eigen::Vector2d(1.0, -1.0)}, "class=\"b\"", "<title>t</title>");
    SvgCanvas::writeCircle(out, Eigen::Vector2d(1.0, 2.0), 3.0, "class=\"c\"");
    SvgCanvas::writeLine(out, Eigen::Vector2d(1.0, 2.0), Eigen::Vector2d(3.0, 4.0), "class=\"d\"");
    SvgCanvas::writeText(out, Eigen::Vector2d(5.0, 6.0), "a<b & 'c'", "class=\"e\"");
    SvgCanvas::writeFooter(out);
    EXPECT_EQ(out.str(),
              "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
              "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"800.00\" height=\"468.00\" "
              "viewBox=\"0.00 0.00 800.00 468.00\" font-family=\"sans-serif\">\n"
              "<rect class=\"background\" x=\"0\" y=\"0\" width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
              "<polygon class=\"a\" points=\"400.00,232.00 800.00,32.00\"></polygon>\n"
              "<polyline class=\"b\" points=\"400.00,232.00\"><title>t</title></polyline>\n"
              "<circle class=\"c\" cx=\"1.00\" cy=\"2.00\" r=\"3.00\"></circle>\n"
              "<line class=\"d\" x1=\"1.00\" y1=\"2.00\" x2=\"3.00\" y2=\"4.00\"/>\n"
              "<text x=\"5.00\" y=\"6.00\" class=\"e\">a&lt;b &amp; &apos;c&apos;</text>\n"
              "</svg>\n");

    // defs go verbatim into <defs> after the <svg> element
    std::ostringstream withDefs;
    c.writeHeader(withDefs, "<marker id=\"m\"/>");
    EXPECT_NE(withDefs.str().find("font-family=\"sans-serif\">\n<defs><marker id=\"m\"/></defs>\n<rect"),
              std::string::npos)
        << withDefs.str();
}
