/* What the scene's SVG picture draws, view by view, in world metres: SceneSvg writes it. */
#pragma once

#include "ompl_mm/setup/ManipulationSetup.h"

#include <Eigen/Geometry>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ompl_mm::picture
{
    /** Which world plane a view draws: top (x right, y up) or side (x right, z up, seen from -y). */
    enum class View
    {
        Top,  ///< seen from above
        Side  ///< seen from -y
    };

    /** A world point in a view's plane. */
    inline Eigen::Vector2d project(View view, const Eigen::Vector3d &p)
    {
        return {p.x(), view == View::Top ? p.y() : p.z()};
    }

    /** A shape's outline in a view (seen from above: its footprint): a polygon, or a circle when
        radius > 0. */
    struct Footprint
    {
        std::vector<Eigen::Vector2d> corners;             ///< the polygon; empty for a circle
        Eigen::Vector2d centre{Eigen::Vector2d::Zero()};  ///< the shape's centre in the view
        double radius{0.0};                               ///< the circle's radius, metres
    };

    /** An obstacle or a support surface, drawn in order (painter's order). */
    struct GroundItem
    {
        long long orderKey;   ///< top view: top height, side view: nearness (-y), in micrometres
        bool isSurface;       ///< at equal height the surface (an obstacle's top) is drawn above it
        bool faint;           ///< an obstacle at or under the lowest surface (a floor slab)
        Footprint footprint;  ///< its outline
        std::string name;     ///< shown as its title
    };

    /** A support surface seen edge-on (side view). */
    struct SurfaceLine
    {
        Eigen::Vector2d from;  ///< one end
        Eigen::Vector2d to;    ///< the other end
        std::string name;      ///< the surface's name
    };

    /** A goal marker with its label. */
    struct GoalMarker
    {
        Eigen::Vector2d at;  ///< where the goal is
        std::string label;   ///< what is shown beside it
        std::string colour;  ///< the object's colour
    };

    /** The course of a point (the tool, a carried object) along one labelled segment. */
    struct ToolSegment
    {
        PrimitiveKind kind;                   ///< the primitive that moved it
        std::vector<Eigen::Vector2d> points;  ///< its course
        int object{-1};                       ///< the carried object of a carried object's course
    };

    /** An arm at one waypoint: its link shapes' outlines (a mesh's: its convex hull's). */
    struct ArmPose
    {
        std::vector<Footprint> links;  ///< one outline per link shape
        std::string caption;           ///< the waypoint and what follows it
    };

    /** Everything one view draws, in world metres. */
    struct Picture
    {
        std::vector<GroundItem> ground;          ///< obstacles and surfaces, in drawing order
        std::vector<SurfaceLine> surfaceLines;   ///< side view: the surfaces edge-on
        std::vector<Footprint> objectStart;      ///< the objects where they start
        std::vector<Footprint> objectEnd;        ///< where the path leaves them; empty without a path
        std::vector<GoalMarker> goals;           ///< the objects' goals
        std::vector<ArmPose> armPoses;           ///< an arm (not a mobile robot), in the path's order
        std::vector<ToolSegment> carried;        ///< side view: carried objects' centres in transfers
        std::vector<ToolSegment> segments;       ///< the tool's course, segment by segment
        std::vector<Eigen::Vector2d> waypoints;  ///< the tool at the path's waypoints
        std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> pushArrows;  ///< pushed objects' moves
        std::optional<Footprint> robotStart;  ///< top view of a mobile robot: where it starts
        std::optional<Footprint> robotEnd;    ///< and where it ends
    };

    /** The top view (x-y) of the setup's scene and, when given, of its solution path; a mobile
        robot (all joints prismatic) at the start and the end, an arm as sidePicture() has it. */
    Picture topPicture(const ManipulationSetup &setup, const ManipulationPath *path);
    /** The side view (x-z, seen from -y) of the setup's scene with the arm at the start, at every
        mode switch and at the end of the path, when given. */
    Picture sidePicture(const ManipulationSetup &setup, const ManipulationPath *path);
    /** True for an obstacle whose top is at or under the scene's lowest support surface (a floor
        slab), which pictures draw faintly so that what stands on it shows. */
    bool isFloorSlab(const Scene &scene, const Obstacle &obstacle);
    /** The world box holding everything a picture draws. */
    Eigen::AlignedBox2d bounds(const Picture &picture);
    /** A world box with a margin around it, at least a metre across, so a lone object is not blown
        up to the whole picture. */
    Eigen::AlignedBox2d padded(const Eigen::AlignedBox2d &box);
}  // namespace ompl_mm::picture
