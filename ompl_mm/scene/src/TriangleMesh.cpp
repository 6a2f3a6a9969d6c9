#include "ompl_mm/scene/TriangleMesh.h"

#include <ompl/util/Exception.h>

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

    std::shared_ptr<const ConvexHull> TriangleMesh::convexHull() const
    {
        std::lock_guard<std::mutex> guard(hullLock_);
        if (hull_ == nullptr)
        {
            try
            {
                hull_ = std::make_shared<const ConvexHull>(computeConvexHull(vertices));
            }
            catch (const ompl::Exception &e)
            {
                throw ompl::Exception("mesh '" + file + "'", e.what());
            }
        }
        return hull_;
    }
}  // namespace ompl_mm
