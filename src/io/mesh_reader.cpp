#include "freespace/io/mesh_reader.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "file_extension.h"
#include "freespace/input_error.h"
#include "vtk_reader.h"

namespace freespace {
namespace {

bool isAssimpFormat(const std::string& extension) {
  return extension == ".obj" || extension == ".stl" || extension == ".ply" ||
         extension == ".off" || extension == ".dae";
}

// Opens the file for reading; throws unless it is a readable, non-empty file.
std::ifstream openNonEmptyFile(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throw InputError(path, "cannot open file: it is a directory");
  }
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError(path, "cannot open file: " + std::generic_category().message(errno));
  if (file.peek() == std::ifstream::traits_type::eof()) throw InputError(path, "file is empty");
  return file;
}

Eigen::Matrix4d toEigen(const aiMatrix4x4& matrix) {
  Eigen::Matrix4d converted;
  for (int row = 0; row < 4; ++row) {
    for (int column = 0; column < 4; ++column) converted(row, column) = matrix[row][column];
  }
  return converted;
}

// Appends the triangles of `node`'s meshes, and of its descendants', placed by
// the transform accumulated from the root. Point and line primitives are skipped.
void collectTriangles(const aiScene& scene, const aiNode& node, const Eigen::Matrix4d& parentTransform,
                      TriangleSoup& soup) {
  const Eigen::Matrix4d transform = parentTransform * toEigen(node.mTransformation);
  const Eigen::Matrix3d linear = transform.topLeftCorner<3, 3>();
  const Eigen::Vector3d translation = transform.topRightCorner<3, 1>();
  for (unsigned m = 0; m < node.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
    const auto firstVertex = static_cast<std::uint32_t>(soup.vertices.size());
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D& vertex = mesh.mVertices[v];
      soup.vertices.push_back(linear * Point3(vertex.x, vertex.y, vertex.z) + translation);
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;
      soup.triangles.push_back({firstVertex + face.mIndices[0], firstVertex + face.mIndices[1],
                                firstVertex + face.mIndices[2]});
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) {
    collectTriangles(scene, *node.mChildren[c], transform, soup);
  }
}

// Assimp applies its importers' conventions as OMPL.app sees them: a COLLADA
// file's <unit> scale and its up axis (Z_UP is turned to Y_UP) are in the root
// node's transform.
TriangleSoup readWithAssimp(const std::string& path) {
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(path, aiProcess_Triangulate);
  if (!scene) throw InputError(path, std::string("cannot read mesh: ") + importer.GetErrorString());
  TriangleSoup soup;
  if (scene->mRootNode) collectTriangles(*scene, *scene->mRootNode, Eigen::Matrix4d::Identity(), soup);
  return soup;
}

}  // namespace

TriangleSoup readTriangleSoup(const std::string& path) {
  std::ifstream file = openNonEmptyFile(path);
  const std::string extension = std::filesystem::path(path).extension().string();
  const std::string format = detail::lowercaseExtension(path);
  if (format == ".vtk") {
    const std::string content{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
    return readLegacyVtk(path, content);
  }
  if (isAssimpFormat(format)) return readWithAssimp(path);
  const std::string found = extension.empty() ? ": the file name has no extension"
                                              : " '" + extension + "'";
  throw InputError(path, "unsupported mesh format" + found +
                             " (expected obj, stl, ply, off, dae or vtk)");
}

Mesh loadMesh(const std::string& path, std::vector<std::string>* warnings) {
  return Mesh::fromSoup(readTriangleSoup(path), path, warnings);
}

}  // namespace freespace
