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
// the robot's centre is their average. They are used for that average alone: the
// import's JoinIdenticalVertices also merges distinct points of a model a few
// millionths across (its tolerance is not relative to the model), so the triangles
// are read without it, and points are welded by the repair (exactly, or within a
// tolerance relative to the model).
constexpr unsigned kOmplAppImportFlags = aiProcess_GenNormals | aiProcess_Triangulate |
                                         aiProcess_JoinIdenticalVertices | aiProcess_SortByPType |
                                         aiProcess_OptimizeGraph;
constexpr unsigned kGeometryImportFlags = aiProcess_Triangulate | aiProcess_SortByPType;

// Calls `visit(mesh, transform)` for the meshes of `node` and of its descendants,
// each with the transform accumulated from the root.
template <class Visit>
void forEachPlacedMesh(const aiScene& scene, const aiNode& node, aiMatrix4x4 transform, const Visit& visit) {
  transform *= node.mTransformation;
  for (unsigned m = 0; m < node.mNumMeshes; ++m) visit(*scene.mMeshes[node.mMeshes[m]], transform);
  for (unsigned c = 0; c < node.mNumChildren; ++c) forEachPlacedMesh(scene, *node.mChildren[c], transform, visit);
}

// The triangles of the scene's meshes, placed by their nodes' transforms in single
// precision as OMPL.app places them. Each mesh a node holds is a piece of its own.
// Point and line primitives add no triangles.
TriangleSoup trianglesOf(const aiScene& scene) {
  TriangleSoup soup;
  if (!scene.mRootNode) return soup;
  forEachPlacedMesh(scene, *scene.mRootNode, aiMatrix4x4(), [&](const aiMesh& mesh, const aiMatrix4x4& transform) {
    const auto firstVertex = static_cast<std::uint32_t>(soup.vertices.size());
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D placed = transform * mesh.mVertices[v];
      soup.vertices.emplace_back(placed.x, placed.y, placed.z);
    }
    const auto piece = soup.pieces.empty() ? 0u : soup.pieces.back() + 1;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;
      soup.triangles.push_back({firstVertex + face.mIndices[0], firstVertex + face.mIndices[1],
                                firstVertex + face.mIndices[2]});
      soup.pieces.push_back(piece);
    }
  });
  return soup;
}

// The average of every placed vertex, summed in single precision as OMPL.app sums
// them (so that it is OMPL.app's robot centre to the bit).
Point3 vertexAverageOf(const aiScene& scene) {
  aiVector3D sum(0, 0, 0);
  std::size_t count = 0;
  if (scene.mRootNode) {
    forEachPlacedMesh(scene, *scene.mRootNode, aiMatrix4x4(), [&](const aiMesh& mesh, const aiMatrix4x4& transform) {
      for (unsigned v = 0; v < mesh.mNumVertices; ++v) sum += transform * mesh.mVertices[v];
      count += mesh.mNumVertices;
    });
  }
  if (count > 0) sum /= static_cast<float>(count);
  return Point3(sum.x, sum.y, sum.z);
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

// The scene assimp makes of the input with `flags`. Assimp applies its importers'
// conventions as OMPL.app sees them: a COLLADA file's <unit> scale and its up axis
// (Z_UP is turned to Y_UP) are in the root node's transform.
const aiScene& importedScene(Assimp::Importer& importer, const std::string& path, const detail::ImportText& input,
                             unsigned flags) {
  const aiScene* scene = importer.ReadFileFromMemory(input.text.data(), input.text.size(), flags, input.format.c_str());
  if (!scene) throw InputError(path, std::string("cannot read mesh: ") + importer.GetErrorString());
  requireFiniteAsRead(path, *scene);
  return *scene;
}

ImportedMesh importWithAssimp(const std::string& path, const detail::ImportText& input, bool withCentre) {
  ImportedMesh imported;
  {
    Assimp::Importer importer;
    imported.soup = trianglesOf(importedScene(importer, path, input, kGeometryImportFlags));
  }
  if (withCentre) {
    Assimp::Importer importer;
    imported.vertexAverage = vertexAverageOf(importedScene(importer, path, input, kOmplAppImportFlags));
  }
  return imported;
}

// The import library trusts counts and indices: PLY, OFF, OBJ and COLLADA files are
// checked against their own headers and structure first (mesh_file_checks.h), and read
// from memory: the import sees the very bytes the checks saw (an OFF file as the
// text its check returns).
detail::ImportText checkedForImport(const std::string& path, const std::string& format, std::string content) {
  if (format == ".ply") detail::checkPlyFile(path, content);
  if (format == ".obj") detail::checkObjFaces(path, content);
  if (format == ".dae") detail::checkColladaFile(path, content);
  if (format == ".off") return detail::checkOffFile(path, content);
  return {std::move(content), format.substr(1)};
}

// Formats OMPL.app cannot read have no convention of their own: the plain average of
// the vertices as read.
Point3 averageOf(const std::vector<Point3>& vertices) {
  Point3 sum = Point3::Zero();
  for (const Point3& vertex : vertices) sum += vertex;
  return vertices.empty() ? sum : Point3(sum / static_cast<double>(vertices.size()));
}

// The file's triangles and, `withCentre`, the average of its vertices as imported.
ImportedMesh importMeshFile(const std::string& path, bool withCentre) {
  std::ifstream file = openNonEmptyFile(path);
  const std::string format = detail::lowercaseExtension(path);
  if (format != ".vtk" && !isAssimpFormat(format)) {
    const std::string extension = std::filesystem::path(path).extension().string();
    const std::string found = extension.empty() ? ": the file name has no extension" : " '" + extension + "'";
    throw InputError(path, "unsupported mesh format" + found + " (expected obj, stl, ply, off, dae or vtk)");
  }
  std::string content{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
  if (format != ".vtk") return importWithAssimp(path, checkedForImport(path, format, std::move(content)), withCentre);
  ImportedMesh imported{readLegacyVtk(path, content), Point3::Zero()};
  if (withCentre) imported.vertexAverage = averageOf(imported.soup.vertices);
  return imported;
}

}  // namespace

ImportedMesh importMesh(const std::string& path) { return importMeshFile(path, true); }

TriangleSoup readTriangleSoup(const std::string& path) { return importMeshFile(path, false).soup; }

}  // namespace freespace
