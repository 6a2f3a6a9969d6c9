/* Quickhull: a tetrahedron of extreme points, then, while a face has points outside it, the
   farthest of them replaces the faces it sees by a fan over their horizon. */
#include "ompl_mm/scene/ConvexHull.h"

#include <ompl/util/Exception.h>

#include <Eigen/Geometry>

#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>

namespace ompl_mm
{
    namespace
    {
        /** Fills the hull's vertex adjacency (each edge of a closed triangulation lies on two faces;
            each face lists it once in each direction) and its axis extremes. */
        void linkVertices(ConvexHull &hull)
        {
            std::vector<std::vector<int>> adjacent(hull.vertices.size());
            for (const std::array<int, 3> &t : hull.triangles)
                for (int i = 0; i < 3; ++i)
                    adjacent[t[i]].push_back(
                        t[(i + 1) % 3]);  // the other direction comes with the other face
            hull.neighbourStart.assign(1, 0);
            for (const std::vector<int> &list : adjacent)
            {
                hull.neighbours.insert(hull.neighbours.end(), list.begin(), list.end());
                hull.neighbourStart.push_back(static_cast<int>(hull.neighbours.size()));
            }
            for (int axis = 0; axis < 3; ++axis)
                for (int v = 0; v < static_cast<int>(hull.vertices.size()); ++v)
                {
                    if (hull.vertices[v][axis] > hull.vertices[hull.extremes[2 * axis]][axis])
                        hull.extremes[2 * axis] = v;
                    if (hull.vertices[v][axis] < hull.vertices[hull.extremes[2 * axis + 1]][axis])
                        hull.extremes[2 * axis + 1] = v;
                }
        }

        const char *const WHO = "convex hull";

        /** A triangle of the hull being built, with the points outside it. */
        struct Face
        {
            std::array<int, 3> v;    ///< corners, counter-clockwise seen from outside
            Eigen::Vector3d normal;  ///< unit, outward
            double offset;           ///< the plane is normal . x = offset
            std::vector<int> outside;
            bool live{true};

            double distance(const Eigen::Vector3d &p) const { return normal.dot(p) - offset; }
        };

        class QuickHull
        {
        public:
            QuickHull(const std::vector<Eigen::Vector3d> &points, double tolerance)
                : points_(points), tolerance_(tolerance)
            {
            }

            ConvexHull build(const std::array<int, 4> &simplex)
            {
                // the tetrahedron, its faces outward (simplex[3] lies below the first)
                const auto [a, b, c, d] = simplex;
                for (const std::array<int, 3> &f :
                     {std::array<int, 3>{a, b, c}, {b, a, d}, {c, b, d}, {a, c, d}})
                    addFace(f[0], f[1], f[2]);
                std::vector<int> rest;
                for (int p = 0; p < static_cast<int>(points_.size()); ++p)
                    if (p != a && p != b && p != c && p != d)
                        rest.push_back(p);
                assign(rest, 0);
                // faces come and go at the end; each round retires the face it starts from
                for (std::size_t f = 0; f < faces_.size(); ++f)
                    if (faces_[f].live && !faces_[f].outside.empty())
                        addFarthestPoint(f);
                return collect();
            }

        private:
            static std::uint64_t key(int from, int to)
            {
                return (static_cast<std::uint64_t>(from) << 32) | static_cast<std::uint32_t>(to);
            }

            /** The face across the edge from -> to of a live face. */
            std::size_t across(int from, int to) const
            {
                const auto it = edges_.find(key(to, from));
                if (it == edges_.end())
                    throw ompl::Exception(WHO, "rounding broke the hull: an edge has one face");
                return it->second;
            }

            void addFace(int a, int b, int c)
            {
                const Eigen::Vector3d &pa = points_[a];
                Face face{{a, b, c}, (points_[b] - pa).cross(points_[c] - pa).normalized(), 0.0, {}, true};
                face.offset = face.normal.dot((pa + points_[b] + points_[c]) / 3.0);
                for (int e = 0; e < 3; ++e)
                    if (!edges_.emplace(key(face.v[e], face.v[(e + 1) % 3]), faces_.size()).second)
                        throw ompl::Exception(WHO, "rounding broke the hull: an edge has three faces");
                faces_.push_back(std::move(face));
            }

            /** Gives each point to the first face from `first` on that it lies outside of. */
            void assign(const std::vector<int> &points, std::size_t first)
            {
                for (int p : points)
                    for (std::size_t f = first; f < faces_.size(); ++f)
                        if (faces_[f].distance(points_[p]) > tolerance_)
                        {
                            faces_[f].outside.push_back(p);
                            break;
                        }
            }

            /** Adds the point of face f's outside set farthest from it to the hull. */
            void addFarthestPoint(std::size_t f)
            {
                int eye = faces_[f].outside.front();
                for (int p : faces_[f].outside)
                    if (faces_[f].distance(points_[p]) > faces_[f].distance(points_[eye]))
                        eye = p;
                const Eigen::Vector3d &e = points_[eye];
                // the faces the eye sees, a connected patch around f, and the patch's rim
                std::vector<std::size_t> visible{f};
                std::unordered_map<std::size_t, bool> seen{{f, true}};
                std::vector<std::array<int, 2>> horizon;
                for (std::size_t k = 0; k < visible.size(); ++k)
                {
                    const std::array<int, 3> v = faces_[visible[k]].v;
                    for (int i = 0; i < 3; ++i)
                    {
                        const std::size_t next = across(v[i], v[(i + 1) % 3]);
                        auto [it, fresh] = seen.emplace(next, false);
                        if (fresh)
                            it->second = faces_[next].distance(e) > tolerance_;
                        if (!it->second)
                            horizon.push_back({v[i], v[(i + 1) % 3]});
                        else if (fresh)
                            visible.push_back(next);
                    }
                }
                // retire the patch, keeping its other outside points for the new faces
                std::vector<int> orphans;
                for (std::size_t g : visible)
                {
                    Face &face = faces_[g];
                    face.live = false;
                    for (int p : face.outside)
                        if (p != eye)
                            orphans.push_back(p);
                    face.outside.clear();
                    for (int i = 0; i < 3; ++i)
                        edges_.erase(key(face.v[i], face.v[(i + 1) % 3]));
                }
                // a fan from the eye over the rim (each rim edge keeps its direction)
                const std::size_t first = faces_.size();
                for (const std::array<int, 2> &edge : horizon)
                    addFace(edge[0], edge[1], eye);
                assign(orphans, first);
            }

            /** The live faces, on the points they use, renumbered; checks Euler's formula. */
            ConvexHull collect() const
            {
                ConvexHull hull;
                std::vector<int> index(points_.size(), -1);
                for (const Face &face : faces_)
                {
                    if (!face.live)
                        continue;
                    std::array<int, 3> t;
                    for (int i = 0; i < 3; ++i)
                    {
                        if (index[face.v[i]] < 0)
                        {
                            index[face.v[i]] = static_cast<int>(hull.vertices.size());
                            hull.vertices.push_back(points_[face.v[i]]);
                        }
                        t[i] = index[face.v[i]];
                    }
                    hull.triangles.push_back(t);
                }
                // a closed triangulated sphere: each edge in both directions, and F = 2 V - 4
                for (const auto &entry : edges_)
                    across(static_cast<int>(entry.first >> 32), static_cast<int>(entry.first & 0xffffffffu));
                if (hull.triangles.size() != 2 * hull.vertices.size() - 4)
                    throw ompl::Exception(WHO, "rounding broke the hull: it is not a sphere");
                linkVertices(hull);
                return hull;
            }

            const std::vector<Eigen::Vector3d> &points_;
            const double tolerance_;
            std::vector<Face> faces_;
            std::unordered_map<std::uint64_t, std::size_t> edges_;  ///< directed edge -> its live face
        };

        /** Index of the point farthest from what the function measures. */
        template <typename Measure>
        int farthest(const std::vector<Eigen::Vector3d> &points, const Measure &measure)
        {
            int best = 0;
            for (int p = 1; p < static_cast<int>(points.size()); ++p)
                if (measure(points[p]) > measure(points[best]))
                    best = p;
            return best;
        }
    }  // namespace

    ConvexHull computeConvexHull(const std::vector<Eigen::Vector3d> &points)
    {
        const std::string count = std::to_string(points.size());
        if (points.size() < 4)
            throw ompl::Exception(WHO, "needs at least 4 points, got " + count);
        Eigen::Vector3d largest = Eigen::Vector3d::Zero();
        for (const Eigen::Vector3d &p : points)
        {
            if (!p.allFinite())
                throw ompl::Exception(WHO, "a point has a coordinate that is not finite");
            largest = largest.cwiseMax(p.cwiseAbs());
        }
        const double tolerance = ConvexHull::RELATIVE_TOLERANCE * largest.sum();
        std::ostringstream within;
        within << " (within " << tolerance << "): they span no volume";
        // a tetrahedron of far-apart points: the farthest from point 0, from it, from their
        // line, from their plane
        const int i0 = farthest(points, [&](const Eigen::Vector3d &p) { return (p - points[0]).norm(); });
        const Eigen::Vector3d &a = points[i0];
        const int i1 = farthest(points, [&](const Eigen::Vector3d &p) { return (p - a).norm(); });
        if ((points[i1] - a).norm() <= tolerance)
            throw ompl::Exception(WHO, "the " + count + " points coincide" + within.str());
        const Eigen::Vector3d along = (points[i1] - a).normalized();
        const int i2 =
            farthest(points, [&](const Eigen::Vector3d &p) { return (p - a).cross(along).norm(); });
        if ((points[i2] - a).cross(along).norm() <= tolerance)
            throw ompl::Exception(WHO, "the " + count + " points are collinear" + within.str());
        const Eigen::Vector3d normal = (points[i1] - a).cross(points[i2] - a).normalized();
        const int i3 =
            farthest(points, [&](const Eigen::Vector3d &p) { return std::abs(normal.dot(p - a)); });
        const double height = normal.dot(points[i3] - a);
        if (std::abs(height) <= tolerance)
            throw ompl::Exception(WHO, "the " + count + " points are coplanar" + within.str());
        // the first face outward: the fourth point below it
        const std::array<int, 4> simplex =
            height < 0.0 ? std::array<int, 4>{i0, i1, i2, i3} : std::array<int, 4>{i0, i2, i1, i3};
        return QuickHull(points, tolerance).build(simplex);
    }
}  // namespace ompl_mm
