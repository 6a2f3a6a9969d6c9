/* A plan as a self-contained 3-D web page: three.js and the viewer inlined, the plan as JSON. Both
   libraries describe their plans in these terms (ompl_mm/io/SceneHtml.h, ompl_phys/io/PhysicsSceneHtml.h). */
#pragma once

#include <Eigen/Geometry>

#include <array>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace ompl_core
{
    /** Triangles that several solids may share (a robot's link mesh, drawn on the link and again in
        its goal pose; one mesh file used by two links): the page holds each once, its corners
        rounded to 0.1 mm. */
    struct ViewerMesh
    {
        std::vector<Eigen::Vector3d> vertices;      ///< corners, m
        std::vector<std::array<int, 3>> triangles;  ///< faces: indices of vertices
    };

    /** A solid of the viewer, posed in its body's frame. */
    struct ViewerSolid
    {
        /** Which solid, and so which fields count. */
        enum class Kind
        {
            Box,       ///< size: edge lengths
            Cylinder,  ///< radius, length along z
            Sphere,    ///< radius
            Mesh,      ///< mesh when set, else vertices and triangles
        };
        Kind kind{Kind::Box};                                   ///< which solid
        Eigen::Vector3d size{Eigen::Vector3d::Zero()};          ///< box edge lengths, m
        double radius{0.0};                                     ///< cylinder or sphere radius, m
        double length{0.0};                                     ///< cylinder length along z, m
        std::vector<Eigen::Vector3d> vertices;                  ///< mesh corners, m
        std::vector<std::array<int, 3>> triangles;              ///< mesh faces: indices of vertices
        Eigen::Isometry3d pose{Eigen::Isometry3d::Identity()};  ///< in the body's frame
        /** Mesh: shared triangles, written once however many solids use them; when set, vertices
            and triangles are not used. */
        std::shared_ptr<const ViewerMesh> mesh;
        std::string colour;  ///< fill colour (CSS, "#rrggbb") of this solid alone; empty: its body's
    };

    /** Solids that move together, drawn in one colour (CSS, "#rrggbb") but for solids with a colour
        of their own. */
    struct ViewerBody
    {
        std::string name;                 ///< for the legend and tooltips
        std::string colour{"#888888"};    ///< fill colour
        double opacity{1.0};              ///< below 1: translucent (goals)
        std::vector<ViewerSolid> solids;  ///< in the body's frame
    };

    /** A stretch of the timeline made by one primitive (or one control), for the colour of the tool
        path, the label on screen and the steps between mode switches. */
    struct ViewerSegment
    {
        std::size_t first{0};  ///< first frame
        std::size_t last{0};   ///< last frame (the next segment's first)
        std::string label;     ///< what happens ("push obj3")
        std::string colour;    ///< of the tool path along it
    };

    /** Everything a plan page shows. Fixed bodies and goals are drawn at their world poses (the
        body frame is the world's); moving bodies get a pose per frame. */
    struct ViewerPlan
    {
        std::string title;                                   ///< shown on the page and as its title
        std::vector<ViewerBody> fixed;                       ///< the static world, support surfaces included
        std::vector<ViewerBody> goals;                       ///< translucent goal poses
        std::vector<ViewerBody> moving;                      ///< robot links, objects, pushed bodies
        double frameStep{0.1};                               ///< animation seconds per frame
        std::vector<std::vector<Eigen::Isometry3d>> frames;  ///< frames[k][b]: moving body b at frame k
        std::vector<Eigen::Vector3d> toolPath;               ///< the tool point at every frame
        std::vector<ViewerSegment> segments;                 ///< in timeline order
        std::vector<std::size_t> tracks;  ///< moving bodies whose course is drawn as a line
        std::vector<std::pair<std::string, std::string>> legend;  ///< (label, colour) lines in the corner
    };

    /** The folder of three.js (three.min.js and examples/js/controls/OrbitControls.js): the
        environment variable OMPL_MM_THREE_JS_DIR when set, else Debian's libjs-three
        (/usr/share/javascript/three). */
    std::string threeJsFolder();

    /** @throws InputError naming the missing file and the package (libjs-three) unless three.js and
        its OrbitControls are in threeJsFolder(). For apps, before planning. */
    void requireThreeJs();

    /** Writes plan as one HTML page that opens offline in a browser: three.js and its
        OrbitControls inlined, an orbiting camera, play/pause, a timeline, speed, steps to the
        previous and next mode switch, and the current segment's label. Numbers are written to
        0.1 mm and 1e-5 of a quaternion; shared meshes (ViewerSolid::mesh) once each, their corners
        as whole multiples of 0.1 mm. Meshes are shaded smoothly within a surface and sharply
        where faces meet at more than 40 degrees. @pre every frame has a pose per moving body, toolPath a
        point per frame. @throws InputError as requireThreeJs(). */
    void writePlanViewerPage(std::ostream &out, const ViewerPlan &plan);
}  // namespace ompl_core
