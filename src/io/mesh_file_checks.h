#pragma once

// Checks of mesh files before the import library reads them (docs/design.md section
// 9): the import library trusts counts and indices, so a truncated or edited PLY or
// OFF file, or a COLLADA file nested deep or instancing itself, can make it loop for
// ever, exhaust memory or crash. These read the whole
// file against its own header, bounds checked, and throw InputError naming the file
// and the defect; they build nothing.

#include <string>

namespace freespace::detail {

/// A PLY file (ASCII or binary, either byte order): a complete header; a vertex
/// element with x, y and z and a face element with a vertex index list; every
/// element's records present in full (counts weighed against the file's size first),
/// in ASCII each on a line of its own with nothing else (the import library reads a
/// record per line); every face with at least 3 vertices, each an index of a vertex.
void checkPlyFile(const std::string& path, const std::string& content);

/// What the import library reads in place of a file: a text and its format as the
/// library names it ("off", "obj", ...).
struct ImportText {
  std::string text;
  std::string format;
};

/// An OFF file (3D; OFF, COFF, NOFF, CNOFF, STOFF ... headers), plain text: its counts, weighed
/// against the file's size; every vertex line with 3 numbers; every face with at
/// least 3 vertices, each an index of a vertex. Returns the same vertices and faces as
/// the import library should read them: one record per line, without comments, blank
/// lines or attributes (its OFF reader takes a blank line for a face, and crashed on
/// such files), as OFF; as OBJ when a face has more than kLargestOffFaceImported
/// vertices (the OFF reader drops those faces, the OBJ reader takes any).
ImportText checkOffFile(const std::string& path, const std::string& content);
constexpr int kLargestOffFaceImported = 9;

/// An OBJ file: plain text (no control characters but tabs and line ends), every
/// face ('f') with at least 3 vertices (the import library takes a
/// shorter one for a point or a line without a word).
void checkObjFaces(const std::string& path, const std::string& content);

/// A COLLADA file: well-formed XML without control characters but tabs and line
/// ends, elements nested at most 256 deep, no node that
/// instances itself through <instance_node> (directly or by a chain), every
/// <float_array> holding as many numbers as its count says and every <accessor>
/// reading within an array of the file, every index list (<p>, <v>, <vcount>, <h>) of whole
/// numbers below the number of values the file holds, and every primitive element
/// (<triangles>, <polylist>, ...) with as many indices as its count and inputs need.
void checkColladaFile(const std::string& path, const std::string& content);

}  // namespace freespace::detail
