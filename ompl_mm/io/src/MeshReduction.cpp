#include "ompl_mm/io/MeshReduction.h"

#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <string>
#include <unordered_map>

namespace ompl_mm
{
    namespace
    {
        /** Most cells along an axis of a clustering grid. */
        constexpr double MAX_CELLS = 1048576.0;

        /** The grid cell of a point: its three indices packed into one key (21 bits each). */
        std::uint64_t cellKey(const Eigen::Vector3d &point, const Eigen::Vector3d &origin, double cellSize)
        {
            std::uint64_t key = 0;
            for (int k = 0; k < 3; ++k)
            {
                // a coordinate that is not finite goes to the first cell rather than to undefined behaviour
                double index = std::floor((point[k] - origin[k]) / cellSize);
                index = std::isfinite(index) ? index : 0.0;
                key =
                    (key << 21) | (static_cast<std::uint64_t>(std::clamp(index, 0.0, 2097151.0)) & 0x1fffff);
            }
            return key;
        }
    }  // namespace

    ompl_core::ViewerMesh clusterVertices(const std::vector<Eigen::Vector3d> &vertices,
                                          const std::vector<std::array<int, 3>> &triangles, double cellSize)
    {
        if (!(cellSize > 0.0) || !std::isfinite(cellSize))
            throw ompl::Exception("clusterVertices", "the cell size must be positive and finite, got " +
                                                         std::to_string(cellSize));
        Eigen::AlignedBox3d box;
        for (const Eigen::Vector3d &v : vertices)
            box.extend(v);
        // a key holds 2^21 cells an axis
        if (!vertices.empty())
            cellSize = std::max(cellSize, box.sizes().maxCoeff() / MAX_CELLS);
        // each vertex's cluster: clusters numbered in order of first appearance
        std::unordered_map<std::uint64_t, int> clusterOfCell;
        std::vector<int> clusterOf(vertices.size());
        std::vector<Eigen::Vector3d> sums;
        std::vector<int> counts;
        for (std::size_t i = 0; i < vertices.size(); ++i)
        {
            const auto [at, added] = clusterOfCell.emplace(cellKey(vertices[i], box.min(), cellSize),
                                                           static_cast<int>(sums.size()));
            if (added)
            {
                sums.push_back(Eigen::Vector3d::Zero());
                counts.push_back(0);
            }
            clusterOf[i] = at->second;
            sums[static_cast<std::size_t>(at->second)] += vertices[i];
            ++counts[static_cast<std::size_t>(at->second)];
        }
        // the triangles on three distinct clusters, each set of clusters once
        ompl_core::ViewerMesh reduced;
        std::set<std::array<int, 3>> seen;
        std::vector<int> newIndex(sums.size(), -1);
        for (const std::array<int, 3> &t : triangles)
        {
            std::array<int, 3> corners{};
            for (int k = 0; k < 3; ++k)
            {
                if (t[k] < 0 || static_cast<std::size_t>(t[k]) >= vertices.size())
                    throw ompl::Exception("clusterVertices", "a triangle names vertex " +
                                                                 std::to_string(t[k]) + " of " +
                                                                 std::to_string(vertices.size()));
                corners[k] = clusterOf[static_cast<std::size_t>(t[k])];
            }
            std::array<int, 3> sorted = corners;
            std::sort(sorted.begin(), sorted.end());
            if (sorted[0] == sorted[1] || sorted[1] == sorted[2] || !seen.insert(sorted).second)
                continue;
            std::array<int, 3> face{};
            for (int k = 0; k < 3; ++k)
            {
                int &index = newIndex[static_cast<std::size_t>(corners[k])];
                if (index < 0)
                {
                    index = static_cast<int>(reduced.vertices.size());
                    const auto c = static_cast<std::size_t>(corners[k]);
                    reduced.vertices.push_back(sums[c] / counts[c]);
                }
                face[k] = index;
            }
            reduced.triangles.push_back(face);
        }
        return reduced;
    }

    ReducedMesh reduceMesh(const TriangleMesh &mesh, const MeshReduction &reduction)
    {
        if (reduction.maxVertices < 3 || !(reduction.firstCell > 0.0))
            throw ompl::Exception("reduceMesh", "maxVertices must be at least 3 and firstCell positive");
        if (mesh.vertices.size() <= reduction.maxVertices)
            return {{mesh.vertices, mesh.triangles}, 0.0};
        Eigen::AlignedBox3d box;
        for (const Eigen::Vector3d &v : mesh.vertices)
            box.extend(v);
        double cell = reduction.firstCell * std::max(box.diagonal().norm(), 1e-9);
        for (;;)
        {
            ReducedMesh reduced{clusterVertices(mesh.vertices, mesh.triangles, cell), cell};
            if (reduced.mesh.vertices.size() <= reduction.maxVertices)
                return reduced;
            cell *= 1.25;
        }
    }
}  // namespace ompl_mm
