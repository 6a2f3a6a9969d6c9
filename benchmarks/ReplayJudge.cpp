#include "ReplayJudge.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace opende_peer
{
    namespace
    {
        /** The deepest overlap of two geoms, m (0 when apart). */
        double depth(dGeomID a, dGeomID b)
        {
            std::array<dContactGeom, 16> contacts;
            const int count =
                dCollide(a, b, static_cast<int>(contacts.size()), contacts.data(), sizeof(dContactGeom));
            double deepest = 0.0;
            for (int i = 0; i < count; ++i)
                deepest = std::max(deepest, contacts[i].depth);
            return deepest;
        }
    }  // namespace

    ReplayJudge::ReplayJudge(ompl_phys::PhysicsScenePtr scene) : probe_(std::move(scene))
    {
        for (std::size_t body : probe_.scene().movableBodies())
            hasUp_.push_back(probe_.scene().bodies[body].shape.kind != ompl_phys::PhysicsShape::Kind::Sphere);
    }

    std::string ReplayJudge::fault(const ompl_phys::BodyStates &states) const
    {
        probe_.placeBodies(states);
        for (dGeomID fixed : probe_.fixedGeoms())
            if (depth(probe_.robotGeom(), fixed) > PENETRATION_TOLERANCE)
                return "robot inside a fixed body";
        for (std::size_t i = 0; i < probe_.movableGeoms().size(); ++i)
        {
            const dGeomID body = probe_.movableGeoms()[i];
            if (depth(body, probe_.floorGeom()) > PENETRATION_TOLERANCE)
                return "body sunk into the floor";
            for (dGeomID fixed : probe_.fixedGeoms())
                if (depth(body, fixed) > PENETRATION_TOLERANCE)
                    return "body sunk into a fixed body";
            const Eigen::Vector3d up = states[i + 1].orientation * Eigen::Vector3d::UnitZ();
            if (hasUp_[i] && std::acos(std::clamp(up.z(), -1.0, 1.0)) > TIP_TOLERANCE)
                return "body tipped over";
        }
        return {};
    }
}  // namespace opende_peer
