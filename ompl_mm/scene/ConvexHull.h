/* The convex hull of a point set in 3-D (quickhull), for conservative collision geometry of meshes. */
#pragma once

#include <Eigen/Core>

#include <array>
#include <vector>

namespace ompl_mm
{
    /** A closed convex polytope as triangles: the corners of a point set's convex hull and its
        faces, each counter-clockwise seen from outside (its normal (v1 - v0) x (v2 - v0) points
        out). Coplanar faces stay split into triangles (a cube has 12). Plain data, copyable. */
    struct ConvexHull
    {
        std::vector<Eigen::Vector3d> vertices;      ///< corners: input points, each used by a face
        std::vector<std::array<int, 3>> triangles;  ///< faces: indices into vertices, outward
        /** The vertices joined to vertex v by an edge are neighbours[neighbourStart[v]] up to
            neighbours[neighbourStart[v + 1]]: walking them uphill finds the vertex farthest along a
            direction without looking at every vertex. */
        std::vector<int> neighbourStart;
        std::vector<int> neighbours;    ///< see neighbourStart
        std::array<int, 6> extremes{};  ///< the vertices farthest along +x, -x, +y, -y, +z, -z

        /** Points closer to a face's plane than this many times the point set's size (the sum of
            its largest absolute coordinates) count as on the plane: the hull leaves them out, so
            it may miss a point by about that distance, and points this flat count as coplanar.
            Mesh files store single-precision coordinates (relative rounding 6e-8): a tolerance
            below theirs would keep the rounding noise of flat tessellated faces as corners and
            sliver triangles. */
        static constexpr double RELATIVE_TOLERANCE = 1e-7;
    };

    /** The convex hull of points by quickhull (C. B. Barber, D. P. Dobkin, H. Huhdanpaa, "The
        Quickhull Algorithm for Convex Hulls", ACM TOMS 22(4), 1996, doi:10.1145/235815.235821),
        without merging coplanar faces. Expected time O(n log n). Every extreme point is a corner;
        points on the hull's boundary may be corners too. Where many points lie near a plane without
        being in it (rounding noise of a tessellated flat face), faces may be thin and tilted:
        points may then lie outside such a face's plane by more than the tolerance, but the hull
        still reaches as far as the points in every direction (to within the tolerance).
        @throws ompl::Exception naming the cause when the points span no volume: fewer than 4, a
        coordinate that is not finite, or all of them coincident, collinear or coplanar (within
        ConvexHull::RELATIVE_TOLERANCE); and, as an always-on check, when rounding breaks the
        hull's topology (every edge shared by two faces). */
    ConvexHull computeConvexHull(const std::vector<Eigen::Vector3d> &points);
}  // namespace ompl_mm
