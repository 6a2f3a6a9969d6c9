// Tests for NumberText: whole-token finite decimals, and angles in radians or degrees.
#include "ompl_core/io/NumberText.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace ompl_core;

namespace
{
    const double PI = std::acos(-1.0);
}  // namespace

TEST(ParseNumber, AcceptsFiniteDecimalNumbersFillingTheToken)
{
    EXPECT_EQ(parseNumber("1"), 1.0);
    EXPECT_EQ(parseNumber("-0.5"), -0.5);
    EXPECT_EQ(parseNumber("+2e-3"), 2e-3);  // a leading '+' is allowed
    EXPECT_EQ(parseNumber("1e308"), 1e308);
    EXPECT_EQ(parseNumber(".5"), 0.5);
}

TEST(ParseNumber, RejectsMalformedOrNonFiniteTokens)
{
    for (const char *token : {"", "+", "++1", "+-1", "1.5x", "abc", " 1", "1 ", "1,5", "0x10", "nan", "inf",
                              "-inf", "1e309", "--1"})
        EXPECT_FALSE(parseNumber(token).has_value()) << "'" << token << "'";
}

TEST(ParseAngle, RadiansOrDegreesWithSuffix)
{
    EXPECT_EQ(parseAngle("1.5"), 1.5);
    EXPECT_NEAR(*parseAngle("90deg"), PI / 2, 1e-15);
    EXPECT_NEAR(*parseAngle("-45deg"), -PI / 4, 1e-15);
    EXPECT_NEAR(*parseAngle("+180deg"), PI, 1e-15);
    for (const char *token : {"deg", "xdeg", "90 deg", "90degs", "infdeg", "90DEG", "nan", ""})
        EXPECT_FALSE(parseAngle(token).has_value()) << "'" << token << "'";
}

// --- the root element and XML syntax ---------------------------------------------------------------------
