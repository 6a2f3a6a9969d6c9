#include "ompl_mm/robot/ColladaCheck.h"

#include <tinyxml2.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <initializer_list>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace ompl_mm
{
    namespace
    {
        std::runtime_error errorAt(const tinyxml2::XMLElement &element, const std::string &message)
        {
            return std::runtime_error("line " + std::to_string(element.GetLineNum()) + ": <" +
                                      element.Name() + "> " + message);
        }

        std::vector<std::string> words(const tinyxml2::XMLElement &element)
        {
            std::istringstream text(element.GetText() != nullptr ? element.GetText() : "");
            std::vector<std::string> all;
            for (std::string word; text >> word;)
                all.push_back(word);
            return all;
        }

        /** Whether word is a whole number: an optional sign, then digits. */
        bool isWholeNumber(const std::string &word)
        {
            const std::size_t digits = word[0] == '-' || word[0] == '+' ? 1 : 0;
            return word.size() > digits && std::all_of(word.begin() + digits, word.end(),
                                                       [](unsigned char c) { return std::isdigit(c); });
        }

        bool isOneOf(const char *name, std::initializer_list<const char *> names)
        {
            return std::any_of(names.begin(), names.end(),
                               [name](const char *n) { return std::strcmp(name, n) == 0; });
        }

        /** A count attribute: a whole number of at most 9 digits (products of two stay exact), or
            nothing. */
        std::optional<unsigned long long> countOf(const tinyxml2::XMLElement &element, const char *attribute)
        {
            const char *text = element.Attribute(attribute);
            if (text == nullptr)
                return std::nullopt;
            const std::string word = text;
            if (word.empty() || word.size() > 9 ||
                !std::all_of(word.begin(), word.end(), [](unsigned char c) { return std::isdigit(c); }))
                throw errorAt(element,
                              std::string(attribute) + "=\"" + word.substr(0, 20) + "\" is not a count");
            return std::stoull(word);
        }

        /** The checks of a primitive element (<triangles>, <polylist>, ...; see checkColladaFile()). */
        void checkPrimitives(const tinyxml2::XMLElement &element)
        {
            const char *name = element.Name();
            const unsigned long long count = countOf(element, "count").value_or(0);
            std::size_t offsets = 1;  // indices per vertex: one per offset the inputs use
            std::vector<const tinyxml2::XMLElement *> lists;
            for (const tinyxml2::XMLElement *child = element.FirstChildElement(); child != nullptr;
                 child = child->NextSiblingElement())
                if (std::strcmp(child->Name(), "input") == 0)
                    offsets = std::max<std::size_t>(offsets, countOf(*child, "offset").value_or(0) + 1);
                else if (std::strcmp(child->Name(), "p") == 0)
                    lists.push_back(child);
            if (isOneOf(name, {"triangles", "lines", "polylist"}))
            {
                if (count > 0 && lists.size() != 1)
                    throw errorAt(element, "of count " + std::to_string(count) + " has " +
                                               std::to_string(lists.size()) + " <p>, not one");
                return;
            }
            if (lists.size() != count)
                throw errorAt(element, "count=\"" + std::to_string(count) + "\" but it has " +
                                           std::to_string(lists.size()) + " <p>");
            // a strip of fewer vertices than one primitive takes underflows the reader's count
            const std::size_t least = std::strcmp(name, "tristrips") == 0    ? 3
                                      : std::strcmp(name, "linestrips") == 0 ? 2
                                                                             : 1;
            for (const tinyxml2::XMLElement *list : lists)
            {
                const std::size_t indices = words(*list).size();
                if (indices % offsets != 0 || indices < least * offsets)
                    throw errorAt(*list, "holds " + std::to_string(indices) + " indices: not " +
                                             std::to_string(least) + " vertices or more of " +
                                             std::to_string(offsets) + " each");
            }
        }

        /** The checks of one element; arrays holds the size of each array met so far, by id. */
        void checkElement(const tinyxml2::XMLElement &element,
                          std::map<std::string, unsigned long long> &arrays)
        {
            const char *name = element.Name();
            if (isOneOf(name, {"p", "vcount", "v", "h"}))
            {
                for (const std::string &word : words(element))
                    if (!isWholeNumber(word))
                        throw errorAt(element, "holds '" + word.substr(0, 20) + "', not a whole number");
            }
            else if (isOneOf(name, {"float_array", "int_array", "bool_array", "Name_array", "IDREF_array"}))
            {
                const std::size_t held = words(element).size();
                const std::optional<unsigned long long> count = countOf(element, "count");
                if (!count)
                    throw errorAt(element, "has no count (COLLADA requires it)");
                if (*count != held)
                    throw errorAt(element, "count=\"" + std::to_string(*count) + "\" but it holds " +
                                               std::to_string(held) + " values");
                if (const char *id = element.Attribute("id"))
                    arrays[id] = held;
            }
            else if (isOneOf(name, {"triangles", "lines", "polylist", "polygons", "trifans", "tristrips",
                                    "linestrips"}))
                checkPrimitives(element);
            else if (std::strcmp(name, "accessor") == 0)
            {
                const char *source = element.Attribute("source");
                const auto array =
                    source != nullptr && source[0] == '#' ? arrays.find(source + 1) : arrays.end();
                if (array != arrays.end())
                {
                    const unsigned long long count = countOf(element, "count").value_or(0);
                    const unsigned long long stride = countOf(element, "stride").value_or(1);
                    const unsigned long long offset = countOf(element, "offset").value_or(0);
                    const unsigned long long last = count == 0 ? 0 : offset + count * stride;
                    if (last > array->second)
                        throw errorAt(element, "reads " + std::to_string(last) + " values of '" +
                                                   array->first + "', which holds " +
                                                   std::to_string(array->second));
                }
            }
            for (const tinyxml2::XMLElement *child = element.FirstChildElement(); child != nullptr;
                 child = child->NextSiblingElement())
                checkElement(*child, arrays);
        }
    }  // namespace

    void checkColladaFile(const std::string &path)
    {
        tinyxml2::XMLDocument document;
        if (document.LoadFile(path.c_str()) != tinyxml2::XML_SUCCESS)
            throw std::runtime_error("line " + std::to_string(document.ErrorLineNum()) + ": malformed XML (" +
                                     document.ErrorName() + ")");
        const tinyxml2::XMLElement *root = document.RootElement();
        if (root == nullptr || std::strcmp(root->Name(), "COLLADA") != 0)
            throw std::runtime_error(root == nullptr ? std::string("no <COLLADA> element")
                                                     : errorAt(*root, "is not <COLLADA>").what());
        std::map<std::string, unsigned long long> arrays;
        checkElement(*root, arrays);
    }
}  // namespace ompl_mm
