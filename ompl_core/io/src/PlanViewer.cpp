#include "ompl_core/io/PlanViewer.h"

#include "ompl_core/io/InputError.h"
#include "ompl_core/io/InputFile.h"
#include "ompl_core/io/TextFormat.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

namespace ompl_core
{
    namespace detail
    {
        extern const char *const PLAN_VIEWER_HTML;
        extern const char *const PLAN_VIEWER_JS;
    }  // namespace detail

    namespace
    {
        const char *const THREE_FILE = "three.min.js";
        const char *const ORBIT_CONTROLS_FILE = "examples/js/controls/OrbitControls.js";

        /** A number with at most decimals digits after the point, trailing zeros dropped: the
            pages stay small, and 0.1 mm is finer than any screen shows. */
        std::string shortNumber(double value, int decimals)
        {
            char text[64];
            std::snprintf(text, sizeof(text), "%.*f", decimals, value);
            std::string s(text);
            if (s.find('.') != std::string::npos)
            {
                s.erase(s.find_last_not_of('0') + 1);
                if (s.back() == '.')
                    s.pop_back();
            }
            return s == "-0" ? "0" : s;
        }

        std::string position(const Eigen::Vector3d &p)
        {
            return shortNumber(p.x(), 4) + "," + shortNumber(p.y(), 4) + "," + shortNumber(p.z(), 4);
        }

        /** [x, y, z, qx, qy, qz, qw] */
        std::string pose(const Eigen::Isometry3d &pose)
        {
            const Eigen::Quaterniond q(pose.rotation());
            return "[" + position(pose.translation()) + "," + shortNumber(q.x(), 5) + "," +
                   shortNumber(q.y(), 5) + "," + shortNumber(q.z(), 5) + "," + shortNumber(q.w(), 5) + "]";
        }

        /** Shared meshes are written in whole multiples of this, metres: integers are shorter
            than decimals, and 0.1 mm is finer than any screen shows. */
        constexpr double MESH_UNIT = 1e-4;

        /** The shared meshes of a plan, each numbered once in order of first use. */
        class MeshTable
        {
        public:
            explicit MeshTable(const ViewerPlan &plan)
            {
                for (const std::vector<ViewerBody> *bodies : {&plan.fixed, &plan.goals, &plan.moving})
                    for (const ViewerBody &body : *bodies)
                        for (const ViewerSolid &solid : body.solids)
                            if (solid.kind == ViewerSolid::Kind::Mesh && solid.mesh &&
                                index_.emplace(solid.mesh.get(), meshes_.size()).second)
                                meshes_.push_back(solid.mesh.get());
            }

            /** The number of a solid's shared mesh. @pre the plan's solid has one. */
            std::size_t indexOf(const ViewerMesh *mesh) const { return index_.at(mesh); }

            /** "[{"vertices":[...],"triangles":[...]},...]", corners in MESH_UNITs. */
            void write(std::ostream &out) const
            {
                out << "[";
                for (std::size_t m = 0; m < meshes_.size(); ++m)
                {
                    out << (m ? ",\n" : "") << "{\"vertices\":[";
                    const std::vector<Eigen::Vector3d> &vertices = meshes_[m]->vertices;
                    for (std::size_t i = 0; i < vertices.size(); ++i)
                        for (int k = 0; k < 3; ++k)
                            out << (i > 0 || k > 0 ? "," : "") << std::llround(vertices[i][k] / MESH_UNIT);
                    out << "],\"triangles\":[";
                    const std::vector<std::array<int, 3>> &triangles = meshes_[m]->triangles;
                    for (std::size_t i = 0; i < triangles.size(); ++i)
                        out << (i ? "," : "") << triangles[i][0] << "," << triangles[i][1] << ","
                            << triangles[i][2];
                    out << "]}";
                }
                out << "]";
            }

        private:
            std::vector<const ViewerMesh *> meshes_;
            std::map<const ViewerMesh *, std::size_t> index_;
        };

        void writeSolid(std::ostream &out, const ViewerSolid &solid, const MeshTable &meshes)
        {
            out << "{\"pose\":" << pose(solid.pose) << ",";
            switch (solid.kind)
            {
                case ViewerSolid::Kind::Box:
                    out << "\"kind\":\"box\",\"size\":[" << position(solid.size) << "]";
                    break;
                case ViewerSolid::Kind::Cylinder:
                    out << "\"kind\":\"cylinder\",\"radius\":" << shortNumber(solid.radius, 4)
                        << ",\"length\":" << shortNumber(solid.length, 4);
                    break;
                case ViewerSolid::Kind::Sphere:
                    out << "\"kind\":\"sphere\",\"radius\":" << shortNumber(solid.radius, 4);
                    break;
                case ViewerSolid::Kind::Mesh:
                {
                    if (solid.mesh)
                    {
                        out << "\"kind\":\"mesh\",\"mesh\":" << meshes.indexOf(solid.mesh.get());
                        break;
                    }
                    out << "\"kind\":\"mesh\",\"vertices\":[";
                    for (std::size_t i = 0; i < solid.vertices.size(); ++i)
                        out << (i ? "," : "") << position(solid.vertices[i]);
                    out << "],\"triangles\":[";
                    for (std::size_t i = 0; i < solid.triangles.size(); ++i)
                        out << (i ? "," : "") << solid.triangles[i][0] << "," << solid.triangles[i][1] << ","
                            << solid.triangles[i][2];
                    out << "]";
                    break;
                }
            }
            if (!solid.colour.empty())
                out << ",\"colour\":" << jsonQuoted(solid.colour);
            out << "}";
        }

        void writeBodies(std::ostream &out, const std::vector<ViewerBody> &bodies, const MeshTable &meshes)
        {
            out << "[";
            for (std::size_t b = 0; b < bodies.size(); ++b)
            {
                const ViewerBody &body = bodies[b];
                out << (b ? "," : "") << "{\"name\":" << jsonQuoted(body.name)
                    << ",\"colour\":" << jsonQuoted(body.colour)
                    << ",\"opacity\":" << shortNumber(body.opacity, 3) << ",\"solids\":[";
                for (std::size_t s = 0; s < body.solids.size(); ++s)
                {
                    out << (s ? "," : "");
                    writeSolid(out, body.solids[s], meshes);
                }
                out << "]}";
            }
            out << "]";
        }

        std::string planJson(const ViewerPlan &plan)
        {
            std::ostringstream out;
            const MeshTable meshes(plan);
            out << "{\"title\":" << jsonQuoted(plan.title)
                << ",\"frameStep\":" << shortNumber(plan.frameStep, 6)
                << ",\"meshUnit\":" << shortNumber(MESH_UNIT, 6) << ",\"meshes\":";
            meshes.write(out);
            out << ",\n\"fixed\":";
            writeBodies(out, plan.fixed, meshes);
            out << ",\"goals\":";
            writeBodies(out, plan.goals, meshes);
            out << ",\"moving\":";
            writeBodies(out, plan.moving, meshes);
            out << ",\n\"frames\":[";
            for (std::size_t k = 0; k < plan.frames.size(); ++k)
            {
                out << (k ? ",\n" : "") << "[";
                for (std::size_t b = 0; b < plan.frames[k].size(); ++b)
                    out << (b ? "," : "") << pose(plan.frames[k][b]);
                out << "]";
            }
            out << "],\n\"toolPath\":[";
            for (std::size_t k = 0; k < plan.toolPath.size(); ++k)
                out << (k ? "," : "") << "[" << position(plan.toolPath[k]) << "]";
            out << "],\n\"segments\":[";
            for (std::size_t s = 0; s < plan.segments.size(); ++s)
            {
                const ViewerSegment &segment = plan.segments[s];
                out << (s ? "," : "") << "{\"first\":" << segment.first << ",\"last\":" << segment.last
                    << ",\"label\":" << jsonQuoted(segment.label)
                    << ",\"colour\":" << jsonQuoted(segment.colour) << "}";
            }
            out << "],\"tracks\":[";
            for (std::size_t t = 0; t < plan.tracks.size(); ++t)
                out << (t ? "," : "") << "{\"body\":" << plan.tracks[t]
                    << ",\"colour\":" << jsonQuoted(plan.moving.at(plan.tracks[t]).colour) << "}";
            out << "]}";
            // inside <script>, "</" could end the element early
            std::string json = out.str();
            for (std::size_t at = json.find("</"); at != std::string::npos; at = json.find("</", at))
                json.replace(at, 2, "<\\/");
            return json;
        }

        std::string legendHtml(const ViewerPlan &plan)
        {
            std::string html;
            for (const auto &[label, colour] : plan.legend)
                html += "<div><span style=\"background:" + xmlEscaped(colour) + "\"></span>" +
                        xmlEscaped(label) + "</div>";
            return html;
        }

        std::string scriptFile(const std::string &relative)
        {
            std::string text =
                readInputFile((std::filesystem::path(threeJsFolder()) / relative).string(), "three.js file");
            // inlined into <script>: a "</script" inside would end it early
            for (std::size_t at = text.find("</script"); at != std::string::npos;
                 at = text.find("</script", at))
                text.replace(at, 2, "<\\/");
            return text;
        }
    }  // namespace

    std::string threeJsFolder()
    {
        const char *folder = std::getenv("OMPL_MM_THREE_JS_DIR");
        return folder && *folder ? folder : OMPL_CORE_THREE_JS_DIR;
    }

    void requireThreeJs()
    {
        for (const char *file : {THREE_FILE, ORBIT_CONTROLS_FILE})
        {
            const std::filesystem::path path = std::filesystem::path(threeJsFolder()) / file;
            std::error_code error;
            if (!std::filesystem::is_regular_file(path, error))
                throw InputError(path.string() +
                                 " not found: plan pages need three.js (Debian's libjs-three; "
                                 "OMPL_MM_THREE_JS_DIR names another folder)");
        }
    }

    void writePlanViewerPage(std::ostream &out, const ViewerPlan &plan)
    {
        requireThreeJs();
        const std::vector<std::pair<std::string, std::string>> values = {
            {"@TITLE@", xmlEscaped(plan.title)},
            {"@LEGEND@", legendHtml(plan)},
            {"@PLAN@", planJson(plan)},
            {"@THREE@", scriptFile(THREE_FILE)},
            {"@ORBIT_CONTROLS@", scriptFile(ORBIT_CONTROLS_FILE)},
            {"@VIEWER@", detail::PLAN_VIEWER_JS}};
        // one pass over the template: what is put in (a title, three.js) is never searched again
        const std::string page = detail::PLAN_VIEWER_HTML;
        for (std::size_t at = 0; at < page.size();)
        {
            const auto placeholder = std::find_if(
                values.begin(), values.end(),
                [&](const auto &value) { return page.compare(at, value.first.size(), value.first) == 0; });
            if (placeholder != values.end())
            {
                out << placeholder->second;
                at += placeholder->first.size();
                continue;
            }
            const std::size_t next = std::min(page.find('@', at + 1), page.size());
            out.write(page.data() + at, static_cast<std::streamsize>(next - at));
            at = next;
        }
    }
}  // namespace ompl_core
