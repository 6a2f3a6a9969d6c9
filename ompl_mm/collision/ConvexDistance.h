#pragma once

#include "ompl_mm/collision/ConvexShape.h"

#include <Eigen/Geometry>

namespace ompl_mm
{
    /** A lower bound of the distance between two convex shapes placed at world frames frameA and
        frameB, less than `tolerance` below the distance when the search converges; 0 or less when
        they touch (then no depth is measured). GJK (E. G. Gilbert, D. W. Johnson, S. S. Keerthi, "A
        fast procedure for computing the distance between complex objects in three-dimensional
        space", IEEE J. Robotics and Automation 4(2), 1988, doi:10.1109/56.2083) on the shapes' cores:
        each iteration's direction v and support point w bound the distance from below by v.w/|v|
        (a separating plane), and the search keeps the largest such bound. So what it returns is a
        lower bound whatever the rounding or the iteration cap (MAX_GJK_ITERATIONS), which is what
        conservative advancement needs; the simplex only decides how fast the bound closes in.
        @pre tolerance > 0. */
    double convexDistance(const ConvexShape &a, const Eigen::Isometry3d &frameA, const ConvexShape &b,
                          const Eigen::Isometry3d &frameB, double tolerance);

    /** Most iterations of one convexDistance() search. */
    constexpr unsigned int MAX_GJK_ITERATIONS = 64;
}  // namespace ompl_mm
