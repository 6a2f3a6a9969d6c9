/* A top-down SVG picture of a planar world: world metres (x right, y up) are mapped into a band of
   a fixed pixel width between a title strip and a legend strip, so line widths and fonts look the
   same for any scene size. Every number is written with two decimals in the classic locale, so
   the same picture is the same bytes. Shared by the picture writers of both libraries. */
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <ostream>
#include <string>
#include <vector>

namespace ompl_core
{
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

        /** Maps world, which must not be empty, onto the layout's width.
            @throws ompl::Exception for an empty or degenerate world box. */
        SvgCanvas(const Eigen::AlignedBox2d &world, const Layout &layout);

        double width() const { return layout_.widthPx; }
        /** Height of the whole picture, pixels. */
        double height() const { return height_; }
        /** Pixels per metre. */
        double scale() const { return scale_; }
        const Layout &layout() const { return layout_; }

        /** The pixel position of a world point (y down). */
        Eigen::Vector2d map(const Eigen::Vector2d &world) const;

        /** "x,y x,y …": the pixel positions of world points. */
        std::string pointList(const std::vector<Eigen::Vector2d> &world) const;

        /** Opens the picture: the XML declaration, <svg> with size and viewBox, defs (verbatim, may
            be empty) and a white background. */
        void writeHeader(std::ostream &out, const std::string &defs) const;

        /** Closes the picture. */
        static void writeFooter(std::ostream &out);

        /** A <polygon> or <polyline> through world points; attributes and content verbatim. */
        void writePolygon(std::ostream &out, const std::vector<Eigen::Vector2d> &world,
                          const std::string &attributes, const std::string &content = "") const;
        void writePolyline(std::ostream &out, const std::vector<Eigen::Vector2d> &world,
                           const std::string &attributes, const std::string &content = "") const;

        /** Elements at pixel positions (for symbols, labels and legends). */
        static void writeCircle(std::ostream &out, const Eigen::Vector2d &centre, double radius,
                                const std::string &attributes, const std::string &content = "");
        static void writeLine(std::ostream &out, const Eigen::Vector2d &a, const Eigen::Vector2d &b,
                              const std::string &attributes);
        /** text is escaped. */
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
