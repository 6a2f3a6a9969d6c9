// Checks the 3-D plan pages of both libraries share.
#pragma once

#include "ompl_core/io/PlanViewer.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace ompl_core::test
{
    /** The body called name, or nullptr. */
    inline const ViewerBody *bodyNamed(const std::vector<ViewerBody> &bodies, const std::string &name)
    {
        for (const ViewerBody &body : bodies)
            if (body.name == name)
                return &body;
        return nullptr;
    }

    /** The segments of plan start at frame 0, end at its last frame, each ends where the next starts,
        and no two neighbours have the same label (they would be one segment). */
    inline void expectContiguousSegments(const ViewerPlan &plan)
    {
        const std::vector<ViewerSegment> &segments = plan.segments;
        ASSERT_FALSE(segments.empty());
        EXPECT_EQ(segments.front().first, 0u);
        EXPECT_EQ(segments.back().last, plan.frames.size() - 1);
        for (std::size_t s = 0; s < segments.size(); ++s)
        {
            EXPECT_LT(segments[s].first, segments[s].last) << "segment " << s;
            if (s + 1 < segments.size())
            {
                EXPECT_EQ(segments[s].last, segments[s + 1].first) << "segment " << s;
                EXPECT_NE(segments[s].label, segments[s + 1].label) << "segment " << s;
            }
        }
    }
}  // namespace ompl_core::test
