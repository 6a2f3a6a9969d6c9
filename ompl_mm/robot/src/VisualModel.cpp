/* VisualModel: a tinyxml2 pass over the URDF's links (urdfdom keeps neither lines nor a mesh's own
   materials), meshes read through assimp one material at a time. */
#include "ompl_mm/robot/VisualModel.h"

#include "ompl_core/io/InputError.h"
#include "ompl_core/io/InputFile.h"
#include "ompl_core/io/XmlReading.h"
#include "ompl_mm/robot/MeshFile.h"

#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <ompl/util/Console.h>
#include <tinyxml2.h>
#include <assimp/Importer.hpp>

#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace ompl_mm
{
    namespace
    {
        using ompl_core::XmlElement;

        /** The triangles of one material of a mesh file, with the material's colour. */
        struct MaterialPart
        {
            std::shared_ptr<const TriangleMesh> mesh;
            std::optional<Rgba> colour;
        };

        /** Mesh files read so far, by path and scale. */
        using VisualMeshCache = std::map<std::string, std::vector<MaterialPart>>;

        /** The diffuse colour of a material the file names (none for assimp's default material,
            which stands in where a file has none). */
        std::optional<Rgba> materialColour(const aiMaterial &material)
        {
            aiString name;
            if (material.Get(AI_MATKEY_NAME, name) != AI_SUCCESS || std::string(name.C_Str()).empty() ||
                std::string(name.C_Str()) == AI_DEFAULT_MATERIAL_NAME)
                return std::nullopt;
            aiColor4D diffuse;
            if (aiGetMaterialColor(&material, AI_MATKEY_COLOR_DIFFUSE, &diffuse) != AI_SUCCESS)
                return std::nullopt;
            return Rgba(diffuse.r, diffuse.g, diffuse.b, 1.0).cwiseMax(0.0).cwiseMin(1.0);
        }

        /** A mesh file's triangles, one part per material, scaled per axis (from cache when read
            before at this scale). As readMeshFile(), a COLLADA file's up axis is ignored.
            @throws std::runtime_error with the reader's message, or when the file holds no triangle. */
        const std::vector<MaterialPart> &readMaterialParts(const std::string &path,
                                                           const Eigen::Vector3d &scale,
                                                           VisualMeshCache &cache)
        {
            const std::string key = meshCacheKey(path, scale);
            if (const auto cached = cache.find(key); cached != cache.end())
                return cached->second;
            Assimp::Importer importer;
            // without normals and texture coordinates, corners at one place become one vertex
            importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, aiComponent_NORMALS | aiComponent_TEXCOORDS |
                                                                    aiComponent_COLORS |
                                                                    aiComponent_TANGENTS_AND_BITANGENTS);
            const aiScene &scene = importMeshFile(importer, path,
                                                  aiProcess_RemoveComponent | aiProcess_Triangulate |
                                                      aiProcess_JoinIdenticalVertices |
                                                      aiProcess_PreTransformVertices | aiProcess_SortByPType);
            // the meshes of each material, gathered into one part
            std::map<unsigned int, std::shared_ptr<TriangleMesh>> byMaterial;
            for (unsigned int m = 0; m < scene.mNumMeshes; ++m)
            {
                const aiMesh &piece = *scene.mMeshes[m];
                std::shared_ptr<TriangleMesh> &part = byMaterial[piece.mMaterialIndex];
                if (!part)
                {
                    part = std::make_shared<TriangleMesh>();
                    part->file = path;
                }
                const int offset = static_cast<int>(part->vertices.size());
                for (unsigned int v = 0; v < piece.mNumVertices; ++v)
                    part->vertices.emplace_back(scale.x() * piece.mVertices[v].x,
                                                scale.y() * piece.mVertices[v].y,
                                                scale.z() * piece.mVertices[v].z);
                for (unsigned int f = 0; f < piece.mNumFaces; ++f)
                    if (piece.mFaces[f].mNumIndices == 3)
                        part->triangles.push_back({offset + static_cast<int>(piece.mFaces[f].mIndices[0]),
                                                   offset + static_cast<int>(piece.mFaces[f].mIndices[1]),
                                                   offset + static_cast<int>(piece.mFaces[f].mIndices[2])});
            }
            std::vector<MaterialPart> parts;
            for (const auto &[material, part] : byMaterial)
            {
                if (part->triangles.empty())
                    continue;
                part->measure();
                parts.push_back({part, material < scene.mNumMaterials
                                           ? materialColour(*scene.mMaterials[material])
                                           : std::nullopt});
            }
            if (parts.empty())
                throw std::runtime_error("the file holds no triangle");
            return cache.emplace(key, std::move(parts)).first->second;
        }

        /** The colour of a `<material>` element's `<color rgba>`, if it has one.
            @throws ompl_core::InputError for a malformed colour or one outside 0 to 1. */
        std::optional<Rgba> ownColour(const XmlElement &material)
        {
            for (const XmlElement &child : material.children())
            {
                if (child.name() != "color")
                    continue;
                const std::vector<double> rgba = child.numbers("rgba", 4);
                for (const double value : rgba)
                    if (value < 0.0 || value > 1.0)
                        child.fail("rgba",
                                   "colour components must lie between 0 and 1, got " + child.text("rgba"));
                return Rgba(rgba[0], rgba[1], rgba[2], rgba[3]);
            }
            return std::nullopt;
        }

        /** The colours of the named materials: those under `<robot>`, then those defined inside a
            visual (which other visuals may name too), the first definition of a name winning. */
        std::map<std::string, Rgba> namedColours(const tinyxml2::XMLElement *robot, const std::string &file)
        {
            std::map<std::string, Rgba> colours;
            const auto note = [&](const tinyxml2::XMLElement *material)
            {
                const char *name = material->Attribute("name");
                if (name == nullptr)
                    return;
                if (const std::optional<Rgba> colour = ownColour(XmlElement(material, file)))
                    colours.emplace(name, *colour);
            };
            for (auto *m = robot->FirstChildElement("material"); m != nullptr;
                 m = m->NextSiblingElement("material"))
                note(m);
            for (auto *link = robot->FirstChildElement("link"); link != nullptr;
                 link = link->NextSiblingElement("link"))
                for (auto *visual = link->FirstChildElement("visual"); visual != nullptr;
                     visual = visual->NextSiblingElement("visual"))
                    if (const tinyxml2::XMLElement *material = visual->FirstChildElement("material"))
                        note(material);
            return colours;
        }

        /** Reads the visuals of one link after another. */
        class LinkVisualReader
        {
        public:
            LinkVisualReader(std::string file, const tinyxml2::XMLElement *robot)
                : file_(std::move(file)), colours_(namedColours(robot, file_))
            {
            }

            /** The link's look from its element (null: none in the file). */
            LinkVisual read(const tinyxml2::XMLElement *element, const Link &link)
            {
                LinkVisual visual;
                if (element == nullptr || element->FirstChildElement("visual") == nullptr)
                    return collisionLook(link);
                for (auto *v = element->FirstChildElement("visual"); v != nullptr;
                     v = v->NextSiblingElement("visual"))
                    if (!addVisual(XmlElement(v, file_), link.name, visual))
                    {
                        LinkVisual fallback = collisionLook(link);
                        fallback.warning = visual.warning;
                        OMPL_WARN("%s", fallback.warning.c_str());
                        return fallback;
                    }
                return visual;
            }

            /** The link's collision shapes, without colours. */
            static LinkVisual collisionLook(const Link &link)
            {
                LinkVisual visual;
                visual.fromCollision = true;
                for (const LinkShape &shape : link.shapes)
                    visual.shapes.push_back({shape.shape, shape.origin, std::nullopt});
                return visual;
            }

        private:
            /** The colour a `<visual>`'s `<material>` gives (its own, or the named one's). */
            std::optional<Rgba> urdfColour(const XmlElement &visual) const
            {
                for (const XmlElement &child : visual.children())
                {
                    if (child.name() != "material")
                        continue;
                    if (std::optional<Rgba> own = ownColour(child))
                        return own;
                    std::string name;
                    for (const auto &[attribute, value] : child.attributes())
                        if (attribute == "name")
                            name = value;
                    const auto named = colours_.find(name);
                    return named == colours_.end() ? std::nullopt : std::optional<Rgba>(named->second);
                }
                return std::nullopt;
            }

            /** Adds a `<visual>`'s shapes; false (with visual.warning set) when its mesh file is
                missing or unreadable. */
            bool addVisual(const XmlElement &element, const std::string &link, LinkVisual &visual)
            {
                Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();
                std::optional<XmlElement> geometry;
                for (const XmlElement &child : element.children())
                    if (child.name() == "origin")
                        origin = ompl_core::readOrigin(child);
                    else if (child.name() == "geometry")
                        geometry = child;
                if (!geometry)
                    element.fail("link '" + link + "': <visual> has no <geometry>");
                const std::vector<XmlElement> solids = geometry->children();
                if (solids.size() != 1)
                    geometry->fail("link '" + link +
                                   "': <geometry> needs one of <box>, <cylinder>, <sphere>, <mesh>");
                const XmlElement &solid = solids.front();
                const std::optional<Rgba> colour = urdfColour(element);
                if (solid.name() != "mesh")
                {
                    visual.shapes.push_back({primitive(solid, link), origin, colour});
                    return true;
                }
                return addMesh(solid, link, origin, colour, visual);
            }

            /** A box, cylinder or sphere. @throws ompl_core::InputError for another or a bad size. */
            static Shape primitive(const XmlElement &solid, const std::string &link)
            {
                Shape shape;
                if (solid.name() == "box")
                {
                    shape.kind = Shape::Kind::Box;
                    const std::vector<double> size = solid.numbers("size", 3);
                    shape.boxSize = Eigen::Vector3d(size[0], size[1], size[2]);
                    if (!(shape.boxSize.minCoeff() > 0.0))
                        solid.fail("size", "link '" + link + "': box size must be positive");
                }
                else if (solid.name() == "cylinder")
                {
                    shape.kind = Shape::Kind::Cylinder;
                    shape.radius = solid.positive("radius");
                    shape.length = solid.positive("length");
                }
                else if (solid.name() == "sphere")
                {
                    shape.kind = Shape::Kind::Sphere;
                    shape.radius = solid.positive("radius");
                }
                else
                    solid.fail("link '" + link + "': unknown visual geometry " + solid.tag());
                return shape;
            }

            bool addMesh(const XmlElement &mesh, const std::string &link, const Eigen::Isometry3d &origin,
                         const std::optional<Rgba> &colour, LinkVisual &visual)
            {
                const std::string filename = mesh.text("filename");
                Eigen::Vector3d scale = Eigen::Vector3d::Ones();
                if (mesh.has("scale"))
                {
                    const std::vector<double> s = mesh.numbers("scale", 3);
                    scale = Eigen::Vector3d(s[0], s[1], s[2]);
                    if (!(scale.minCoeff() > 0.0))
                        mesh.fail("scale", "link '" + link + "': mesh scale must be positive");
                }
                const std::string where = mesh.where().str() + ": link '" + link + "': visual mesh '";
                std::string tried;
                const std::string path = resolveMeshFile(filename, file_, tried);
                if (path.empty())
                {
                    visual.warning = where + filename + "' not found (looked for " + tried +
                                     "); showing its collision shapes";
                    return false;
                }
                try
                {
                    for (const MaterialPart &part : readMaterialParts(path, scale, meshes_))
                    {
                        Shape shape;
                        shape.kind = Shape::Kind::Mesh;
                        shape.mesh = part.mesh;
                        visual.shapes.push_back({shape, origin, part.colour ? part.colour : colour});
                    }
                }
                catch (const std::runtime_error &e)
                {
                    visual.warning =
                        where + path + "' cannot be read (" + e.what() + "); showing its collision shapes";
                    return false;
                }
                return true;
            }

            std::string file_;
            std::map<std::string, Rgba> colours_;
            VisualMeshCache meshes_;
        };
    }  // namespace

    VisualModel VisualModel::fromUrdfFile(const std::string &urdfFile, const RobotModel &robot)
    {
        const std::string text = ompl_core::readInputFile(urdfFile, "URDF file");
        tinyxml2::XMLDocument document;
        ompl_core::parseRootElement(document, text, urdfFile, "robot");
        const tinyxml2::XMLElement *robotElement = document.RootElement();
        std::map<std::string, const tinyxml2::XMLElement *> linkElements;
        for (auto *e = robotElement->FirstChildElement("link"); e != nullptr;
             e = e->NextSiblingElement("link"))
            if (const char *name = e->Attribute("name"))
                linkElements.emplace(name, e);
        LinkVisualReader reader(urdfFile, robotElement);
        VisualModel model;
        for (const Link &link : robot.links())
        {
            const auto element = linkElements.find(link.name);
            model.links_.push_back(
                reader.read(element == linkElements.end() ? nullptr : element->second, link));
        }
        return model;
    }

    VisualModel VisualModel::fromCollision(const RobotModel &robot)
    {
        VisualModel model;
        for (const Link &link : robot.links())
            model.links_.push_back(LinkVisualReader::collisionLook(link));
        return model;
    }

    std::vector<std::string> VisualModel::warnings() const
    {
        std::vector<std::string> all;
        for (const LinkVisual &link : links_)
            if (!link.warning.empty())
                all.push_back(link.warning);
        return all;
    }
}  // namespace ompl_mm
