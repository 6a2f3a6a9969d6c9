/* Placing the text labels of a picture so that none covers another. */
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <optional>
#include <string>
#include <vector>

namespace ompl_mm
{
    /** Places a picture's labels one after another, greedily: each goes to the first of eight
        places around what it names (its preferred side, the opposite side, right, left, then the
        four corners) where it stays inside the picture's area and overlaps no label placed before
        and no box kept free (a symbol); a label that finds no such place is left out. So the labels
        placed first, the more important ones, keep their preferred places. Pixels, y down; text is
        centred on its anchor (SVG text-anchor="middle"). Text boxes are estimated from the font
        size (a character 0.62 em wide, as DejaVu Sans's average, plus the white halo), not
        measured. Copyable value type. */
    class LabelLayout
    {
    public:
        /** The side of its target a label tries first. */
        enum class Side
        {
            Above,  ///< over the target
            Below   ///< under the target
        };

        /** Labels of fontSize pixels that must stay inside area.
            @throws ompl::Exception unless fontSize is positive. */
        LabelLayout(const Eigen::AlignedBox2d &area, double fontSize);

        /** Keeps box free of labels placed from now on. */
        void keepFree(const Eigen::AlignedBox2d &box);

        /** The anchor (baseline centre) of text placed beside the pixel box named (grown by the
            boxes kept free that overlap it, so a label clears a symbol drawn on what it names),
            preferred side first, and reserves its box; nullopt when every place overlaps (the label
            is left out). */
        std::optional<Eigen::Vector2d> place(const std::string &text, const Eigen::AlignedBox2d &named,
                                             Side preferred);

        /** The pixel box text covers with its baseline centre at anchor. */
        Eigen::AlignedBox2d textBox(const std::string &text, const Eigen::Vector2d &anchor) const;

        /** The boxes of the labels placed so far, in order. */
        const std::vector<Eigen::AlignedBox2d> &placed() const { return placed_; }

    private:
        /** True when box lies in the area and overlaps nothing placed or kept free. */
        bool isFree(const Eigen::AlignedBox2d &box) const;

        Eigen::AlignedBox2d area_;
        double fontSize_;
        std::vector<Eigen::AlignedBox2d> placed_;
        std::vector<Eigen::AlignedBox2d> kept_;
    };
}  // namespace ompl_mm
