#include "ompl_mm/scene/Scene.h"

#include <ompl/util/Exception.h>

namespace ompl_mm
{
    double Shape::height() const
    {
        switch (kind)
        {
            case Kind::Box:
                return boxSize.z();
            case Kind::Cylinder:
                return length;
            case Kind::Sphere:
                return 2.0 * radius;
        }
        // only a Kind value cast from an out-of-range integer gets here
        throw ompl::Exception("Shape::height",
                              "invalid shape kind " + std::to_string(static_cast<int>(kind)));
    }

    int Scene::objectIndex(const std::string &name) const
    {
        for (std::size_t i = 0; i < objects.size(); ++i)
            if (objects[i].name == name)
                return static_cast<int>(i);
        return -1;
    }

    int Scene::restingSurface(const Eigen::Vector3d &base) const
    {
        for (std::size_t i = 0; i < surfaces.size(); ++i)
            if (surfaces[i].supports(base))
                return static_cast<int>(i);
        return -1;
    }
}  // namespace ompl_mm
