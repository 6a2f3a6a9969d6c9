#pragma once

#include "ompl_mm/scene/Scene.h"

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <vector>

namespace ompl_mm
{
    /** A convex solid described by its support mapping, for GJK distance queries (convexDistance):
        a box, a cylinder along z or the corners of a convex polytope, each centred in its own frame,
        or a sphere, which is its centre (a core point) grown by a margin. Copyable; a polytope
        shares its corners. */
    class ConvexShape
    {
    public:
        /** A box of edge lengths size, metres. */
        static ConvexShape box(const Eigen::Vector3d &size);
        /** A cylinder of radius and length along z, metres. */
        static ConvexShape cylinder(double radius, double length);
        /** A sphere of radius, metres. */
        static ConvexShape sphere(double radius);
        /** The convex hull of corners (not empty), in the shape's frame. */
        static ConvexShape polytope(std::shared_ptr<const std::vector<Eigen::Vector3d>> corners);

        /** The convex shape a collision shape is, as the collision checks take it: boxes,
            cylinders and spheres; a mesh when meshes asks for its convex hull; nullopt for a mesh
            taken as its triangles (not convex). */
        static std::optional<ConvexShape> of(const Shape &shape, MeshCollision meshes);

        /** A point of the core farthest along direction (the shape's frame; any direction, the
            zero vector included). */
        Eigen::Vector3d support(const Eigen::Vector3d &direction) const;
        /** How far the shape reaches beyond its core in every direction, metres (a sphere's radius,
            0 otherwise). */
        double margin() const { return margin_; }

    private:
        enum class Kind
        {
            Point,
            Box,
            Cylinder,
            Polytope
        };
        explicit ConvexShape(Kind kind) : kind_(kind) {}

        Kind kind_;
        Eigen::Vector3d halfSize_{Eigen::Vector3d::Zero()};  ///< box half edges; cylinder (r, r, half length)
        double margin_{0.0};
        std::shared_ptr<const std::vector<Eigen::Vector3d>> corners_;
        /** A mesh hull's polytope: its vertex graph, walked uphill by support(); null otherwise. */
        std::shared_ptr<const ConvexHull> hull_;
    };
}  // namespace ompl_mm
