#include "ompl_mm/io/JsonText.h"

#include "ompl_mm/io/ResultJson.h"

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

    void writeRunHeader(std::ostream &out, const RunDescription &run, bool solved, const std::string &status,
                        double time)
    {
        out << std::setprecision(10) << "{\n"
            << "  \"scene\": " << jsonQuoted(run.scene) << ",\n"
            << "  \"planner\": " << jsonQuoted(run.planner) << ",\n"
            << "  \"seed\": " << run.seed << ",\n"
            << "  \"time_limit_s\": " << run.timeLimit << ",\n"
            << "  \"solved\": " << (solved ? "true" : "false") << ",\n"
            << "  \"status\": " << jsonQuoted(status) << ",\n"
            << "  \"time_s\": " << time << ",\n";
    }
}  // namespace ompl_mm
