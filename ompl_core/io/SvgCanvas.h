#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <ostream>
#include <string>
#include <vector>

namespace ompl_core
{
    /** A top-down SVG picture of a planar world: world metres (x right, y up) are mapped into a band
        of a fixed pixel width between a title strip and a legend strip, so line widths and fonts
        look the same for any scene size. Every number is written with two decimals in the classic
        locale, so the same picture is the same bytes. Shared by the picture writers of both
        libraries. The canvas only maps and formats; the caller owns the stream and writes the
        elements in drawing order, header first and footer last. */
    class SvgCanvas
    {
    public:
        /** The strips around the drawing band, pixels. */
        struct Layout
        {
            double widthPx{800.0};  ///< width of the whole picture
            double titlePx{32.0};   ///< strip above the drawing
            double legendPx{36.0};  ///< strip below the drawing
        };

        /** Maps world (metres), which must not be empty, onto the layout's width; the height
            follows from the world's aspect ratio.
            @throws ompl::Exception for an empty world box or one of zero width. */
        SvgCanvas(const Eigen::AlignedBox2d &world, const Layout &layout);

        /** Width of the whole picture, pixels. */
        double width() const { return layout_.widthPx; }
        /** Height of the whole picture, pixels. */
        double height() const { return height_; }
        /** Pixels per metre. */
        double scale() const { return scale_; }
        /** The strips the canvas was made with. */
        const Layout &layout() const { return layout_; }

        /** The pixel position of a world point (metres); pixel y grows downwards. */
        Eigen::Vector2d map(const Eigen::Vector2d &world) const;

        /** "x,y x,y …": the pixel positions of world points. */
        std::string pointList(const std::vector<Eigen::Vector2d> &world) const;

        /** Opens the picture: the XML declaration, the `<svg>` element with size and viewBox, defs
            (verbatim inside `<defs>`, left out when empty) and a white background. */
        void writeHeader(std::ostream &out, const std::string &defs) const;

        /** Closes the picture (`</svg>`). */
        static void writeFooter(std::ostream &out);

        /** A closed `<polygon>` through world points; attributes and content verbatim. */
        void writePolygon(std::ostream &out, const std::vector<Eigen::Vector2d> &world,
                          const std::string &attributes, const std::string &content = "") const;
        /** An open `<polyline>` through world points; attributes and content verbatim. */
        void writePolyline(std::ostream &out, const std::vector<Eigen::Vector2d> &world,
                           const std::string &attributes, const std::string &content = "") const;

        /** A `<circle>` at a pixel position with a radius in pixels (for symbols, labels and
            legends); attributes and content verbatim. */
        static void writeCircle(std::ostream &out, const Eigen::Vector2d &centre, double radius,
                                const std::string &attributes, const std::string &content = "");
        /** A `<line>` between two pixel positions; attributes verbatim. */
        static void writeLine(std::ostream &out, const Eigen::Vector2d &a, const Eigen::Vector2d &b,
                              const std::string &attributes);
        /** A `<text>` at a pixel position; text is escaped, attributes are verbatim. */
        static void writeText(std::ostream &out, const Eigen::Vector2d &at, const std::string &text,
                              const std::string &attributes);

        /** A number of pixels with two decimals ("-0.00" written as "0.00"). */
        static std::string number(double value);

    private:
        void writePointList(std::ostream &out, const char *tag, const std::vector<Eigen::Vector2d> &world,
                            const std::string &attributes, const std::string &content) const;

        Layout layout_;
        Eigen::Vector2d min_;  ///< world point at the left edge and the bottom of the drawing band
        double top_;           ///< world y at the top of the drawing band
        double scale_;
        double height_;
    };
}  // namespace ompl_core
