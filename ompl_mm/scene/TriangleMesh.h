#pragma once

#include "ompl_mm/scene/ConvexHull.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace ompl_mm
{
    /** A triangle mesh in its own frame, metres (scaled as its URDF element asked), with the
        measures shapes need and, on demand, its convex hull. Shared, immutable once filled: links
        that use one file share one mesh. Not copyable or movable (it holds the hull's lock). */
    struct TriangleMesh
    {
        std::string file;                           ///< the file it was read from
        std::vector<Eigen::Vector3d> vertices;      ///< corners, metres
        std::vector<std::array<int, 3>> triangles;  ///< faces: indices into vertices
        Eigen::AlignedBox3d bounds;                 ///< of the vertices
        double boundingRadius{0.0};                 ///< largest distance of a vertex from the origin, metres
        double footprintRadius{0.0};                ///< largest distance of a vertex from the z axis, metres

        TriangleMesh() = default;
        TriangleMesh(const TriangleMesh &) = delete;             ///< not copyable
        TriangleMesh &operator=(const TriangleMesh &) = delete;  ///< not copyable

        /** Sets bounds and the radii from the vertices. */
        void measure();

        /** The convex hull of the vertices, computed on the first call and kept for the mesh's
            life (thread-safe). @pre the vertices do not change after the first call.
            @throws ompl::Exception naming file and the cause when the vertices span no volume
            (fewer than 4, or all coplanar; see computeConvexHull()). */
        std::shared_ptr<const ConvexHull> convexHull() const;

    private:
        mutable std::mutex hullLock_;
        mutable std::shared_ptr<const ConvexHull> hull_;
    };
}  // namespace ompl_mm
