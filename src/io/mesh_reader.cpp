#include "freespace/io/mesh_reader.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <system_error>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "file_extension.h"
#include "freespace/input_error.h"
#include "freespace/io/input_file.h"
#include "mesh_file_checks.h"
#include "vtk_reader.h"

namespace freespace {
namespace {

bool isAssimpFormat(const std::string& extension) {
  return extension == ".obj" || extension == ".stl" || extension == ".ply" ||
         extension == ".off" || extension == ".dae";
}

// Opens the file for reading; throws unless it is a readable, non-empty file.
std::ifstream openNonEmptyFile(const std::string& path) {
  std::ifstream file = openInputFile(path, std::ios::binary);
  if (file.peek() == std::ifstream::traits_type::eof()) throw InputError(path, "file is empty");
  return file;
}

// OMPL.app's import flags: the same flags give the same vertices (JoinIdenticalVertices
// merges only corners with equal normals, so GenNormals changes how many remain), and
// the robot's centre is their average.
constexpr unsigned kOmplAppImportFlags = aiProcess_GenNormals | aiProcess_Triangulate |
                                         aiProcess_JoinIdenticalVertices | aiProcess_SortByPType |
                                         aiProcess_OptimizeGraph;

// Appends the triangles of `node`'s meshes, and of its descendants', placed by the
// transform accumulated from the root, and adds every vertex of those meshes to
// `vertexSum`. Both are computed in single precision as OMPL.app computes them, so the
// positions and the sum are OMPL.app's to the bit. Each mesh a node holds is a piece
// of its own. Point and line primitives add no triangles.
void collectTriangles(const aiScene& scene, const aiNode& node, aiMatrix4x4 transform, ImportedMesh& imported,
                      aiVector3D& vertexSum, std::size_t& vertexCount, std::size_t& pieceCount) {
  transform *= node.mTransformation;
  for (unsigned m = 0; m < node.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
    TriangleSoup& soup = imported.soup;
    const auto firstVertex = static_cast<std::uint32_t>(soup.vertices.size());
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D placed = transform * mesh.mVertices[v];
      soup.vertices.emplace_back(placed.x, placed.y, placed.z);
      vertexSum += placed;
    }
    vertexCount += mesh.mNumVertices;
    const auto piece = static_cast<std::uint32_t>(pieceCount++);
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;
      soup.triangles.push_back({firstVertex + face.mIndices[0], firstVertex + face.mIndices[1],
                                firstVertex + face.mIndices[2]});
      soup.pieces.push_back(piece);
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) {
    collectTriangles(scene, *node.mChildren[c], transform, imported, vertexSum, vertexCount, pieceCount);
  }
}

// Coordinates are read as floats: one beyond their range (about 3.4e38) is infinite,
// and a transform would turn it into NaN; said here, as read.
void requireFiniteAsRead(const std::string& path, const aiScene& scene) {
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    for (unsigned v = 0; v < scene.mMeshes[m]->mNumVertices; ++v) {
      const aiVector3D& p = scene.mMeshes[m]->mVertices[v];
      if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) continue;
      std::ostringstream text;
      text << "a vertex at (" << p.x << ", " << p.y << ", " << p.z
           << ") as read: coordinates must be finite and within single precision's range (about 3.4e38), "
              "in which the file is read";
      throw InputError(path, text.str());
    }
  }
}

// Assimp applies its importers' conventions as OMPL.app sees them: a COLLADA
// file's <unit> scale and its up axis (Z_UP is turned to Y_UP) are in the root
// node's transform. `objText`, when not empty, is read in place of the file (an OFF
// file's polygons as OBJ: checkOffFile).
ImportedMesh importWithAssimp(const std::string& path, const std::string& objText) {
  Assimp::Importer importer;
  const aiScene* scene = objText.empty()
                             ? importer.ReadFile(path, kOmplAppImportFlags)
                             : importer.ReadFileFromMemory(objText.data(), objText.size(), kOmplAppImportFlags, "obj");
  if (!scene) throw InputError(path, std::string("cannot read mesh: ") + importer.GetErrorString());
  requireFiniteAsRead(path, *scene);
  ImportedMesh imported;
  aiVector3D vertexSum(0, 0, 0);
  std::size_t vertexCount = 0, pieceCount = 0;
  if (scene->mRootNode) {
    collectTriangles(*scene, *scene->mRootNode, aiMatrix4x4(), imported, vertexSum, vertexCount, pieceCount);
  }
  if (vertexCount > 0) vertexSum /= static_cast<float>(vertexCount);
  imported.vertexAverage = Point3(vertexSum.x, vertexSum.y, vertexSum.z);
  return imported;
}

// The import library trusts counts and indices: PLY, OFF, OBJ and COLLADA files are
// checked against their own headers and structure first (mesh_file_checks.h).
// Returns the text to import in place of the file: empty but for an OFF file with
// faces the import library's OFF reader would drop.
std::string checkBeforeImport(const std::string& path, const std::string& format, std::ifstream& file) {
  if (format == ".stl") return {};
  const std::string content{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
  if (format == ".ply") detail::checkPlyFile(path, content);
  if (format == ".off") return detail::checkOffFile(path, content);
  if (format == ".obj") detail::checkObjFaces(path, content);
  if (format == ".dae") detail::checkColladaFile(path, content);
  return {};
}

// Formats OMPL.app cannot read have no convention of their own: the plain average of
// the vertices as read.
Point3 averageOf(const std::vector<Point3>& vertices) {
  Point3 sum = Point3::Zero();
  for (const Point3& vertex : vertices) sum += vertex;
  return vertices.empty() ? sum : Point3(sum / static_cast<double>(vertices.size()));
}

}  // namespace

ImportedMesh importMesh(const std::string& path) {
  std::ifstream file = openNonEmptyFile(path);
  const std::string extension = std::filesystem::path(path).extension().string();
  const std::string format = detail::lowercaseExtension(path);
  if (format == ".vtk") {
    const std::string content{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
    ImportedMesh imported{readLegacyVtk(path, content), Point3::Zero()};
    imported.vertexAverage = averageOf(imported.soup.vertices);
    return imported;
  }
  if (isAssimpFormat(format)) {
    return importWithAssimp(path, checkBeforeImport(path, format, file));
  }
  const std::string found = extension.empty() ? ": the file name has no extension"
                                              : " '" + extension + "'";
  throw InputError(path, "unsupported mesh format" + found +
                             " (expected obj, stl, ply, off, dae or vtk)");
}

TriangleSoup readTriangleSoup(const std::string& path) { return importMesh(path).soup; }

}  // namespace freespace
