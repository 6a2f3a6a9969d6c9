/* ODE set-up, geometry and masses of a physics scene's shapes, for PhysicsWorld and for code that
   builds an ODE world of its own (benchmarks/bench_opende_peer, ompl_mmphys). Needs ODE's headers
   (libode-dev). */
#pragma once

#include "ompl_phys/scene/PhysicsScene.h"

#include <ode/ode.h>

#include <array>
#include <deque>

namespace ompl_phys
{
    /** The arrays ODE reads an upright triangular prism from, as a convex, while its geom lives. */
    struct ConvexPrismData
    {
        std::array<dReal, 20> planes;           ///< three sides, top, bottom: normal and distance
        std::array<dReal, 18> points;           ///< the corners on top, then below
        std::array<unsigned int, 23> polygons;  ///< per face its corner count, then its corners
    };

    /** Initialises ODE once per process (and closes it at exit); call before making a world. */
    void initialiseOde();

    /** Puts geom (one without a body) at pose in the world. */
    void placeGeom(dGeomID geom, const Eigen::Isometry3d &pose);

    /** rotation as ODE's row-major 3 x 4 matrix, written to out. */
    void toOdeRotation(const Eigen::Matrix3d &rotation, dMatrix3 &out);

    /** Creates the geom of shape in space, centred at the origin of its frame: ODE's box, cylinder
        (along z) and sphere; a prism becomes a convex whose arrays are appended to prisms (a
        deque, so the arrays of earlier prisms stay where ODE points). */
    dGeomID createShapeGeom(dSpaceID space, const PhysicsShape &shape, std::deque<ConvexPrismData> &prisms);

    /** Gives body the inertia of shape with the total mass, kg (a prism's as its radius's sphere:
        prisms are fixed bodies, which have no mass). */
    void setShapeMass(dBodyID body, const PhysicsShape &shape, double mass);
}  // namespace ompl_phys
