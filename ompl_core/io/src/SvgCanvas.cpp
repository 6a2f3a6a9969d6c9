#include "ompl_core/io/SvgCanvas.h"

#include "ompl_core/io/TextFormat.h"

#include <ompl/util/Exception.h>

#include <locale>
#include <sstream>

namespace ompl_core
{
    SvgCanvas::SvgCanvas(const Eigen::AlignedBox2d &world, const Layout &layout)
        : layout_(layout), min_(world.min()), top_(world.max().y())
    {
        if (world.isEmpty() || !(world.sizes().x() > 0.0) || !(world.sizes().y() >= 0.0))
            throw ompl::Exception("SvgCanvas", "the world box to draw is empty");
        scale_ = layout.widthPx / world.sizes().x();
        height_ = layout.titlePx + world.sizes().y() * scale_ + layout.legendPx;
    }

    Eigen::Vector2d SvgCanvas::map(const Eigen::Vector2d &world) const
    {
        return {(world.x() - min_.x()) * scale_, layout_.titlePx + (top_ - world.y()) * scale_};
    }

    std::string SvgCanvas::pointList(const std::vector<Eigen::Vector2d> &world) const
    {
        std::string list;
        for (const Eigen::Vector2d &point : world)
        {
            const Eigen::Vector2d p = map(point);
            list += (list.empty() ? "" : " ") + number(p.x()) + "," + number(p.y());
        }
        return list;
    }

    void SvgCanvas::writeHeader(std::ostream &out, const std::string &defs) const
    {
        const std::string width = number(layout_.widthPx);
        const std::string height = number(height_);
        out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
            << R"(<svg xmlns="http://www.w3.org/2000/svg" width=")" << width << R"(" height=")" << height
            << R"(" viewBox="0.00 0.00 )" << width << " " << height << R"(" font-family="sans-serif">)"
            << "\n";
        if (!defs.empty())
            out << "<defs>" << defs << "</defs>\n";
        out << R"(<rect class="background" x="0" y="0" width="100%" height="100%" fill="white"/>)"
            << "\n";
    }

    void SvgCanvas::writeFooter(std::ostream &out)
    {
        out << "</svg>\n";
    }

    void SvgCanvas::writePolygon(std::ostream &out, const std::vector<Eigen::Vector2d> &world,
                                 const std::string &attributes, const std::string &content) const
    {
        writePointList(out, "polygon", world, attributes, content);
    }

    void SvgCanvas::writePolyline(std::ostream &out, const std::vector<Eigen::Vector2d> &world,
                                  const std::string &attributes, const std::string &content) const
    {
        writePointList(out, "polyline", world, attributes, content);
    }

    void SvgCanvas::writePointList(std::ostream &out, const char *tag,
                                   const std::vector<Eigen::Vector2d> &world, const std::string &attributes,
                                   const std::string &content) const
    {
        out << '<' << tag << ' ' << attributes << " points=\"" << pointList(world) << "\">" << content << "</"
            << tag << ">\n";
    }

    void SvgCanvas::writeCircle(std::ostream &out, const Eigen::Vector2d &centre, double radius,
                                const std::string &attributes, const std::string &content)
    {
        out << "<circle " << attributes << " cx=\"" << number(centre.x()) << "\" cy=\"" << number(centre.y())
            << "\" r=\"" << number(radius) << "\">" << content << "</circle>\n";
    }

    void SvgCanvas::writeLine(std::ostream &out, const Eigen::Vector2d &a, const Eigen::Vector2d &b,
                              const std::string &attributes)
    {
        out << "<line " << attributes << " x1=\"" << number(a.x()) << "\" y1=\"" << number(a.y())
            << "\" x2=\"" << number(b.x()) << "\" y2=\"" << number(b.y()) << "\"/>\n";
    }

    void SvgCanvas::writeText(std::ostream &out, const Eigen::Vector2d &at, const std::string &text,
                              const std::string &attributes)
    {
        out << "<text x=\"" << number(at.x()) << "\" y=\"" << number(at.y()) << "\" " << attributes << ">"
            << xmlEscaped(text) << "</text>\n";
    }

    std::string SvgCanvas::number(double value)
    {
        std::ostringstream s;
        s.imbue(std::locale::classic());
        s.setf(std::ios::fixed);
        s.precision(2);
        s << value;
        const std::string text = s.str();
        return text == "-0.00" ? "0.00" : text;
    }
}  // namespace ompl_core
