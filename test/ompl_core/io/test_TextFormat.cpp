// Tests for the text pieces of ompl_core/io/TextFormat.h.
#include "ompl_core/io/TextFormat.h"

#include <gtest/gtest.h>

#include <locale>
#include <string>

using namespace ompl_core;

TEST(TextFormat, ExactTextConvertsBackToTheSameDouble)
{
    for (double value : {15.157279566815411, 0.1, -2.5e-300, 1.0 / 3.0, 123456789.123456789})
        EXPECT_EQ(std::stod(exactText(value)), value) << exactText(value);
    EXPECT_EQ(exactText(0.5), "0.5");
}

namespace
{
    /** Numbers as some locales write them: a decimal comma. */
    struct DecimalComma : std::numpunct<char>
    {
        char do_decimal_point() const override { return ','; }
    };
}  // namespace

TEST(TextFormat, ExactTextIgnoresTheGlobalLocale)
{
    // a decimal comma would make the text unreadable to OMPL's parameter parsing and to JSON
    const std::locale previous = std::locale::global(std::locale(std::locale::classic(), new DecimalComma));
    const std::string text = exactText(0.25);
    std::locale::global(previous);
    EXPECT_EQ(text, "0.25");
}

TEST(TextFormat, JsonQuotedEscapesQuotesBackslashesAndControls)
{
    EXPECT_EQ(jsonQuoted("a\"b\\c\n"), "\"a\\\"b\\\\c\\u000a\"");
}

TEST(TextFormat, JoinedNamesSaysWhenThereAreNone)
{
    EXPECT_EQ(joinedNames({"a", "b"}), "a, b");
    EXPECT_EQ(joinedNames({}), "none");
}
