// Tests for XmlReading: every reader of XmlElement with its bounds, '*' only where allowed, unknown
// attributes and children, text in elements, names and tags used twice and the root element; every error
// is an InputError naming file:line.
#include "ompl_core/io/XmlReading.h"

#include "common/InputErrors.h"
#include "ompl_core/io/InputError.h"

#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace ompl_core;
using ompl_core::test::contains;
using ompl_core::test::inputErrorOf;
using ompl_core::test::startsWith;

namespace
{
    const double PI = std::acos(-1.0);

    /** A parsed document whose root is <r>, named "t.xml" in messages. */
    class Doc
    {
    public:
        explicit Doc(const std::string &xml) : root_(parseRootElement(document_, xml, "t.xml", "r")) {}
        const XmlElement &root() const { return root_; }
        /** The root's i-th child element. */
        XmlElement child(std::size_t i) const { return root_.children().at(i); }

    private:
        tinyxml2::XMLDocument document_;  // declared first: root_ points into it
        XmlElement root_;
    };

    /** The InputError message of f(root of xml), "" when f throws none. */
    template <typename F>
    std::string errorOn(const std::string &xml, F f)
    {
        const Doc doc(xml);
        return inputErrorOf([&] { f(doc.root()); });
    }

    /** The InputError message of parsing xml with root <r>, "" when it parses. */
    std::string parseError(const std::string &xml)
    {
        tinyxml2::XMLDocument document;
        return inputErrorOf([&] { parseRootElement(document, xml, "t.xml", "r"); });
    }
}  // namespace

TEST(ParseRootElement, AcceptsTheOneExpectedRoot)
{
    const Doc doc("<?xml version=\"1.0\"?>\n<!-- a comment -->\n<r a=\"1\"/>\n");
    EXPECT_EQ(doc.root().name(), "r");
    EXPECT_EQ(doc.root().tag(), "<r>");
    EXPECT_EQ(doc.root().where().file, "t.xml");
    EXPECT_EQ(doc.root().where().line, 3);
}

TEST(ParseRootElement, SyntaxErrorNamesTheLineAndTheElement)
{
    // <a> of line 2 is never closed
    EXPECT_EQ(parseError("<r>\n  <a>\n</r>\n"),
              "t.xml:2: XML syntax error: end tag missing or mismatched for <a>");
}

TEST(ParseRootElement, MalformedAttributeIsASyntaxError)
{
    EXPECT_EQ(parseError("<r>\n  <a b=1/>\n</r>"),
              "t.xml:2: XML syntax error: malformed attribute (unquoted value, or an attribute given twice) "
              "for <a>");
    EXPECT_TRUE(
        startsWith(parseError("<r a=\"1\" a=\"2\"/>"), "t.xml:1: XML syntax error: malformed attribute"));
}

TEST(ParseRootElement, EmptyDocument)
{
    const std::string message = parseError("");
    EXPECT_TRUE(startsWith(message, "t.xml")) << message;
    EXPECT_TRUE(contains(message, "XML syntax error: the document is empty")) << message;
}

TEST(ParseRootElement, NoRootElement)
{
    // only a comment: well-formed for tinyxml2, but no element; the line is unknown
    EXPECT_EQ(parseError("<!-- nothing -->\n"), "t.xml: no root element, expected <r>");
}

TEST(ParseRootElement, SecondRootElement)
{
    EXPECT_EQ(parseError("<r/>\n\n<s/>\n"), "t.xml:3: second root element <s>, only one <r> is allowed");
}

TEST(ParseRootElement, WrongRootElement)
{
    EXPECT_EQ(parseError("\n<scene/>"), "t.xml:2: the root element must be <r>, found <scene>");
}

// --- attributes and children ------------------------------------------------------------------------------

TEST(XmlElement, UnknownAttributeListsTheAllowedOnes)
{
    EXPECT_EQ(errorOn("<r a=\"1\"\n   c=\"2\"/>",
                      [](const XmlElement &r) {
                          r.checkAttributes({"a", "b"});
                      }),
              "t.xml:2: unknown attribute 'c' on <r> (allowed: a, b)");
    EXPECT_EQ(errorOn("<r a=\"1\"/>", [](const XmlElement &r) { r.checkAttributes({}); }),
              "t.xml:1: unknown attribute 'a' on <r> (allowed: none)");
    EXPECT_EQ(errorOn("<r a=\"1\" b=\"2\"/>",
                      [](const XmlElement &r) {
                          r.checkAttributes({"b", "a"});
                      }),
              "");
}

TEST(XmlElement, AttributesInDocumentOrder)
{
    const Doc doc("<r b=\"2\" a=\"\"/>");
    const std::vector<std::pair<std::string, std::string>> expected{{"b", "2"}, {"a", ""}};
    EXPECT_EQ(doc.root().attributes(), expected);
}

TEST(XmlElement, UnknownChildElementListsTheAllowedOnes)
{
    EXPECT_EQ(errorOn("<r>\n  <a/>\n  <x/>\n</r>",
                      [](const XmlElement &r) {
                          r.children({"a", "b"});
                      }),
              "t.xml:3: unknown element <x> in <r> (allowed: a, b)");
    const Doc doc("<r>\n  <a/><!-- a comment -->\n  <b/>\n  <a/>\n</r>");
    const std::vector<XmlElement> children = doc.root().children({"a", "b"});
    ASSERT_EQ(children.size(), 3u);
    EXPECT_EQ(children[1].name(), "b");
    EXPECT_EQ(children[2].where().line, 4);
}

TEST(XmlElement, TextInAnElementIsRejected)
{
    const std::string message = errorOn("<r>\n  <a/>  3.5\n</r>", [](const XmlElement &r) { r.children(); });
    EXPECT_TRUE(startsWith(message, "t.xml:2: ")) << message;
    EXPECT_TRUE(contains(message, "unexpected text in <r> (values go in attributes)")) << message;
    // the check with allowed names as well
    EXPECT_TRUE(contains(errorOn("<r>x</r>", [](const XmlElement &r) { r.children({"a"}); }),
                         "unexpected text in <r>"));
    // blank text (spaces, tabs, line breaks) is not text
    EXPECT_EQ(errorOn("<r>\n\t <a/> \r\n</r>", [](const XmlElement &r) { r.children({"a"}); }), "");
}

TEST(XmlElement, FailNamesTheAttributeLineOrTheElementLine)
{
    EXPECT_EQ(errorOn("<r\n  a=\"1\"/>", [](const XmlElement &r) { r.fail("a", "bad a"); }),
              "t.xml:2: bad a");
    // an absent attribute: the element's line
    EXPECT_EQ(errorOn("<r\n  a=\"1\"/>", [](const XmlElement &r) { r.fail("b", "no b"); }), "t.xml:1: no b");
    EXPECT_EQ(errorOn("\n<r/>", [](const XmlElement &r) { r.fail("whole"); }), "t.xml:2: whole");
}

// --- texts and numbers ------------------------------------------------------------------------------------

TEST(XmlElement, TextMustBePresentAndNotEmpty)
{
    const Doc doc("<r n=\"box\" e=\"\"/>");
    EXPECT_TRUE(doc.root().has("e"));
    EXPECT_FALSE(doc.root().has("m"));
    EXPECT_EQ(doc.root().text("n"), "box");
    EXPECT_EQ(doc.root().text("m", "fallback"), "fallback");
    EXPECT_EQ(errorOn("<r/>", [](const XmlElement &r) { r.text("n"); }),
              "t.xml:1: missing required attribute 'n' on <r>");
    EXPECT_EQ(errorOn("<r\n n=\"\"/>", [](const XmlElement &r) { r.text("n"); }),
              "t.xml:2: attribute 'n' of <r> must not be empty");
    // present but empty is an error even with a fallback
    EXPECT_EQ(errorOn("<r n=\"\"/>", [](const XmlElement &r) { r.text("n", "x"); }),
              "t.xml:1: attribute 'n' of <r> must not be empty");
}

TEST(XmlElement, NumberMustBeOneFiniteNumber)
{
    const Doc doc("<r x=\" 1.5 \"/>");
    EXPECT_EQ(doc.root().number("x"), 1.5);
    EXPECT_EQ(doc.root().number("y", -2.0), -2.0);
    EXPECT_EQ(errorOn("<r/>", [](const XmlElement &r) { r.number("x"); }),
              "t.xml:1: missing required attribute 'x' on <r>");
    EXPECT_EQ(errorOn("<r x=\"1.5x\"/>", [](const XmlElement &r) { r.number("x"); }),
              "t.xml:1: malformed number '1.5x' in attribute 'x' of <r>: expected a finite decimal number");
    EXPECT_EQ(errorOn("<r x=\"1e999\"/>", [](const XmlElement &r) { r.number("x", 0.0); }),
              "t.xml:1: malformed number '1e999' in attribute 'x' of <r>: expected a finite decimal number");
    EXPECT_EQ(errorOn("<r x=\"1 2\"/>", [](const XmlElement &r) { r.number("x"); }),
              "t.xml:1: attribute 'x' of <r> needs 1 value, got 2");
    EXPECT_EQ(errorOn("<r x=\" \"/>", [](const XmlElement &r) { r.number("x"); }),
              "t.xml:1: attribute 'x' of <r> needs 1 value, got 0");
}

TEST(XmlElement, PositiveRejectsZeroAndAcceptsTheSmallestPositive)
{
    EXPECT_EQ(errorOn("<r p=\"0\"/>", [](const XmlElement &r) { r.positive("p"); }),
              "t.xml:1: attribute 'p' of <r> must be positive, got 0");
    EXPECT_EQ(errorOn("<r p=\"-1e-300\"/>", [](const XmlElement &r) { r.positive("p"); }),
              "t.xml:1: attribute 'p' of <r> must be positive, got -1e-300");
    EXPECT_EQ(errorOn("<r/>", [](const XmlElement &r) { r.positive("p"); }),
              "t.xml:1: missing required attribute 'p' on <r>");
    EXPECT_EQ(Doc("<r p=\"1e-300\"/>").root().positive("p"), 1e-300);
}

TEST(XmlElement, NonNegativeRejectsBelowZeroAndAcceptsZero)
{
    EXPECT_EQ(errorOn("<r m=\"-1e-300\"/>", [](const XmlElement &r) { r.nonNegative("m", 1.0); }),
              "t.xml:1: attribute 'm' of <r> must not be negative, got -1e-300");
    EXPECT_EQ(Doc("<r m=\"0\"/>").root().nonNegative("m", 1.0), 0.0);
    EXPECT_EQ(Doc("<r m=\"-0\"/>").root().nonNegative("m", 1.0), 0.0);
    EXPECT_EQ(Doc("<r/>").root().nonNegative("m", 0.7), 0.7);
}

TEST(XmlElement, InRangeIncludesBothBounds)
{
    const auto read = [](const std::string &value)
    { return Doc("<r v=\"" + value + "\"/>").root().inRange("v", 1e-6, 1.0, 0.5); };
    EXPECT_EQ(read("1e-6"), 1e-6);
    EXPECT_EQ(read("1"), 1.0);
    EXPECT_EQ(Doc("<r/>").root().inRange("v", 1e-6, 1.0, 0.5), 0.5);
    EXPECT_EQ(errorOn("<r v=\"1.0001\"/>", [](const XmlElement &r) { r.inRange("v", 1e-6, 1.0, 0.5); }),
              "t.xml:1: v must be in [1e-06, 1], got 1.0001");
    EXPECT_EQ(errorOn("<r v=\"9e-7\"/>", [](const XmlElement &r) { r.inRange("v", 1e-6, 1.0, 0.5); }),
              "t.xml:1: v must be in [1e-06, 1], got 9e-7");
    EXPECT_TRUE(
        contains(errorOn("<r v=\"one\"/>", [](const XmlElement &r) { r.inRange("v", 0.0, 1.0, 0.5); }),
                 "malformed number 'one'"));
}

TEST(XmlElement, CountIsAWholeNumberInItsRange)
{
    const auto read = [](const std::string &value)
    { return Doc("<r n=\"" + value + "\"/>").root().count("n", 1, 16, 3); };
    EXPECT_EQ(read("1"), 1u);
    EXPECT_EQ(read("16"), 16u);
    EXPECT_EQ(read("1.6e1"), 16u);  // written as a decimal number
    EXPECT_EQ(read("+4.0"), 4u);
    EXPECT_EQ(Doc("<r/>").root().count("n", 1, 16, 3), 3u);
    for (const char *bad : {"0", "17", "2.5", "-1", "1e10"})
        EXPECT_EQ(errorOn(std::string("<r n=\"") + bad + "\"/>",
                          [](const XmlElement &r) { r.count("n", 1, 16, 3); }),
                  std::string("t.xml:1: n must be a whole number in [1, 16], got ") + bad);
    EXPECT_TRUE(contains(errorOn("<r n=\"many\"/>", [](const XmlElement &r) { r.count("n", 1, 16, 3); }),
                         "malformed number 'many'"));
}

// --- angles -----------------------------------------------------------------------------------------------

TEST(XmlElement, AngleInRadiansOrDegrees)
{
    const Doc doc("<r a=\"90deg\" b=\"0.25\"/>");
    EXPECT_NEAR(doc.root().angle("a", 0.0), PI / 2, 1e-15);
    EXPECT_EQ(doc.root().angle("b", 0.0), 0.25);
    EXPECT_EQ(doc.root().angle("c", 0.5), 0.5);
    EXPECT_EQ(errorOn("<r a=\"90 deg\"/>", [](const XmlElement &r) { r.angle("a", 0.0); }),
              "t.xml:1: attribute 'a' of <r> needs 1 value, got 2");
    EXPECT_EQ(
        errorOn("<r a=\"right\"/>", [](const XmlElement &r) { r.angle("a", 0.0); }),
        "t.xml:1: malformed number 'right' in attribute 'a' of <r>: expected a finite number of radians, "
        "or degrees as in '90deg'");
    EXPECT_TRUE(contains(errorOn("<r a=\"*\"/>", [](const XmlElement &r) { r.angle("a", 0.0); }),
                         "'*' (don't care) is not allowed"));
}

TEST(XmlElement, NonNegativeAngleRejectsBelowZeroAndAcceptsZero)
{
    EXPECT_EQ(errorOn("<r t=\"-0.001deg\"/>", [](const XmlElement &r) { r.nonNegativeAngle("t", 0.0); }),
              "t.xml:1: attribute 't' of <r> must not be negative, got -0.001deg");
    EXPECT_EQ(Doc("<r t=\"0deg\"/>").root().nonNegativeAngle("t", 1.0), 0.0);
    EXPECT_NEAR(Doc("<r t=\"0.001deg\"/>").root().nonNegativeAngle("t", 0.0), 0.001 * PI / 180, 1e-18);
    EXPECT_EQ(Doc("<r/>").root().nonNegativeAngle("t", 0.3), 0.3);
}

TEST(XmlElement, AngleOrAnyAllowsStar)
{
    const Doc doc("<r a=\"*\" b=\"45deg\"/>");
    EXPECT_EQ(doc.root().angleOrAny("a", 1.0), std::nullopt);
    EXPECT_NEAR(*doc.root().angleOrAny("b", std::nullopt), PI / 4, 1e-15);
    EXPECT_EQ(doc.root().angleOrAny("c", 0.5), OptionalNumber(0.5));
    EXPECT_EQ(doc.root().angleOrAny("c", std::nullopt), std::nullopt);
    EXPECT_TRUE(contains(errorOn("<r a=\"**\"/>", [](const XmlElement &r) { r.angleOrAny("a", 0.0); }),
                         "malformed number '**'"));
}

TEST(XmlElement, Angles3)
{
    const Eigen::Vector3d rpy =
        Doc("<r rpy=\"0.1 90deg -0.2\"/>").root().angles3("rpy", Eigen::Vector3d::Zero());
    EXPECT_EQ(rpy.x(), 0.1);
    EXPECT_NEAR(rpy.y(), PI / 2, 1e-15);
    EXPECT_EQ(rpy.z(), -0.2);
    EXPECT_TRUE(
        Doc("<r/>").root().angles3("rpy", Eigen::Vector3d(1, 2, 3)).isApprox(Eigen::Vector3d(1, 2, 3)));
    EXPECT_EQ(
        errorOn("<r rpy=\"0 0\"/>", [](const XmlElement &r) { r.angles3("rpy", Eigen::Vector3d::Zero()); }),
        "t.xml:1: attribute 'rpy' of <r> needs 3 values, got 2");
    EXPECT_TRUE(contains(
        errorOn("<r rpy=\"0 * 0\"/>", [](const XmlElement &r) { r.angles3("rpy", Eigen::Vector3d::Zero()); }),
        "'*' (don't care) is not allowed in attribute 'rpy' of <r>"));
}

// --- vectors and '*' --------------------------------------------------------------------------------------

TEST(XmlElement, NumbersOfAGivenOrAnyCount)
{
    const Doc doc("<r v=\"1 -2\t3e1\"/>");
    EXPECT_EQ(doc.root().numbers("v", 3), (std::vector<double>{1.0, -2.0, 30.0}));
    EXPECT_EQ(doc.root().numbers("v", 0), (std::vector<double>{1.0, -2.0, 30.0}));  // any count >= 1
    EXPECT_EQ(errorOn("<r v=\"1 2\"/>", [](const XmlElement &r) { r.numbers("v", 3); }),
              "t.xml:1: attribute 'v' of <r> needs 3 values, got 2");
    EXPECT_EQ(errorOn("<r v=\"1 2 3 4\"/>", [](const XmlElement &r) { r.numbers("v", 3); }),
              "t.xml:1: attribute 'v' of <r> needs 3 values, got 4");
    const std::string none = errorOn("<r v=\"\"/>", [](const XmlElement &r) { r.numbers("v", 0); });
    EXPECT_TRUE(startsWith(none, "t.xml:1: attribute 'v' of <r> needs at least 1 value")) << none;
    EXPECT_TRUE(contains(none, "got 0")) << none;
    EXPECT_EQ(errorOn("<r v=\"1 nan\"/>", [](const XmlElement &r) { r.numbers("v", 0); }),
              "t.xml:1: malformed number 'nan' in attribute 'v' of <r>: expected a finite decimal number");
}

TEST(XmlElement, StarOnlyWhereAllowed)
{
    const std::vector<OptionalNumber> c = Doc("<r v=\"1 * 3\"/>").root().coordinates("v", 3);
    ASSERT_EQ(c.size(), 3u);
    EXPECT_EQ(c[0], OptionalNumber(1.0));
    EXPECT_EQ(c[1], std::nullopt);
    EXPECT_EQ(c[2], OptionalNumber(3.0));
    EXPECT_EQ(
        errorOn("<r v=\"1 * 3\"/>", [](const XmlElement &r) { r.numbers("v", 3); }),
        "t.xml:1: '*' (don't care) is not allowed in attribute 'v' of <r>; it is allowed only in <goal>");
    EXPECT_TRUE(contains(errorOn("<r v=\"*\"/>", [](const XmlElement &r) { r.number("v"); }), "'*'"));
    EXPECT_TRUE(contains(errorOn("<r v=\"* 1\"/>", [](const XmlElement &r) { r.vector2("v"); }), "'*'"));
    // coordinates still check the count and the numbers
    EXPECT_EQ(errorOn("<r v=\"1 *\"/>", [](const XmlElement &r) { r.coordinates("v", 3); }),
              "t.xml:1: attribute 'v' of <r> needs 3 values, got 2");
    EXPECT_TRUE(contains(errorOn("<r v=\"1 ? 3\"/>", [](const XmlElement &r) { r.coordinates("v", 3); }),
                         "malformed number '?'"));
}

TEST(XmlElement, FixedLengthVectors)
{
    const Doc doc("<r a=\"1 2\" b=\"1 2 3\"/>");
    EXPECT_TRUE(doc.root().vector2("a").isApprox(Eigen::Vector2d(1, 2)));
    EXPECT_TRUE(doc.root().vector3("b").isApprox(Eigen::Vector3d(1, 2, 3)));
    EXPECT_TRUE(doc.root().vector3("c", Eigen::Vector3d(4, 5, 6)).isApprox(Eigen::Vector3d(4, 5, 6)));
    EXPECT_EQ(errorOn("<r a=\"1 2 3\"/>", [](const XmlElement &r) { r.vector2("a"); }),
              "t.xml:1: attribute 'a' of <r> needs 2 values, got 3");
    EXPECT_EQ(errorOn("<r b=\"1 2\"/>", [](const XmlElement &r) { r.vector3("b"); }),
              "t.xml:1: attribute 'b' of <r> needs 3 values, got 2");
    EXPECT_EQ(errorOn("<r b=\"1 2\"/>", [](const XmlElement &r) { r.vector3("b", Eigen::Vector3d::Zero()); }),
              "t.xml:1: attribute 'b' of <r> needs 3 values, got 2");
    EXPECT_EQ(errorOn("<r/>", [](const XmlElement &r) { r.vector2("a"); }),
              "t.xml:1: missing required attribute 'a' on <r>");
}

TEST(XmlElement, LengthsLieBetweenAMillimetreAndAHundredMetres)
{
    EXPECT_EQ(errorOn("<r s=\"0.2 0 0.2\"/>", [](const XmlElement &r) { r.lengths3("s"); }),
              "t.xml:1: attribute 's' of <r> must be in [0.001, 100] in every component, got '0.2 0 0.2'");
    EXPECT_EQ(errorOn("<r s=\"1 1 100.001\"/>", [](const XmlElement &r) { r.lengths3("s"); }),
              "t.xml:1: attribute 's' of <r> must be in [0.001, 100] in every component, got '1 1 100.001'");
    EXPECT_TRUE(Doc("<r s=\"0.001 100 1\"/>").root().lengths3("s").isApprox(Eigen::Vector3d(0.001, 100, 1)));
    EXPECT_EQ(errorOn("<r l=\"0.0009\"/>", [](const XmlElement &r) { r.length("l"); }),
              "t.xml:1: l must be in [0.001, 100], got 0.0009");
    EXPECT_EQ(errorOn("<r/>", [](const XmlElement &r) { r.length("l"); }),
              "t.xml:1: missing required attribute 'l' on <r>");
    EXPECT_EQ(Doc("<r l=\"100\"/>").root().length("l"), 100.0);
}

TEST(XmlElement, ListValuesLieWithinAThousand)
{
    // a position of 1e308 overflowed the geometry
    EXPECT_EQ(errorOn("<r xyz=\"0 1e308 0\"/>", [](const XmlElement &r) { r.vector3("xyz"); }),
              "t.xml:1: attribute 'xyz' of <r> must lie within ±1000 in every component, got '1e308'");
    EXPECT_EQ(errorOn("<r v=\"-1000.001\"/>", [](const XmlElement &r) { r.numbers("v", 0); }),
              "t.xml:1: attribute 'v' of <r> must lie within ±1000 in every component, got '-1000.001'");
    EXPECT_EQ(Doc("<r xyz=\"-1000 0 1000\"/>").root().vector3("xyz"), Eigen::Vector3d(-1000, 0, 1000));
}

// --- names and tags used once -----------------------------------------------------------------------------

TEST(ClaimName, SecondUseNamesTheFirstLine)
{
    const Doc doc("<r>\n  <a name=\"x\"/>\n  <b\n    name=\"x\"/>\n  <a name=\"y\"/>\n</r>");
    FirstUses uses;
    claimName(uses, doc.child(0), "x", "second thing named 'x'");
    claimName(uses, doc.child(2), "y", "second thing named 'y'");
    // at the name attribute's line
    EXPECT_EQ(inputErrorOf([&] { claimName(uses, doc.child(1), "x", "second thing named 'x'"); }),
              "t.xml:4: second thing named 'x' (first at line 2)");
}

TEST(ClaimOnce, SecondTagNamesTheFirstLine)
{
    const Doc doc("<r>\n  <a/>\n  <b/>\n  <a/>\n</r>");
    FirstUses uses;
    claimOnce(uses, doc.child(0), doc.root());
    claimOnce(uses, doc.child(1), doc.root());
    EXPECT_EQ(inputErrorOf([&] { claimOnce(uses, doc.child(2), doc.root()); }),
              "t.xml:4: second <a> in <r>, only one is allowed (first at line 2)");
}

TEST(ChildrenByTag, GroupsInDocumentOrder)
{
    const Doc doc("<r>\n  <b n=\"1\"/>\n  <a/>\n  <b n=\"2\"/>\n</r>");
    auto byTag = childrenByTag(doc.root(), {"a", "b", "c"}, {"b"}, {"a"});
    ASSERT_EQ(byTag["b"].size(), 2u);
    EXPECT_EQ(byTag["b"][0].text("n"), "1");
    EXPECT_EQ(byTag["b"][1].text("n"), "2");
    EXPECT_EQ(byTag["a"].size(), 1u);
    EXPECT_TRUE(byTag["c"].empty());
}

TEST(ChildrenByTag, UnknownSecondOrMissingTag)
{
    EXPECT_EQ(errorOn("<r>\n  <a/>\n  <d/>\n</r>",
                      [](const XmlElement &r) {
                          childrenByTag(r, {"a", "b"}, {"b"}, {"a"});
                      }),
              "t.xml:3: unknown element <d> in <r> (allowed: a, b)");
    EXPECT_EQ(errorOn("<r>\n  <a/>\n  <a/>\n</r>",
                      [](const XmlElement &r) {
                          childrenByTag(r, {"a", "b"}, {"b"}, {"a"});
                      }),
              "t.xml:3: second <a> in <r>, only one is allowed (first at line 2)");
    EXPECT_EQ(errorOn("<r>\n  <b/>\n</r>",
                      [](const XmlElement &r) {
                          childrenByTag(r, {"a", "b"}, {"b"}, {"a"});
                      }),
              "t.xml:1: missing <a> in <r>");
    EXPECT_TRUE(contains(
        errorOn("<r>\n  <a/>text\n</r>", [](const XmlElement &r) { childrenByTag(r, {"a"}, {}, {}); }),
        "unexpected text in <r>"));
}

// --- leaves and origins -----------------------------------------------------------------------------------

TEST(CheckLeaf, OnlyTheGivenAttributesAndNoChildren)
{
    EXPECT_EQ(errorOn("<r a=\"1\"/>", [](const XmlElement &r) { checkLeaf(r, {"a"}); }), "");
    EXPECT_EQ(errorOn("<r a=\"1\" z=\"2\"/>", [](const XmlElement &r) { checkLeaf(r, {"a"}); }),
              "t.xml:1: unknown attribute 'z' on <r> (allowed: a)");
    EXPECT_EQ(errorOn("<r>\n  <a/>\n</r>", [](const XmlElement &r) { checkLeaf(r, {"a"}); }),
              "t.xml:2: unknown element <a> in <r> (allowed: none)");
    EXPECT_TRUE(contains(errorOn("<r>1 2 3</r>", [](const XmlElement &r) { checkLeaf(r, {}); }),
                         "unexpected text in <r>"));
}

TEST(ReadOrigin, DefaultsToTheIdentity)
{
    EXPECT_TRUE(readOrigin(Doc("<r/>").root()).isApprox(Eigen::Isometry3d::Identity()));
}

TEST(ReadOrigin, RpyAsInUrdf)
{
    const Eigen::Isometry3d pose = readOrigin(Doc("<r xyz=\"1 2 3\" rpy=\"0.1 0.2 30deg\"/>").root());
    const Eigen::Matrix3d expected =
        (Eigen::AngleAxisd(PI / 6, Eigen::Vector3d::UnitZ()) *
         Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY()) * Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()))
            .toRotationMatrix();
    EXPECT_TRUE(pose.translation().isApprox(Eigen::Vector3d(1, 2, 3)));
    EXPECT_TRUE(pose.linear().isApprox(expected, 1e-14));
    // a yaw of 90 degrees turns x into y
    const Eigen::Isometry3d turned = readOrigin(Doc("<r rpy=\"0 0 90deg\"/>").root());
    EXPECT_TRUE((turned.linear() * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitY(), 1e-14));
}

TEST(ReadOrigin, RejectsOtherAttributesChildrenAndBadValues)
{
    EXPECT_EQ(errorOn("<r xyz=\"0 0 0\" scale=\"2\"/>", [](const XmlElement &r) { readOrigin(r); }),
              "t.xml:1: unknown attribute 'scale' on <r> (allowed: xyz, rpy)");
    EXPECT_EQ(errorOn("<r>\n  <a/>\n</r>", [](const XmlElement &r) { readOrigin(r); }),
              "t.xml:2: unknown element <a> in <r> (allowed: none)");
    EXPECT_EQ(errorOn("<r xyz=\"0 0\"/>", [](const XmlElement &r) { readOrigin(r); }),
              "t.xml:1: attribute 'xyz' of <r> needs 3 values, got 2");
    EXPECT_TRUE(contains(errorOn("<r rpy=\"0 0 ninety\"/>", [](const XmlElement &r) { readOrigin(r); }),
                         "malformed number 'ninety' in attribute 'rpy' of <r>"));
    EXPECT_TRUE(contains(errorOn("<r xyz=\"0 0 1deg\"/>", [](const XmlElement &r) { readOrigin(r); }),
                         "malformed number '1deg' in attribute 'xyz' of <r>"));
}

// --- describeXmlError --------------------------------------------------------------------------------------

TEST(DescribeXmlError, NamesTheElementTinyxml2Reports)
{
    EXPECT_EQ(describeXmlError(tinyxml2::XML_ERROR_EMPTY_DOCUMENT, "whatever name=x"),
              "the document is empty");
    EXPECT_EQ(describeXmlError(tinyxml2::XML_ERROR_MISMATCHED_ELEMENT,
                               "Error=XML_ERROR line=3 XMLElement name=box"),
              "end tag missing or mismatched for <box>");
    EXPECT_EQ(describeXmlError(tinyxml2::XML_ERROR_PARSING_COMMENT, "line=1"), "unterminated comment");
    EXPECT_EQ(describeXmlError(tinyxml2::XML_ERROR_FILE_NOT_FOUND, ""), "syntax error");
}
