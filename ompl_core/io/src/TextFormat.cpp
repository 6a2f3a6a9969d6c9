#include "ompl_core/io/TextFormat.h"

#include <algorithm>
#include <iomanip>
#include <iterator>
#include <locale>
#include <sstream>
#include <utility>

namespace ompl_core
{
    std::string exactText(double value)
    {
        std::ostringstream out;
        out.imbue(std::locale::classic());
        out << std::setprecision(17) << value;
        return out.str();
    }

    std::string formatNumber(double value)
    {
        std::ostringstream out;
        out.imbue(std::locale::classic());
        out << value;
        return out.str();
    }

    std::string jsonQuoted(const std::string &text)
    {
        std::ostringstream out;
        out << '"';
        for (const char c : text)
        {
            if (c == '"' || c == '\\')
                out << '\\' << c;
            else if (static_cast<unsigned char>(c) < 0x20)
                out << "\\u" << std::hex << std::setw(4) << std::setfill('0') << static_cast<int>(c)
                    << std::dec;
            else
                out << c;
        }
        out << '"';
        return out.str();
    }

    std::string joinedNames(const std::vector<std::string> &names, const std::string &whenEmpty)
    {
        std::string joined;
        for (const std::string &name : names)
            joined += (joined.empty() ? "" : ", ") + name;
        return joined.empty() ? whenEmpty : joined;
    }

    std::string xmlEscaped(const std::string &text)
    {
        static const std::pair<char, const char *> ENTITIES[] = {
            {'&', "&amp;"}, {'<', "&lt;"}, {'>', "&gt;"}, {'"', "&quot;"}, {'\'', "&apos;"}};
        std::string out;
        for (char c : text)
        {
            const auto *entity = std::find_if(std::begin(ENTITIES), std::end(ENTITIES),
                                              [c](const auto &e) { return e.first == c; });
            out += entity == std::end(ENTITIES) ? std::string(1, c) : std::string(entity->second);
        }
        return out;
    }
}  // namespace ompl_core
