#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <string>
#include <vector>

namespace ompl_mm
{
    /** A triangle mesh in its own frame, metres (scaled as its URDF element asked), with the
        measures shapes need. Shared, immutable: links that use one file share one mesh. */
    struct TriangleMesh
    {
        std::string file;                           ///< the file it was read from
        std::vector<Eigen::Vector3d> vertices;      ///< corners, metres
        std::vector<std::array<int, 3>> triangles;  ///< faces: indices into vertices
        Eigen::AlignedBox3d bounds;                 ///< of the vertices
        double boundingRadius{0.0};                 ///< largest distance of a vertex from the origin, metres
        double footprintRadius{0.0};                ///< largest distance of a vertex from the z axis, metres

        /** Sets bounds and the radii from the vertices. */
        void measure();
    };
}  // namespace ompl_mm
