#include "ompl_mm/io/LabelLayout.h"

#include <ompl/util/Exception.h>

#include <array>

namespace ompl_mm
{
    namespace
    {
        /** A character's width, in font sizes (DejaVu Sans averages about 0.6 on names). */
        constexpr double CHARACTER_WIDTH = 0.62;
        /** How far glyphs reach above and below the baseline, in font sizes. */
        constexpr double ASCENT = 0.8;
        constexpr double DESCENT = 0.25;
        /** The white halo around the letters, pixels (half the stroke width). */
        constexpr double HALO = 1.5;
        /** Between a label and what it names, pixels. */
        constexpr double GAP = 3.0;

        /** Characters (UTF-8 code points) of text. */
        std::size_t codePoints(const std::string &text)
        {
            std::size_t n = 0;
            for (const char c : text)
                n += (static_cast<unsigned char>(c) & 0xc0) != 0x80 ? 1 : 0;
            return n;
        }

        /** True when the boxes share more than an edge. */
        bool boxesOverlap(const Eigen::AlignedBox2d &a, const Eigen::AlignedBox2d &b)
        {
            return a.min().x() < b.max().x() && b.min().x() < a.max().x() && a.min().y() < b.max().y() &&
                   b.min().y() < a.max().y();
        }
    }  // namespace

    LabelLayout::LabelLayout(const Eigen::AlignedBox2d &area, double fontSize)
        : area_(area), fontSize_(fontSize)
    {
        if (!(fontSize > 0.0))
            throw ompl::Exception("LabelLayout", "the font size must be positive");
    }

    void LabelLayout::keepFree(const Eigen::AlignedBox2d &box)
    {
        kept_.push_back(box);
    }

    Eigen::AlignedBox2d LabelLayout::textBox(const std::string &text, const Eigen::Vector2d &anchor) const
    {
        const double half = CHARACTER_WIDTH * fontSize_ * static_cast<double>(codePoints(text)) / 2.0 + HALO;
        return Eigen::AlignedBox2d(anchor + Eigen::Vector2d(-half, -ASCENT * fontSize_ - HALO),
                                   anchor + Eigen::Vector2d(half, DESCENT * fontSize_ + HALO));
    }

    bool LabelLayout::isFree(const Eigen::AlignedBox2d &box) const
    {
        if (!area_.contains(box))
            return false;
        for (const std::vector<Eigen::AlignedBox2d> *boxes : {&placed_, &kept_})
            for (const Eigen::AlignedBox2d &other : *boxes)
                if (boxesOverlap(box, other))
                    return false;
        return true;
    }

    std::optional<Eigen::Vector2d> LabelLayout::place(const std::string &text,
                                                      const Eigen::AlignedBox2d &named, Side preferred)
    {
        // around the boxes kept free that the target touches too (a goal symbol on an object), so
        // that the label clears both
        Eigen::AlignedBox2d target = named;
        for (bool grown = true; grown;)
        {
            grown = false;
            for (const Eigen::AlignedBox2d &kept : kept_)
                if (boxesOverlap(target, kept) && !target.contains(kept))
                {
                    target.extend(kept);
                    grown = true;
                }
        }
        const Eigen::AlignedBox2d size = textBox(text, Eigen::Vector2d::Zero());
        const double halfWidth = size.max().x();
        // baselines that put the box just above and just below the target, and centred beside it
        const double above = target.min().y() - GAP - size.max().y();
        const double below = target.max().y() + GAP - size.min().y();
        const double middle = target.center().y() - size.center().y();
        const double centre = target.center().x();
        const double right = target.max().x() + GAP + halfWidth;
        const double left = target.min().x() - GAP - halfWidth;
        const double first = preferred == Side::Above ? above : below;
        const double second = preferred == Side::Above ? below : above;
        const std::array<Eigen::Vector2d, 8> anchors = {
            Eigen::Vector2d(centre, first), Eigen::Vector2d(centre, second), Eigen::Vector2d(right, middle),
            Eigen::Vector2d(left, middle),  Eigen::Vector2d(right, first),   Eigen::Vector2d(left, first),
            Eigen::Vector2d(right, second), Eigen::Vector2d(left, second)};
        for (const Eigen::Vector2d &anchor : anchors)
        {
            const Eigen::AlignedBox2d box = textBox(text, anchor);
            if (isFree(box))
            {
                placed_.push_back(box);
                return anchor;
            }
        }
        return std::nullopt;
    }
}  // namespace ompl_mm
