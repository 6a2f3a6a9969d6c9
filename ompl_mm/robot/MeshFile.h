/* Collision meshes of URDF links: where a mesh file is, and its triangles. */
#pragma once

#include "ompl_mm/scene/TriangleMesh.h"

#include <map>
#include <memory>
#include <string>

namespace Assimp
{
    class Importer;
}
struct aiScene;

namespace ompl_mm
{
    /** The file a URDF mesh element's filename names: a relative name against the URDF's folder,
        then against each of its ancestors (PyBullet-style paths, relative to a folder above the URDF);
        "package://NAME/PATH" against each folder of the environment variable OMPL_MM_PACKAGE_PATH
        (colon-separated, like ROS_PACKAGE_PATH) that holds NAME/PATH, then against the URDF's
        ancestors that hold NAME/PATH (so the package folder itself is found from inside it);
        "file://" is dropped.
        @returns the path, or "" when no candidate exists; tried lists the places looked. */
    std::string resolveMeshFile(const std::string &filename, const std::string &urdfFile, std::string &tried);

    /** Reads a mesh file with importer and the post-processing steps given (a COLLADA file's up axis
        ignored, as in ROS), a COLLADA file after the checks assimp 5.2 lacks (checkColladaFile()).
        @returns the scene, owned by importer.
        @throws std::runtime_error with the file's line, or with the reader's message. */
    const aiScene &importMeshFile(Assimp::Importer &importer, const std::string &path, unsigned int steps);

    /** The key of a mesh file read at a scale, for caches of what is read from it. */
    std::string meshCacheKey(const std::string &path, const Eigen::Vector3d &scale);

    /** Meshes read so far, by file and scale: a file several links use is read once. */
    using MeshCache = std::map<std::string, std::shared_ptr<const TriangleMesh>>;

    /** The triangles of a mesh file (STL, OBJ, DAE and what else assimp reads), every node's
        transform applied, scaled per axis; from cache when read before with this scale. As in
        ROS, a COLLADA file's up axis is ignored (its coordinates are taken as they are, z up);
        its unit is applied.
        @throws std::runtime_error with the reader's message when the file cannot be read or holds
        no triangle. */
    std::shared_ptr<const TriangleMesh> readMeshFile(const std::string &path, const Eigen::Vector3d &scale,
                                                     MeshCache &cache);
}  // namespace ompl_mm
