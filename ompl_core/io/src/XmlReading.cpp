#include "ompl_core/io/XmlReading.h"

#include <tinyxml2.h>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <locale>
#include <sstream>
#include <utility>

#include "ompl_core/io/InputError.h"
#include "ompl_core/io/NumberText.h"
#include "ompl_core/io/TextFormat.h"

namespace ompl_core
{
    namespace
    {
        std::vector<std::string> splitWhitespace(const char *text)
        {
            std::vector<std::string> tokens;
            std::istringstream in(text);
            std::string token;
            while (in >> token)
                tokens.push_back(token);
            return tokens;
        }

        std::string joinNames(std::initializer_list<const char *> names)
        {
            return joinedNames(std::vector<std::string>(names.begin(), names.end()));
        }

        bool isListed(const char *name, std::initializer_list<const char *> names)
        {
            for (const char *listed : names)
                if (std::string_view(listed) == name)
                    return true;
            return false;
        }

        bool isBlank(const char *text)
        {
            return std::string(text).find_first_not_of(" \t\r\n") == std::string::npos;
        }
    }  // namespace

    std::string describeXmlError(int errorId, const std::string &errorStr)
    {
        std::string description;
        switch (static_cast<tinyxml2::XMLError>(errorId))
        {
            case tinyxml2::XML_ERROR_EMPTY_DOCUMENT:
                return "the document is empty";
            case tinyxml2::XML_ERROR_MISMATCHED_ELEMENT:
                description = "end tag missing or mismatched";
                break;
            case tinyxml2::XML_ERROR_PARSING_ELEMENT:
                description = "malformed element tag";
                break;
            case tinyxml2::XML_ERROR_PARSING_ATTRIBUTE:
                description = "malformed attribute (unquoted value, or an attribute given twice)";
                break;
            case tinyxml2::XML_ERROR_PARSING_TEXT:
                description = "malformed text (a stray '<' or '&', or text outside the root element)";
                break;
            case tinyxml2::XML_ERROR_PARSING_COMMENT:
                description = "unterminated comment";
                break;
            case tinyxml2::XML_ERROR_PARSING_CDATA:
                description = "unterminated CDATA section";
                break;
            case tinyxml2::XML_ERROR_PARSING_DECLARATION:
                description = "malformed <?...?> declaration";
                break;
            default:
                description = "syntax error";
        }
        // tinyxml2 ends some messages with "XMLElement name=<tag>": name the element
        const std::string marker = "name=";
        const std::size_t at = errorStr.rfind(marker);
        if (at != std::string::npos)
            description += " for <" + errorStr.substr(at + marker.size()) + ">";
        return description;
    }

    XmlElement::XmlElement(const tinyxml2::XMLElement *element, std::string file)
        : element_(element), file_(std::move(file))
    {
    }

    std::string XmlElement::name() const
    {
        return element_->Name();
    }

    std::string XmlElement::tag() const
    {
        return "<" + name() + ">";
    }

    SourceLocation XmlElement::where() const
    {
        return SourceLocation{file_, element_->GetLineNum()};
    }

    SourceLocation XmlElement::where(const char *attribute) const
    {
        const tinyxml2::XMLAttribute *found = element_->FindAttribute(attribute);
        return found ? SourceLocation{file_, found->GetLineNum()} : where();
    }

    void XmlElement::fail(const std::string &message) const
    {
        throw InputError(where(), message);
    }

    void XmlElement::fail(const char *attribute, const std::string &message) const
    {
        throw InputError(where(attribute), message);
    }

    void XmlElement::checkAttributes(std::initializer_list<const char *> allowed) const
    {
        for (const tinyxml2::XMLAttribute *a = element_->FirstAttribute(); a; a = a->Next())
            if (!isListed(a->Name(), allowed))
                fail(a->Name(), "unknown attribute '" + std::string(a->Name()) + "' on " + tag() +
                                    " (allowed: " + joinNames(allowed) + ")");
    }

    std::vector<std::pair<std::string, std::string>> XmlElement::attributes() const
    {
        std::vector<std::pair<std::string, std::string>> all;
        for (const tinyxml2::XMLAttribute *a = element_->FirstAttribute(); a; a = a->Next())
            all.emplace_back(a->Name(), a->Value());
        return all;
    }

    std::vector<XmlElement> XmlElement::children(std::initializer_list<const char *> allowed) const
    {
        std::vector<XmlElement> found = children();
        for (const XmlElement &child : found)
            if (!isListed(child.name().c_str(), allowed))
                child.fail("unknown element " + child.tag() + " in " + tag() +
                           " (allowed: " + joinNames(allowed) + ")");
        return found;
    }

    std::vector<XmlElement> XmlElement::children() const
    {
        std::vector<XmlElement> found;
        for (const tinyxml2::XMLNode *node = element_->FirstChild(); node; node = node->NextSibling())
        {
            if (const tinyxml2::XMLElement *child = node->ToElement())
                found.emplace_back(child, file_);
            else if (node->ToText() && !isBlank(node->Value()))
                throw InputError(SourceLocation{file_, node->GetLineNum()},
                                 "unexpected text in " + tag() + " (values go in attributes)");
        }
        return found;
    }

    bool XmlElement::has(const char *attribute) const
    {
        return value(attribute) != nullptr;
    }

    std::string XmlElement::text(const char *attribute) const
    {
        const std::string found = required(attribute);
        if (found.empty())
            fail(attribute, "attribute '" + std::string(attribute) + "' of " + tag() + " must not be empty");
        return found;
    }

    std::string XmlElement::text(const char *attribute, const std::string &fallback) const
    {
        return has(attribute) ? text(attribute) : fallback;
    }

    double XmlElement::number(const char *attribute) const
    {
        return *read(attribute, 1, false, false).front();
    }

    double XmlElement::number(const char *attribute, double fallback) const
    {
        return has(attribute) ? number(attribute) : fallback;
    }

    double XmlElement::positive(const char *attribute) const
    {
        const double found = number(attribute);
        if (found <= 0.0)
            fail(attribute, "attribute '" + std::string(attribute) + "' of " + tag() +
                                " must be positive, got " + required(attribute));
        return found;
    }

    double XmlElement::nonNegative(const char *attribute, double fallback) const
    {
        const double found = number(attribute, fallback);
        if (found < 0.0)
            fail(attribute, "attribute '" + std::string(attribute) + "' of " + tag() +
                                " must not be negative, got " + required(attribute));
        return found;
    }

    double XmlElement::inRange(const char *attribute, double low, double high, double fallback) const
    {
        const double value = number(attribute, fallback);
        if (value < low || value > high)
            fail(attribute, std::string(attribute) + " must be in [" + formatNumber(low) + ", " +
                                formatNumber(high) + "], got " + text(attribute));
        return value;
    }

    double XmlElement::inRange(const char *attribute, double low, double high) const
    {
        required(attribute);
        return inRange(attribute, low, high, 0.0);
    }

    unsigned int XmlElement::count(const char *attribute, unsigned int low, unsigned int high,
                                   unsigned int fallback) const
    {
        if (!has(attribute))
            return fallback;
        const double value = number(attribute);
        if (value != std::floor(value) || value < low || value > high)
            fail(attribute, std::string(attribute) + " must be a whole number in [" + std::to_string(low) +
                                ", " + std::to_string(high) + "], got " + text(attribute));
        return static_cast<unsigned int>(value);
    }

    double XmlElement::nonNegativeAngle(const char *attribute, double fallback) const
    {
        const double found = angle(attribute, fallback);
        if (found < 0.0)
            fail(attribute, "attribute '" + std::string(attribute) + "' of " + tag() +
                                " must not be negative, got " + required(attribute));
        return found;
    }

    double XmlElement::angle(const char *attribute, double fallback) const
    {
        return has(attribute) ? *read(attribute, 1, true, false).front() : fallback;
    }

    OptionalNumber XmlElement::angleOrAny(const char *attribute, OptionalNumber fallback) const
    {
        return has(attribute) ? read(attribute, 1, true, true).front() : fallback;
    }

    std::vector<double> XmlElement::numbers(const char *attribute, std::size_t count) const
    {
        std::vector<double> values;
        for (const OptionalNumber &value : read(attribute, count, false, false))
            values.push_back(*value);
        return values;
    }

    std::vector<OptionalNumber> XmlElement::coordinates(const char *attribute, std::size_t count) const
    {
        return read(attribute, count, false, true);
    }

    Eigen::Vector2d XmlElement::vector2(const char *attribute) const
    {
        const std::vector<double> values = numbers(attribute, 2);
        return Eigen::Vector2d(values[0], values[1]);
    }

    Eigen::Vector3d XmlElement::vector3(const char *attribute) const
    {
        const std::vector<double> values = numbers(attribute, 3);
        return Eigen::Vector3d(values[0], values[1], values[2]);
    }

    Eigen::Vector3d XmlElement::vector3(const char *attribute, const Eigen::Vector3d &fallback) const
    {
        return has(attribute) ? vector3(attribute) : fallback;
    }

    double XmlElement::length(const char *attribute) const
    {
        return inRange(attribute, MIN_LENGTH, MAX_LENGTH);
    }

    Eigen::Vector3d XmlElement::lengths3(const char *attribute) const
    {
        const Eigen::Vector3d found = vector3(attribute);
        if (found.minCoeff() < MIN_LENGTH || found.maxCoeff() > MAX_LENGTH)
            fail(attribute, "attribute '" + std::string(attribute) + "' of " + tag() + " must be in [" +
                                formatNumber(MIN_LENGTH) + ", " + formatNumber(MAX_LENGTH) +
                                "] in every component, got '" + required(attribute) + "'");
        return found;
    }

    Eigen::Vector3d XmlElement::angles3(const char *attribute, const Eigen::Vector3d &fallback) const
    {
        if (!has(attribute))
            return fallback;
        const std::vector<OptionalNumber> values = read(attribute, 3, true, false);
        return Eigen::Vector3d(*values[0], *values[1], *values[2]);
    }

    const char *XmlElement::value(const char *attribute) const
    {
        return element_->Attribute(attribute);
    }

    const char *XmlElement::required(const char *attribute) const
    {
        const char *found = value(attribute);
        if (!found)
            fail("missing required attribute '" + std::string(attribute) + "' on " + tag());
        return found;
    }

    std::vector<OptionalNumber> XmlElement::read(const char *attribute, std::size_t count, bool angles,
                                                 bool allowAny) const
    {
        const std::vector<std::string> tokens = splitWhitespace(required(attribute));
        const std::string what = "attribute '" + std::string(attribute) + "' of " + tag();
        if (tokens.empty() || (count > 0 && tokens.size() != count))
            fail(attribute, what + " needs " + (count > 0 ? std::to_string(count) : "at least 1") + " value" +
                                (count == 1 ? "" : "s") + ", got " + std::to_string(tokens.size()));
        std::vector<OptionalNumber> values;
        for (const std::string &token : tokens)
        {
            if (token == "*")
            {
                if (!allowAny)
                    fail(attribute,
                         "'*' (don't care) is not allowed in " + what + "; it is allowed only in <goal>");
                values.emplace_back(std::nullopt);
                continue;
            }
            const std::optional<double> parsed = angles ? parseAngle(token) : parseNumber(token);
            if (!parsed)
                fail(attribute,
                     "malformed number '" + token + "' in " + what +
                         (angles ? ": expected a finite number of radians, or degrees as in '90deg'"
                                 : ": expected a finite decimal number"));
            if (count != 1 && std::abs(*parsed) > MAX_LIST_VALUE)
                fail(attribute, what + " must lie within ±" + formatNumber(MAX_LIST_VALUE) +
                                    " in every component, got '" + token + "'");
            values.emplace_back(parsed);
        }
        return values;
    }

    XmlElement parseRootElement(tinyxml2::XMLDocument &document, const std::string &xml,
                                const std::string &sourceName, const char *rootName)
    {
        const std::string expected = "<" + std::string(rootName) + ">";
        if (document.Parse(xml.c_str(), xml.size()) != tinyxml2::XML_SUCCESS)
            throw InputError(
                SourceLocation{sourceName, document.ErrorLineNum()},
                "XML syntax error: " + describeXmlError(document.ErrorID(), document.ErrorStr()));
        const tinyxml2::XMLElement *root = document.RootElement();
        if (!root)
            throw InputError(SourceLocation{sourceName, 0}, "no root element, expected " + expected);
        if (const tinyxml2::XMLElement *second = root->NextSiblingElement())
            throw InputError(SourceLocation{sourceName, second->GetLineNum()},
                             "second root element <" + std::string(second->Name()) + ">, only one " +
                                 expected + " is allowed");
        const XmlElement element(root, sourceName);
        if (element.name() != rootName)
            element.fail("the root element must be " + expected + ", found " + element.tag());
        return element;
    }

    void claimName(FirstUses &uses, const XmlElement &element, const std::string &name,
                   const std::string &message)
    {
        const auto [first, inserted] = uses.emplace(name, element.where());
        if (!inserted)
            element.fail("name", message + " (first at line " + std::to_string(first->second.line) + ")");
    }

    void claimOnce(FirstUses &uses, const XmlElement &child, const XmlElement &parent)
    {
        const auto [first, inserted] = uses.emplace(child.name(), child.where());
        if (!inserted)
            child.fail("second " + child.tag() + " in " + parent.tag() +
                       ", only one is allowed (first at line " + std::to_string(first->second.line) + ")");
    }

    std::map<std::string, std::vector<XmlElement>> childrenByTag(
        const XmlElement &parent, std::initializer_list<const char *> allowed,
        std::initializer_list<const char *> repeatable, std::initializer_list<const char *> required)
    {
        std::map<std::string, std::vector<XmlElement>> byTag;
        FirstUses singles;
        for (const XmlElement &child : parent.children(allowed))
        {
            if (!isListed(child.name().c_str(), repeatable))
                claimOnce(singles, child, parent);
            byTag[child.name()].push_back(child);
        }
        for (const char *tag : required)
            if (byTag[tag].empty())
                parent.fail("missing <" + std::string(tag) + "> in " + parent.tag());
        return byTag;
    }

    void checkLeaf(const XmlElement &element, std::initializer_list<const char *> attributes)
    {
        element.checkAttributes(attributes);
        element.children({});
    }

    Eigen::Isometry3d readOrigin(const XmlElement &element)
    {
        checkLeaf(element, {"xyz", "rpy"});
        const Eigen::Vector3d rpy = element.angles3("rpy", Eigen::Vector3d::Zero());
        Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
        pose.translation() = element.vector3("xyz", Eigen::Vector3d::Zero());
        pose.linear() = (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
                         Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
                         Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
                            .toRotationMatrix();
        return pose;
    }
}  // namespace ompl_core
