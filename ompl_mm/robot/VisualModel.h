/* How a URDF robot looks: its links' <visual> geometry with colours, for pictures only (the planner
   never reads it, so loading a scene stays fast however detailed the robot's visual meshes are). */
#pragma once

#include "ompl_mm/robot/RobotModel.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <optional>
#include <string>
#include <vector>

namespace ompl_mm
{
    /** A colour: red, green, blue and opacity, each from 0 to 1. */
    using Rgba = Eigen::Vector4d;

    /** One solid of a link's look, in one colour. */
    struct VisualShape
    {
        /** A box, cylinder or sphere; or a mesh: the triangles of one material of a mesh file,
            scaled as the element asks, shared by every link that uses the file at that scale. */
        Shape shape;
        Eigen::Isometry3d origin{Eigen::Isometry3d::Identity()};  ///< the shape's frame in the link frame
        /** The mesh file's colour for the material (its diffuse colour, e.g. an OBJ's .mtl `Kd`)
            when the file names a material; else the colour of the visual's URDF `<material>`
            (given there, or by name in a `<material>` elsewhere in the file); none when neither
            gives one. */
        std::optional<Rgba> colour;
    };

    /** How one link looks. Plain data. */
    struct LinkVisual
    {
        std::vector<VisualShape> shapes;  ///< none for a link with neither visual nor collision geometry
        /** True when shapes are the link's collision shapes (without colour): the link has no
            `<visual>`, or one of its visual meshes could not be found or read. */
        bool fromCollision{false};
        /** Why a link that has `<visual>` elements shows its collision shapes ("file:line: link
            'name': visual mesh ... not found ..."); empty otherwise. */
        std::string warning;
    };

    /** The look of a robot: for each link its `<visual>` boxes, cylinders, spheres and meshes,
        each with its origin and colour. Mesh files are found as RobotModel finds collision meshes
        (resolveMeshFile()) and read through assimp, one shape per material. A link without
        `<visual>` shows its collision shapes; so does a link with a visual mesh file that is
        missing or cannot be read, with a warning (logged with OMPL_WARN and kept in its
        LinkVisual): a picture does not fail for want of a mesh. Textures, vertex colours and
        material opacity are not read. Copyable value type; meshes are shared between copies. */
    class VisualModel
    {
    public:
        /** Reads the `<visual>` elements of the URDF file for the links of robot (read from the
            same file, maybe with joints fixed since), matched by name.
            @throws ompl_core::InputError naming the file, and the line where known, when the file
            cannot be read or is no URDF, or for a visual whose geometry is missing, unknown or of
            non-positive size, a malformed origin, or a colour outside 0 to 1. */
        static VisualModel fromUrdfFile(const std::string &urdfFile, const RobotModel &robot);

        /** Every link of robot showing its collision shapes (for a robot without a URDF file). */
        static VisualModel fromCollision(const RobotModel &robot);

        /** One entry per link of the robot, in RobotModel::links() order. */
        const std::vector<LinkVisual> &links() const { return links_; }

        /** The links' warnings (LinkVisual::warning), in link order, the empty ones left out. */
        std::vector<std::string> warnings() const;

    private:
        std::vector<LinkVisual> links_;
    };
}  // namespace ompl_mm
