#include "ompl_phys/scene/PhysicsScene.h"

#include <ompl/util/Exception.h>

#include <algorithm>

namespace ompl_phys
{
    double PhysicsShape::halfHeight() const
    {
        switch (kind)
        {
            case Kind::Box:
                return 0.5 * boxSize.z();
            case Kind::Sphere:
                return radius;
            case Kind::Cylinder:
            case Kind::Prism:
                break;
        }
        return 0.5 * length;
    }

    double PhysicsShape::boundingRadius() const
    {
        switch (kind)
        {
            case Kind::Box:
                return 0.5 * boxSize.head<2>().norm();
            case Kind::Cylinder:
            case Kind::Sphere:
                break;
            case Kind::Prism:
                return triangle.colwise().norm().maxCoeff();
        }
        return radius;
    }

    std::size_t PhysicsScene::bodyIndex(const std::string &bodyName) const
    {
        const auto found = std::find_if(bodies.begin(), bodies.end(),
                                        [&](const PhysicsBody &body) { return body.name == bodyName; });
        if (found == bodies.end())
            throw ompl::Exception("PhysicsScene", "no body named '" + bodyName + "' in scene '" + name + "'");
        return static_cast<std::size_t>(found - bodies.begin());
    }

    std::vector<std::size_t> PhysicsScene::movableBodies() const
    {
        std::vector<std::size_t> movable;
        for (std::size_t i = 0; i < bodies.size(); ++i)
            if (bodies[i].kind != BodyKind::Fixed)
                movable.push_back(i);
        return movable;
    }
}  // namespace ompl_phys
