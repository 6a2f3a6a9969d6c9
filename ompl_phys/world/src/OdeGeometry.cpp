#include "ompl_phys/world/OdeGeometry.h"

#include <cstdlib>
#include <mutex>

namespace ompl_phys
{
    namespace
    {
        /** The triangle extruded ±length/2 along z, centred at the body frame, as a convex. */
        dGeomID createPrism(dSpaceID space, const PhysicsShape &shape, ConvexPrismData &prism)
        {
            auto &[planes, points, polygons] = prism;
            const double h = 0.5 * shape.length;
            for (int i = 0; i < 3; ++i)
            {
                const Eigen::Vector2d c = shape.triangle.col(i);
                points[3 * i] = points[9 + 3 * i] = c.x();
                points[3 * i + 1] = points[9 + 3 * i + 1] = c.y();
                points[3 * i + 2] = h;
                points[9 + 3 * i + 2] = -h;
                // side i runs from corner i to corner i+1; counter-clockwise corners put the outside on the
                // right
                const Eigen::Vector2d edge = shape.triangle.col((i + 1) % 3) - c;
                const Eigen::Vector2d normal = Eigen::Vector2d(edge.y(), -edge.x()).normalized();
                planes[4 * i] = normal.x();
                planes[4 * i + 1] = normal.y();
                planes[4 * i + 2] = 0.0;
                planes[4 * i + 3] = normal.dot(c);
            }
            planes[12] = 0.0, planes[13] = 0.0, planes[14] = 1.0, planes[15] = h;
            planes[16] = 0.0, planes[17] = 0.0, planes[18] = -1.0, planes[19] = h;
            // faces in plane order (sides, top, bottom); top corners 0-2, bottom 3-5; each face
            // counter-clockwise seen from outside
            polygons = {4, 3, 4, 1, 0, 4, 4, 5, 2, 1, 4, 5, 3, 0, 2, 3, 0, 1, 2, 3, 5, 4, 3};
            return dCreateConvex(space, planes.data(), 5, points.data(), 6, polygons.data());
        }
    }  // namespace

    void initialiseOde()
    {
        static std::once_flag once;
        std::call_once(once,
                       []
                       {
                           dInitODE2(0);
                           std::atexit(dCloseODE);  // frees ODE's per-thread collision data
                       });
    }

    void toOdeRotation(const Eigen::Matrix3d &rotation, dMatrix3 &out)
    {
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c)
                out[4 * r + c] = rotation(r, c);
        for (int r = 0; r < 3; ++r)
            out[4 * r + 3] = 0.0;
    }

    void placeGeom(dGeomID geom, const Eigen::Isometry3d &pose)
    {
        dMatrix3 rotation;
        toOdeRotation(pose.linear(), rotation);
        dGeomSetPosition(geom, pose.translation().x(), pose.translation().y(), pose.translation().z());
        dGeomSetRotation(geom, rotation);
    }

    dGeomID createShapeGeom(dSpaceID space, const PhysicsShape &shape, std::deque<ConvexPrismData> &prisms)
    {
        switch (shape.kind)
        {
            case PhysicsShape::Kind::Box:
                return dCreateBox(space, shape.boxSize.x(), shape.boxSize.y(), shape.boxSize.z());
            case PhysicsShape::Kind::Cylinder:
                return dCreateCylinder(space, shape.radius, shape.length);
            case PhysicsShape::Kind::Prism:
                return createPrism(space, shape, prisms.emplace_back());
            case PhysicsShape::Kind::Sphere:
                break;
        }
        return dCreateSphere(space, shape.radius);
    }

    void setShapeMass(dBodyID body, const PhysicsShape &shape, double mass)
    {
        dMass m;
        switch (shape.kind)
        {
            case PhysicsShape::Kind::Box:
                dMassSetBoxTotal(&m, mass, shape.boxSize.x(), shape.boxSize.y(), shape.boxSize.z());
                break;
            case PhysicsShape::Kind::Cylinder:
                dMassSetCylinderTotal(&m, mass, 3, shape.radius, shape.length);  // 3: along z
                break;
            case PhysicsShape::Kind::Sphere:
            case PhysicsShape::Kind::Prism:
                dMassSetSphereTotal(&m, mass, shape.radius);
                break;
        }
        dBodySetMass(body, &m);
    }
}  // namespace ompl_phys
