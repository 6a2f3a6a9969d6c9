#include "ompl_phys/knowledge/Footprint.h"

#include <algorithm>
#include <cmath>

namespace ompl_phys
{
    namespace
    {
        double segmentDistance(const Eigen::Vector2d &p, const Eigen::Vector2d &a, const Eigen::Vector2d &b)
        {
            const Eigen::Vector2d ab = b - a;
            const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
            return (p - (a + t * ab)).norm();
        }

        /** Distance from p to a counter-clockwise triangle; 0 inside. */
        double triangleDistance(const Eigen::Vector2d &p, const Eigen::Matrix<double, 2, 3> &t)
        {
            bool inside = true;
            double nearest = std::numeric_limits<double>::infinity();
            for (int i = 0; i < 3; ++i)
            {
                const Eigen::Vector2d a = t.col(i);
                const Eigen::Vector2d b = t.col((i + 1) % 3);
                inside = inside && cross(b - a, p - a) >= 0.0;
                nearest = std::min(nearest, segmentDistance(p, a, b));
            }
            return inside ? 0.0 : nearest;
        }
    }  // namespace

    double footprintDistance(const PhysicsShape &shape, const Eigen::Vector2d &position, double yaw,
                             const Eigen::Vector2d &point)
    {
        const Eigen::Vector2d local = Eigen::Rotation2Dd(-yaw) * (point - position);
        switch (shape.kind)
        {
            case PhysicsShape::Kind::Box:
            {
                const Eigen::Vector2d outside =
                    (local.cwiseAbs() - 0.5 * shape.boxSize.head<2>()).cwiseMax(0.0);
                return outside.norm();
            }
            case PhysicsShape::Kind::Prism:
                return triangleDistance(local, shape.triangle);
            case PhysicsShape::Kind::Cylinder:
            case PhysicsShape::Kind::Sphere:
                break;
        }
        return std::max(0.0, local.norm() - shape.radius);
    }

    double yawOf(const Eigen::Quaterniond &orientation)
    {
        const Eigen::Vector3d x = orientation * Eigen::Vector3d::UnitX();
        return std::atan2(x.y(), x.x());
    }

    double cross(const Eigen::Vector2d &a, const Eigen::Vector2d &b)
    {
        return a.x() * b.y() - a.y() * b.x();
    }
}  // namespace ompl_phys
