/* Reading XML input files so that every error names file:line: the XmlElement
   view, and the checks the scene loaders of both libraries share (the root, names used once,
   children by tag). Knows nothing of what the elements mean. */
#pragma once

#include "ompl_core/io/SourceLocation.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tinyxml2
{
    class XMLDocument;
    class XMLElement;
}  // namespace tinyxml2

namespace ompl_core
{
    /** A number, or nothing for "*" (don't care). */
    using OptionalNumber = std::optional<double>;

    /** A readable description of a tinyxml2 syntax error (errorId is a tinyxml2::XMLError, errorStr
        its ErrorStr()), such as "end tag missing or mismatched for <a>". */
    std::string describeXmlError(int errorId, const std::string &errorStr);

    /** One element of an XML file, with the file it came from, for reading values whose errors name
        file:line: allowed attributes and children, finite numbers, angles with an optional "deg"
        suffix, fixed-length vectors, "*" (don't care) coordinates.

        A cheap, copyable view: the tinyxml2 document must outlive it and every element it hands
        out. All readers throw InputError naming the file and the line of the element or
        attribute. */
    class XmlElement
    {
    public:
        /** Views element, which file names in messages.
            @pre element is not null and its document outlives this view. */
        XmlElement(const tinyxml2::XMLElement *element, std::string file);

        /** The element's tag name, such as "box". */
        std::string name() const;

        /** The tag in angle brackets for messages, such as "<box>". */
        std::string tag() const;

        /** File and line of the element's start tag. */
        SourceLocation where() const;

        /** File and line of the attribute, or of the element when it is absent. */
        SourceLocation where(const char *attribute) const;

        /** @throws InputError at the element's line with message. */
        [[noreturn]] void fail(const std::string &message) const;

        /** @throws InputError at the attribute's line with message. */
        [[noreturn]] void fail(const char *attribute, const std::string &message) const;

        /** @throws InputError for the first attribute not in allowed, listing the allowed ones. */
        void checkAttributes(std::initializer_list<const char *> allowed) const;

        /** All attributes in document order, as (name, value). */
        std::vector<std::pair<std::string, std::string>> attributes() const;

        /** Child elements in document order.
            @throws InputError for a child whose name is not in allowed, or for non-blank text. */
        std::vector<XmlElement> children(std::initializer_list<const char *> allowed) const;

        /** Child elements in document order, any names. @throws InputError for non-blank text. */
        std::vector<XmlElement> children() const;

        /** Whether the attribute is present (even when empty). */
        bool has(const char *attribute) const;

        /** The attribute's text. @throws InputError when it is missing or empty. */
        std::string text(const char *attribute) const;
        /** The attribute's text, or fallback when absent. @throws InputError when present but empty. */
        std::string text(const char *attribute, const std::string &fallback) const;

        /** One finite number. @throws InputError when missing or malformed. */
        double number(const char *attribute) const;
        /** One finite number, or fallback when absent. @throws InputError when malformed. */
        double number(const char *attribute, double fallback) const;

        /** One number > 0. @throws InputError when missing, malformed or not positive. */
        double positive(const char *attribute) const;

        /** One number >= 0, or fallback when absent. @throws InputError when malformed or negative. */
        double nonNegative(const char *attribute, double fallback) const;

        /** One number in [low, high], or fallback when absent.
            @throws InputError when malformed or out of range. */
        double inRange(const char *attribute, double low, double high, double fallback) const;
        /** One number in [low, high]. @throws InputError when missing, malformed or out of range. */
        double inRange(const char *attribute, double low, double high) const;

        /** One whole number in [low, high] (written as a decimal number), or fallback when absent.
            @throws InputError when malformed, not whole or out of range. */
        unsigned int count(const char *attribute, unsigned int low, unsigned int high,
                           unsigned int fallback) const;

        /** One angle >= 0 (radians, or degrees with "deg"), or fallback when absent; in radians.
            @throws InputError when malformed or negative. */
        double nonNegativeAngle(const char *attribute, double fallback) const;

        /** One angle (radians, or degrees with "deg"), or fallback when absent; in radians.
            @throws InputError when malformed. */
        double angle(const char *attribute, double fallback) const;

        /** One angle in radians or "*" (nullopt), or fallback when absent.
            @throws InputError when malformed. */
        OptionalNumber angleOrAny(const char *attribute, OptionalNumber fallback) const;

        /** Whitespace-separated finite numbers; count 0 means any count >= 1. A list (any count but
            1) must hold values within ±MAX_LIST_VALUE, as must vector2(), vector3(), coordinates()
            and angles3(). @throws InputError when missing, malformed, out of range or of the wrong
            count. */
        std::vector<double> numbers(const char *attribute, std::size_t count) const;

        /** As numbers(), each entry may also be "*" (nullopt). */
        std::vector<OptionalNumber> coordinates(const char *attribute, std::size_t count) const;

        /** Two finite numbers. @throws InputError when missing, malformed or of the wrong count. */
        Eigen::Vector2d vector2(const char *attribute) const;
        /** Three finite numbers. @throws InputError when missing, malformed or of the wrong count. */
        Eigen::Vector3d vector3(const char *attribute) const;
        /** Three finite numbers, or fallback when absent.
            @throws InputError when malformed or of the wrong count. */
        Eigen::Vector3d vector3(const char *attribute, const Eigen::Vector3d &fallback) const;

        /** One length in [MIN_LENGTH, MAX_LENGTH]. @throws InputError when missing, malformed or out
            of range. */
        double length(const char *attribute) const;
        /** Three lengths, each in [MIN_LENGTH, MAX_LENGTH] (a box's size).
            @throws InputError when missing, malformed, out of range or of the wrong count. */
        Eigen::Vector3d lengths3(const char *attribute) const;

        /** Three angles (radians, or degrees with "deg"), or fallback when absent; in radians.
            @throws InputError when malformed or of the wrong count. */
        Eigen::Vector3d angles3(const char *attribute, const Eigen::Vector3d &fallback) const;

    private:
        /** The attribute's value, or nullptr when absent. */
        const char *value(const char *attribute) const;

        /** The attribute's value. @throws InputError when absent. */
        const char *required(const char *attribute) const;

        /** The tokens of the attribute, each parsed as a number or angle, "*" allowed or not. */
        std::vector<OptionalNumber> read(const char *attribute, std::size_t count, bool angles,
                                         bool allowAny) const;

        const tinyxml2::XMLElement *element_;
        std::string file_;
    };

    /** The largest magnitude of a value in a list attribute (positions, sizes, axes, angles, joint
        values: metres and radians; not single numbers such as a time limit): scenes are rooms, and
        values like 1e308 overflow the geometry. */
    constexpr double MAX_LIST_VALUE = 1000.0;

    /** The shortest length of a shape (sizes, radii, heights), metres: collision checking and
        simulation handle lengths from a millimetre to a hundred metres with their default tolerances. */
    constexpr double MIN_LENGTH = 1e-3;
    /** The longest length of a shape, metres (see MIN_LENGTH). */
    constexpr double MAX_LENGTH = 100.0;

    /** Parses xml into document and returns its only root element, which must be the element
        called rootName. The returned view points into document, which must outlive it.
        @throws InputError naming sourceName and the line of a syntax error, a missing or second
        root element, or a wrong root. */
    XmlElement parseRootElement(tinyxml2::XMLDocument &document, const std::string &xml,
                                const std::string &sourceName, const char *rootName);

    /** For each name or tag already used, where it was first used. */
    using FirstUses = std::map<std::string, SourceLocation>;

    /** Records that element uses name (its attribute "name").
        @throws InputError with message and the first use's line when name was used before. */
    void claimName(FirstUses &uses, const XmlElement &element, const std::string &name,
                   const std::string &message);

    /** Records that child appears in parent. @throws InputError when its tag appeared before. */
    void claimOnce(FirstUses &uses, const XmlElement &child, const XmlElement &parent);

    /** The children of parent grouped by tag, in document order within each tag. Tags not in
        repeatable may appear once; tags in required must appear.
        @throws InputError for an unknown tag, a second single one, or a missing required one. */
    std::map<std::string, std::vector<XmlElement>> childrenByTag(
        const XmlElement &parent, std::initializer_list<const char *> allowed,
        std::initializer_list<const char *> repeatable, std::initializer_list<const char *> required);

    /** Checks an element that carries only the given attributes and no children.
        @throws InputError for another attribute, a child element or non-blank text. */
    void checkLeaf(const XmlElement &element, std::initializer_list<const char *> attributes);

    /** Reads an origin element's xyz (metres, default 0 0 0) and rpy (radians or "deg", default
        0 0 0) into a pose: rpy as in URDF, R = Rz(yaw) Ry(pitch) Rx(roll).
        @throws InputError for other attributes, children or malformed values. */
    Eigen::Isometry3d readOrigin(const XmlElement &element);
}  // namespace ompl_core
