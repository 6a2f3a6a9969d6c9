#include "ompl_mm/collision/ConvexDistance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace ompl_mm
{
    namespace
    {
        /** A support point that brings the search no further than this share of |v|^2 ends it. */
        constexpr double LEAST_PROGRESS = 1e-12;
        /** Squared area (|ab x ac|^2) or volume below which a triangle or tetrahedron counts as flat,
            relative to its edges' scale. */
        constexpr double FLAT = 1e-14;

        /** Up to four points of the Minkowski difference; their hull's point nearest the origin
            is the search's current v. */
        struct Simplex
        {
            Eigen::Vector3d points[4]{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                                      Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
            int size{0};
        };

        /** Nearest point to the origin on segment a b; the simplex keeps the ends that span it. */
        Eigen::Vector3d nearestOnSegment(Simplex &s, const Eigen::Vector3d &a, const Eigen::Vector3d &b)
        {
            const Eigen::Vector3d ab = b - a;
            const double t = -a.dot(ab);
            const double length = ab.squaredNorm();
            if (t <= 0.0 || length <= 0.0)
            {
                s.points[0] = a, s.size = 1;
                return a;
            }
            if (t >= length)
            {
                s.points[0] = b, s.size = 1;
                return b;
            }
            s.points[0] = a, s.points[1] = b, s.size = 2;
            return a + (t / length) * ab;
        }

        /** Nearest point to the origin on triangle a b c (C. Ericson, Real-Time Collision Detection,
            2005, section 5.1.5, by Voronoi regions); the simplex keeps the corners that span it. */
        Eigen::Vector3d nearestOnTriangle(Simplex &s, const Eigen::Vector3d &a, const Eigen::Vector3d &b,
                                          const Eigen::Vector3d &c)
        {
            const Eigen::Vector3d ab = b - a, ac = c - a;
            const double d1 = -ab.dot(a), d2 = -ac.dot(a);
            if (d1 <= 0.0 && d2 <= 0.0)
            {
                s.points[0] = a, s.size = 1;
                return a;
            }
            const double d3 = -ab.dot(b), d4 = -ac.dot(b);
            if (d3 >= 0.0 && d4 <= d3)
            {
                s.points[0] = b, s.size = 1;
                return b;
            }
            const double vc = d1 * d4 - d3 * d2;
            if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
                return nearestOnSegment(s, a, b);
            const double d5 = -ab.dot(c), d6 = -ac.dot(c);
            if (d6 >= 0.0 && d5 <= d6)
            {
                s.points[0] = c, s.size = 1;
                return c;
            }
            const double vb = d5 * d2 - d1 * d6;
            if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
                return nearestOnSegment(s, a, c);
            const double va = d3 * d6 - d5 * d4;
            if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
                return nearestOnSegment(s, b, c);
            const double area = va + vb + vc;  // |ab x ac|^2
            if (area <= FLAT * ab.squaredNorm() * ac.squaredNorm())
            {
                // a flat triangle: the nearest of its edges
                Simplex edge;
                Eigen::Vector3d best = nearestOnSegment(s, a, b);
                for (const auto &[p, q] : {std::pair{a, c}, std::pair{b, c}})
                {
                    const Eigen::Vector3d point = nearestOnSegment(edge, p, q);
                    if (point.squaredNorm() < best.squaredNorm())
                        best = point, s = edge;
                }
                return best;
            }
            s.points[0] = a, s.points[1] = b, s.points[2] = c, s.size = 3;
            return a + (vb / area) * ab + (vc / area) * ac;
        }

        /** Nearest point to the origin on tetrahedron a b c d, or nullopt when the origin lies
            inside it; the simplex keeps the corners that span the point. */
        std::optional<Eigen::Vector3d> nearestOnTetrahedron(Simplex &s, const Eigen::Vector3d &a,
                                                            const Eigen::Vector3d &b,
                                                            const Eigen::Vector3d &c,
                                                            const Eigen::Vector3d &d)
        {
            const Eigen::Vector3d corners[4] = {a, b, c, d};
            // each face with the corner it leaves out
            static constexpr int FACES[4][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}};
            const double scale =
                std::max({(b - a).squaredNorm(), (c - a).squaredNorm(), (d - a).squaredNorm()});
            bool outsideAny = false;
            double nearest = std::numeric_limits<double>::infinity();
            Eigen::Vector3d best = a;
            for (const auto &face : FACES)
            {
                const Eigen::Vector3d &p = corners[face[0]], &q = corners[face[1]], &r = corners[face[2]];
                const Eigen::Vector3d normal = (q - p).cross(r - p);
                const double originSide = -normal.dot(p);
                const double cornerSide = normal.dot(corners[face[3]] - p);
                // a flat tetrahedron has no inside: every face counts as facing the origin
                const bool flat = cornerSide * cornerSide <= FLAT * scale * scale * scale;
                if (!flat && originSide * cornerSide >= 0.0)
                    continue;
                outsideAny = true;
                Simplex faceSimplex;
                const Eigen::Vector3d point = nearestOnTriangle(faceSimplex, p, q, r);
                if (point.squaredNorm() < nearest)
                {
                    nearest = point.squaredNorm();
                    best = point;
                    s = faceSimplex;
                }
            }
            if (!outsideAny)
                return std::nullopt;
            return best;
        }

        /** The point nearest the origin of the simplex's hull, the simplex reduced to the points
            that span it; nullopt when the hull holds the origin. */
        std::optional<Eigen::Vector3d> nearestToOrigin(Simplex &s)
        {
            const Simplex in = s;
            switch (in.size)
            {
                case 1:
                    return in.points[0];
                case 2:
                    return nearestOnSegment(s, in.points[0], in.points[1]);
                case 3:
                    return nearestOnTriangle(s, in.points[0], in.points[1], in.points[2]);
                default:
                    return nearestOnTetrahedron(s, in.points[0], in.points[1], in.points[2], in.points[3]);
            }
        }
    }  // namespace

    double convexDistance(const ConvexShape &a, const Eigen::Isometry3d &frameA, const ConvexShape &b,
                          const Eigen::Isometry3d &frameB, double tolerance)
    {
        // in a's frame: the Minkowski difference a - b of the cores, and its support mapping
        const Eigen::Isometry3d bInA = frameA.inverse() * frameB;
        const Eigen::Matrix3d &rotation = bInA.linear();
        const Eigen::Vector3d &offset = bInA.translation();
        const auto support = [&](const Eigen::Vector3d &direction) -> Eigen::Vector3d {
            return a.support(direction) -
                   (rotation * b.support(-(rotation.transpose() * direction)) + offset);
        };
        const double margins = a.margin() + b.margin();

        // the centres' difference is a point of it: a first direction
        Eigen::Vector3d v = -offset;
        if (v.squaredNorm() == 0.0)
            return -margins;
        Simplex simplex;
        double lower = 0.0;
        for (unsigned int iteration = 0; iteration < MAX_GJK_ITERATIONS; ++iteration)
        {
            const Eigen::Vector3d w = support(-v);
            const double squared = v.squaredNorm();
            const double length = std::sqrt(squared);
            const double along = v.dot(w);
            // the plane through w normal to v has all of the difference on the far side
            if (along > 0.0)
                lower = std::max(lower, along / length);
            if (length - lower <= tolerance || squared - along <= LEAST_PROGRESS * squared)
                break;
            simplex.points[simplex.size++] = w;
            const std::optional<Eigen::Vector3d> nearest = nearestToOrigin(simplex);
            if (!nearest)
                return -margins;  // the cores overlap
            if (iteration > 0 && nearest->squaredNorm() >= squared)
                break;  // rounding: no nearer point
            v = *nearest;
        }
        return lower - margins;
    }
}  // namespace ompl_mm
