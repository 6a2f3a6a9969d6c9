#include "ompl_mm/io/JsonText.h"

#include <iomanip>
#include <sstream>

namespace ompl_mm
{
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
}  // namespace ompl_mm
