#include "freespace/io/mesh_writer.h"

#include <assimp/material.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Exporter.hpp>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <system_error>

#include "file_extension.h"
#include "freespace/input_error.h"
#include "freespace/io/output_file.h"

namespace freespace {
namespace {

/// Assimp's exporter for an extension ("objnomtl": OBJ without a .mtl file beside
/// it), or an empty string for the formats written here.
std::string assimpFormat(const std::string& extension) {
  if (extension == ".obj") return "objnomtl";
  if (extension == ".stl") return "stl";  // ASCII
  if (extension == ".ply") return "ply";  // ASCII
  if (extension == ".dae") return "collada";
  return "";
}

/// A scene holding the soup under its root node. Assimp stores coordinates as float
/// (ai_real), so a coordinate that is not a float is rounded in these formats.
std::unique_ptr<aiScene> toAssimpScene(const TriangleSoup& soup, const std::string& name) {
  auto scene = std::make_unique<aiScene>();
  scene->mNumMaterials = 1;
  scene->mMaterials = new aiMaterial* [1] { new aiMaterial() };

  auto* out = new aiMesh();
  out->mName = name;
  out->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
  out->mMaterialIndex = 0;
  out->mNumVertices = static_cast<unsigned>(soup.vertices.size());
  out->mVertices = new aiVector3D[out->mNumVertices];
  for (unsigned v = 0; v < out->mNumVertices; ++v) {
    const Point3& p = soup.vertices[v];
    out->mVertices[v] =
        aiVector3D(static_cast<ai_real>(p.x()), static_cast<ai_real>(p.y()), static_cast<ai_real>(p.z()));
  }
  out->mNumFaces = static_cast<unsigned>(soup.triangles.size());
  out->mFaces = new aiFace[out->mNumFaces];
  for (unsigned f = 0; f < out->mNumFaces; ++f) {
    aiFace& face = out->mFaces[f];
    face.mNumIndices = 3;
    face.mIndices = new unsigned[3];
    std::copy(soup.triangles[f].begin(), soup.triangles[f].end(), face.mIndices);
  }
  scene->mNumMeshes = 1;
  scene->mMeshes = new aiMesh* [1] { out };

  scene->mRootNode = new aiNode("root");
  scene->mRootNode->mNumMeshes = 1;
  scene->mRootNode->mMeshes = new unsigned[1]{0};
  return scene;
}

void writeWithAssimp(const TriangleSoup& soup, const std::string& path, const std::string& format) {
  const std::unique_ptr<aiScene> scene = toAssimpScene(soup, std::filesystem::path(path).stem().string());
  Assimp::Exporter exporter;
  if (exporter.Export(scene.get(), format, path) != aiReturn_SUCCESS) {
    throw InputError(path, std::string("cannot write: ") + exporter.GetErrorString());
  }
}

/// The shortest decimal that reads back as exactly the same double.
std::string exactDecimal(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

void writePoint(std::ostream& out, const Point3& p) {
  out << exactDecimal(p.x()) << ' ' << exactDecimal(p.y()) << ' ' << exactDecimal(p.z()) << '\n';
}

void writeTriangle(std::ostream& out, const TriangleIndices& t) {
  out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

/// Legacy VTK, POLYDATA, ASCII, coordinates as exact doubles.
void writeVtk(const TriangleSoup& soup, std::ostream& out) {
  out << "# vtk DataFile Version 3.0\n"
      << "freespace mesh\n"
      << "ASCII\n"
      << "DATASET POLYDATA\n"
      << "POINTS " << soup.vertices.size() << " double\n";
  for (const Point3& p : soup.vertices) writePoint(out, p);
  out << "POLYGONS " << soup.triangles.size() << ' ' << 4 * soup.triangles.size() << '\n';
  for (const TriangleIndices& t : soup.triangles) writeTriangle(out, t);
}

/// Object File Format (assimp 5.2 has no OFF exporter), coordinates as exact doubles.
void writeOff(const TriangleSoup& soup, std::ostream& out) {
  out << "OFF\n" << soup.vertices.size() << ' ' << soup.triangles.size() << " 0\n";
  for (const Point3& p : soup.vertices) writePoint(out, p);
  for (const TriangleIndices& t : soup.triangles) writeTriangle(out, t);
}

/// The only checks: a file of them would be unreadable, or an exporter would read
/// out of bounds.
void requireWritable(const TriangleSoup& soup, const std::string& path) {
  for (std::size_t v = 0; v < soup.vertices.size(); ++v) {
    if (!soup.vertices[v].allFinite()) {
      throw InputError(path, "cannot write: vertex " + std::to_string(v) + " has a non-finite coordinate");
    }
  }
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    for (const std::uint32_t v : soup.triangles[t]) {
      if (v >= soup.vertices.size()) {
        throw InputError(path, "cannot write: triangle " + std::to_string(t) + " refers to vertex " +
                                   std::to_string(v) + ", but there are only " + std::to_string(soup.vertices.size()));
      }
    }
  }
}

}  // namespace

void writeSoup(const TriangleSoup& soup, const std::string& path, bool overwrite) {
  requireWritable(soup, path);
  std::error_code error;
  if (!overwrite && std::filesystem::exists(path, error)) throw InputError(path, "already exists (not overwritten)");
  const std::string extension = detail::lowercaseExtension(path);
  if (extension == ".vtk") {
    writeFile(path, true, [&](std::ostream& out) { writeVtk(soup, out); });
  } else if (extension == ".off") {
    writeFile(path, true, [&](std::ostream& out) { writeOff(soup, out); });
  } else if (const std::string format = assimpFormat(extension); !format.empty()) {
    writeWithAssimp(soup, path, format);
  } else {
    throw InputError(
        path, "cannot write: unsupported mesh format '" + extension + "' (expected obj, stl, ply, off, dae or vtk)");
  }
}

void writeMesh(const Mesh& mesh, const std::string& path, bool overwrite) {
  writeSoup(TriangleSoup{mesh.vertices(), mesh.triangles()}, path, overwrite);
}

}  // namespace freespace
