#include "ompl_mm/scene/Scene.h"

#include "ompl_core/io/InputError.h"

#include <ompl/util/Exception.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ompl_mm
{
    namespace
    {
        [[noreturn]] void throwInvalidKind(const char *function, Shape::Kind kind)
        {
            // only a Kind value cast from an out-of-range integer gets here
            throw ompl::Exception(function, "invalid shape kind " + std::to_string(static_cast<int>(kind)));
        }
    }  // namespace

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
            case Kind::Mesh:
                return mesh->bounds.sizes().z();
        }
        throwInvalidKind("Shape::height", kind);
    }

    double Shape::footprintRadius() const
    {
        switch (kind)
        {
            case Kind::Box:
                return 0.5 * boxSize.head<2>().norm();
            case Kind::Cylinder:
            case Kind::Sphere:
                return radius;
            case Kind::Mesh:
                return mesh->footprintRadius;
        }
        throwInvalidKind("Shape::footprintRadius", kind);
    }

    double Shape::boundingRadius() const
    {
        switch (kind)
        {
            case Kind::Box:
                return 0.5 * boxSize.norm();
            case Kind::Cylinder:
                return std::hypot(radius, 0.5 * length);
            case Kind::Sphere:
                return radius;
            case Kind::Mesh:
                return mesh->boundingRadius;
        }
        throwInvalidKind("Shape::boundingRadius", kind);
    }

    bool SupportSurface::contains(double x, double y) const
    {
        return x >= min.x() && x <= max.x() && y >= min.y() && y <= max.y();
    }

    bool SupportSurface::supports(const Eigen::Vector3d &base) const
    {
        return restMargin(base) > 0.0;
    }

    double SupportSurface::restMargin(const Eigen::Vector3d &base) const
    {
        const double inside =
            std::min({base.x() - min.x(), max.x() - base.x(), base.y() - min.y(), max.y() - base.y()});
        return REST_TOLERANCE - std::max(std::abs(base.z() - height), -inside);
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

    double Scene::restMargin(const Eigen::Vector3d &base, const std::function<bool(int)> &counts) const
    {
        // some counted surface supports the base and no surface before it does
        double margin = -std::numeric_limits<double>::infinity();
        double noneBefore = std::numeric_limits<double>::infinity();
        for (std::size_t s = 0; s < surfaces.size(); ++s)
        {
            const double supports = surfaces[s].restMargin(base);
            if (counts(static_cast<int>(s)))
                margin = std::max(margin, std::min(supports, noneBefore));
            noneBefore = std::min(noneBefore, -supports);
        }
        return margin;
    }

    void Scene::setPushModel(const std::string &model)
    {
        if (model != "kinematic" && model != "physics")
            throw ompl_core::InputError("the push model must be kinematic or physics, got '" + model + "'");
        for (PrimitiveSpec &spec : primitives)
            if (spec.type.rfind("push_", 0) == 0)
                spec.params["model"] = model;
    }
}  // namespace ompl_mm
