/* Meshes made smaller for the 3-D plan page: vertex clustering on a grid, so that a robot's visual
   meshes (a Franka Panda's are 100 000 triangles) make a page of a few megabytes that a browser
   draws at once. */
#pragma once

#include "ompl_core/io/PlanViewer.h"
#include "ompl_mm/scene/TriangleMesh.h"

#include <array>
#include <cstddef>
#include <vector>

namespace ompl_mm
{
    /** The mesh (vertices, and triangles indexing them) with its vertices clustered on a grid of
        cubes cellSize wide, as J. Rossignac and P. Borrel, "Multi-resolution 3D approximations for
        rendering complex scenes", Modeling in Computer Graphics, Springer 1993,
        doi:10.1007/978-3-642-78114-8_29: the vertices in one cell become one vertex at their mean;
        a triangle with two corners in one cell vanishes, and one on the same three cells as an
        earlier one is dropped; vertices no triangle uses are dropped. So every vertex of the result
        is the mean of vertices of the input in one cell: it lies in the input's bounding box, within
        cellSize * sqrt(3) of each of those vertices. Thin parts narrower than a cell may vanish.
        The grid starts at the bounding box's lower corner and has at most 2^20 cells along an axis
        (larger cells when cellSize would make more).
        @throws ompl::Exception unless cellSize is positive and finite, or when a triangle names a
        vertex that does not exist. */
    ompl_core::ViewerMesh clusterVertices(const std::vector<Eigen::Vector3d> &vertices,
                                          const std::vector<std::array<int, 3>> &triangles, double cellSize);

    /** How far reduceMesh() reduces a mesh. Plain data. */
    struct MeshReduction
    {
        /** A mesh with at most this many vertices is kept as it is; a larger one is clustered until
            at most this many remain. 3000 by default (a Franka Panda page is about 2 MB). */
        std::size_t maxVertices{3000};
        /** The first cell tried, as a fraction of the mesh's bounding-box diagonal; each further try
            makes the cells a quarter larger. 0.01 by default. */
        double firstCell{0.01};
    };

    /** A mesh made smaller for a page, with the cell size that did it. */
    struct ReducedMesh
    {
        ompl_core::ViewerMesh mesh;  ///< the vertices and triangles
        double cellSize{0.0};        ///< edge of the clustering grid's cells, metres; 0 when kept as it was
    };

    /** The mesh as it is when it has at most reduction.maxVertices vertices, else clustered
        (clusterVertices()) on the finest grid, among firstCell and the sizes a quarter larger each,
        that leaves at most maxVertices vertices.
        @throws ompl::Exception when maxVertices is below 3 or firstCell is not positive. */
    ReducedMesh reduceMesh(const TriangleMesh &mesh, const MeshReduction &reduction = MeshReduction());
}  // namespace ompl_mm
