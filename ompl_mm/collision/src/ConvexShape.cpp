#include "ompl_mm/collision/ConvexShape.h"

#include "ompl_mm/scene/ConvexHull.h"
#include "ompl_mm/scene/TriangleMesh.h"

#include <cmath>

namespace ompl_mm
{
    ConvexShape ConvexShape::box(const Eigen::Vector3d &size)
    {
        ConvexShape shape(Kind::Box);
        shape.halfSize_ = 0.5 * size;
        return shape;
    }

    ConvexShape ConvexShape::cylinder(double radius, double length)
    {
        ConvexShape shape(Kind::Cylinder);
        shape.halfSize_ = {radius, radius, 0.5 * length};
        return shape;
    }

    ConvexShape ConvexShape::sphere(double radius)
    {
        ConvexShape shape(Kind::Point);
        shape.margin_ = radius;
        return shape;
    }

    ConvexShape ConvexShape::polytope(std::shared_ptr<const std::vector<Eigen::Vector3d>> corners)
    {
        ConvexShape shape(Kind::Polytope);
        shape.corners_ = std::move(corners);
        return shape;
    }

    std::optional<ConvexShape> ConvexShape::of(const Shape &shape, MeshCollision meshes)
    {
        switch (shape.kind)
        {
            case Shape::Kind::Box:
                return box(shape.boxSize);
            case Shape::Kind::Cylinder:
                return cylinder(shape.radius, shape.length);
            case Shape::Kind::Sphere:
                return sphere(shape.radius);
            case Shape::Kind::Mesh:
                if (meshes == MeshCollision::ConvexHull)
                {
                    // the corners stay with the mesh's hull, shared
                    const std::shared_ptr<const ConvexHull> hull = shape.mesh->convexHull();
                    ConvexShape polytope = ConvexShape::polytope({hull, &hull->vertices});
                    polytope.hull_ = hull;
                    return polytope;
                }
                return std::nullopt;
        }
        return std::nullopt;
    }

    Eigen::Vector3d ConvexShape::support(const Eigen::Vector3d &direction) const
    {
        switch (kind_)
        {
            case Kind::Point:
                return Eigen::Vector3d::Zero();
            case Kind::Box:
                return {std::copysign(halfSize_.x(), direction.x()),
                        std::copysign(halfSize_.y(), direction.y()),
                        std::copysign(halfSize_.z(), direction.z())};
            case Kind::Cylinder:
            {
                // the rim point towards the direction's horizontal part, on the cap it points to
                // sqrt rather than hypot: no overflow to guard against here, and hypot is slow
                const double horizontal =
                    std::sqrt(direction.x() * direction.x() + direction.y() * direction.y());
                const double scale = horizontal > 0.0 ? halfSize_.x() / horizontal : 0.0;
                return {scale * direction.x(), scale * direction.y(),
                        std::copysign(halfSize_.z(), direction.z())};
            }
            case Kind::Polytope:
            {
                const std::vector<Eigen::Vector3d> &corners = *corners_;
                if (hull_)
                {
                    // uphill along the hull's edges from the best axis extreme: a vertex no neighbour
                    // of which lies farther is the farthest of a convex polytope
                    int best = hull_->extremes[0];
                    for (const int extreme : hull_->extremes)
                        if (corners[extreme].dot(direction) > corners[best].dot(direction))
                            best = extreme;
                    double farthest = corners[best].dot(direction);
                    for (bool climbed = true; climbed;)
                    {
                        climbed = false;
                        for (int k = hull_->neighbourStart[best]; k < hull_->neighbourStart[best + 1]; ++k)
                        {
                            const double along = corners[hull_->neighbours[k]].dot(direction);
                            if (along > farthest)
                            {
                                farthest = along;
                                best = hull_->neighbours[k];
                                climbed = true;
                            }
                        }
                    }
                    return corners[best];
                }
                std::size_t best = 0;
                double farthest = corners[0].dot(direction);
                for (std::size_t i = 1; i < corners.size(); ++i)
                {
                    const double along = corners[i].dot(direction);
                    if (along > farthest)
                    {
                        farthest = along;
                        best = i;
                    }
                }
                return corners[best];
            }
        }
        return Eigen::Vector3d::Zero();
    }
}  // namespace ompl_mm
