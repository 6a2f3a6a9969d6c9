#include "ompl_mm/scene/TriangleMesh.h"

#include <algorithm>

namespace ompl_mm
{
    void TriangleMesh::measure()
    {
        bounds.setEmpty();
        boundingRadius = 0.0;
        footprintRadius = 0.0;
        for (const Eigen::Vector3d &v : vertices)
        {
            bounds.extend(v);
            boundingRadius = std::max(boundingRadius, v.norm());
            footprintRadius = std::max(footprintRadius, v.head<2>().norm());
        }
    }
}  // namespace ompl_mm
