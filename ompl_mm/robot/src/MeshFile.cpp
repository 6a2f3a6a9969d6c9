#include "ompl_mm/robot/MeshFile.h"

#include "ompl_mm/robot/ColladaCheck.h"

#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace ompl_mm
{
    namespace fs = std::filesystem;

    namespace
    {
        const std::string PACKAGE_SCHEME = "package://";
        const std::string FILE_SCHEME = "file://";

        bool isFile(const fs::path &path)
        {
            std::error_code error;
            return fs::is_regular_file(path, error);
        }

        bool isColladaFile(const std::string &path)
        {
            std::string extension = fs::path(path).extension().string();
            std::transform(extension.begin(), extension.end(), extension.begin(),
                           [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
            return extension == ".dae";
        }

        /** Tries path, noting it in tried. */
        bool tryPath(const fs::path &path, std::string &tried)
        {
            tried += (tried.empty() ? "" : ", ") + path.string();
            return isFile(path);
        }
    }  // namespace

    std::string resolveMeshFile(const std::string &filename, const std::string &urdfFile, std::string &tried)
    {
        tried.clear();
        const fs::path urdfFolder = fs::absolute(fs::path(urdfFile)).parent_path();
        if (filename.compare(0, PACKAGE_SCHEME.size(), PACKAGE_SCHEME) != 0)
        {
            std::string name = filename;
            if (name.compare(0, FILE_SCHEME.size(), FILE_SCHEME) == 0)
                name = name.substr(FILE_SCHEME.size());
            if (fs::path(name).is_absolute())
                return tryPath(fs::path(name).lexically_normal(), tried)
                           ? fs::path(name).lexically_normal().string()
                           : "";
            // the URDF's folder, then its ancestors: PyBullet-style descriptions write their mesh
            // paths relative to a search path above the URDF (the repository's root)
            for (fs::path ancestor = urdfFolder; !ancestor.empty(); ancestor = ancestor.parent_path())
            {
                const fs::path path = (ancestor / name).lexically_normal();
                if (tryPath(path, tried))
                    return path.string();
                if (ancestor == ancestor.root_path())
                    break;
            }
            return "";
        }
        const std::string rest = filename.substr(PACKAGE_SCHEME.size());
        const std::string package = rest.substr(0, rest.find('/'));
        const std::string inside = rest.find('/') == std::string::npos ? "" : rest.substr(rest.find('/') + 1);
        if (const char *path = std::getenv("OMPL_MM_PACKAGE_PATH"))
        {
            std::stringstream folders(path);
            std::string folder;
            while (std::getline(folders, folder, ':'))
                if (!folder.empty() && tryPath(fs::path(folder) / package / inside, tried))
                    return (fs::path(folder) / package / inside).string();
        }
        for (fs::path ancestor = urdfFolder; !ancestor.empty(); ancestor = ancestor.parent_path())
        {
            if (tryPath(ancestor / package / inside, tried))
                return (ancestor / package / inside).string();
            if (ancestor == ancestor.root_path())
                break;
        }
        return "";
    }

    const aiScene &importMeshFile(Assimp::Importer &importer, const std::string &path, unsigned int steps)
    {
        if (isColladaFile(path))
            checkColladaFile(path);
        // COLLADA files declare an up axis (most Z_UP); assimp would turn them to Y_UP, while ROS
        // (RViz, geometric_shapes) takes their coordinates as they are, z up
        importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
        const aiScene *scene = importer.ReadFile(path, steps);
        if (scene == nullptr)
            throw std::runtime_error(importer.GetErrorString());
        return *scene;
    }

    std::string meshCacheKey(const std::string &path, const Eigen::Vector3d &scale)
    {
        std::ostringstream key;
        key.precision(17);
        key << path << '|' << scale.x() << ' ' << scale.y() << ' ' << scale.z();
        return key.str();
    }

    std::shared_ptr<const TriangleMesh> readMeshFile(const std::string &path, const Eigen::Vector3d &scale,
                                                     MeshCache &cache)
    {
        const std::string key = meshCacheKey(path, scale);
        if (const auto cached = cache.find(key); cached != cache.end())
            return cached->second;

        Assimp::Importer importer;
        const aiScene &scene = importMeshFile(importer, path,
                                              aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                                  aiProcess_PreTransformVertices | aiProcess_SortByPType);
        auto mesh = std::make_shared<TriangleMesh>();
        mesh->file = path;
        for (unsigned int m = 0; m < scene.mNumMeshes; ++m)
        {
            const aiMesh &part = *scene.mMeshes[m];
            const int offset = static_cast<int>(mesh->vertices.size());
            for (unsigned int v = 0; v < part.mNumVertices; ++v)
                mesh->vertices.emplace_back(scale.x() * part.mVertices[v].x, scale.y() * part.mVertices[v].y,
                                            scale.z() * part.mVertices[v].z);
            for (unsigned int f = 0; f < part.mNumFaces; ++f)
                if (part.mFaces[f].mNumIndices == 3)
                    mesh->triangles.push_back({offset + static_cast<int>(part.mFaces[f].mIndices[0]),
                                               offset + static_cast<int>(part.mFaces[f].mIndices[1]),
                                               offset + static_cast<int>(part.mFaces[f].mIndices[2])});
        }
        if (mesh->triangles.empty())
            throw std::runtime_error("the file holds no triangle");
        mesh->measure();
        cache.emplace(key, mesh);
        return mesh;
    }
}  // namespace ompl_mm
