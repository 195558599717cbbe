// The check of PLY files before import (mesh_file_checks.h).
#include "mesh_file_checks.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string_view>
#include <vector>

#include "freespace/input_error.h"
#include "mesh_text.h"

namespace freespace::detail {

namespace {

enum class PlyFormat { ascii, littleEndian, bigEndian };

struct PlyProperty {
  std::string name;
  int size = 0;             // bytes of a value (of an item, for a list)
  bool integer = false;     // an integer type
  bool isSigned = false;
  int countSize = 0;        // lists: bytes of the count; 0 for a scalar
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  PlyFormat format = PlyFormat::ascii;
  std::vector<PlyElement> elements;
  std::size_t bodyStart = 0;
};

// Size, integer and sign of a PLY type name; false for an unknown one.
bool plyType(std::string_view name, PlyProperty& type) {
  static const struct {
    const char* names[2];
    int size;
    bool integer, isSigned;
  } kTypes[] = {{{"char", "int8"}, 1, true, true},         {{"uchar", "uint8"}, 1, true, false},
                {{"short", "int16"}, 2, true, true},       {{"ushort", "uint16"}, 2, true, false},
                {{"int", "int32"}, 4, true, true},         {{"uint", "uint32"}, 4, true, false},
                {{"float", "float32"}, 4, false, true},    {{"double", "float64"}, 8, false, true}};
  for (const auto& known : kTypes) {
    if (name == known.names[0] || name == known.names[1]) {
      type.size = known.size;
      type.integer = known.integer;
      type.isSigned = known.isSigned;
      return true;
    }
  }
  return false;
}

constexpr std::size_t kLongestPlyHeader = 1 << 20;

PlyHeader readPlyHeader(const std::string& path, const std::string& content) {
  // The header's lines, up to a line that is "end_header" and nothing else.
  Lines lines(std::string_view(content).substr(0, std::min(content.size(), kLongestPlyHeader)));
  PlyHeader header;
  bool formatSeen = false, ended = false;
  std::size_t bodyStart = 0;
  std::string_view line;
  while (!ended && lines.next(line)) {
    bodyStart = static_cast<std::size_t>(line.data() - content.data()) + line.size() + 1;
    const std::vector<std::string_view> words = wordsOf(line);
    const std::string where = "PLY header line " + std::to_string(lines.number()) + ": ";
    if (lines.number() == 1) {
      if (words.size() != 1 || words[0] != "ply") throw InputError(path, where + "expected 'ply'");
      continue;
    }
    if (words.empty() || words[0] == "comment" || words[0] == "obj_info") continue;
    if (words[0] == "end_header" && words.size() == 1) {
      ended = true;
      continue;
    }
    if (words[0] == "format" && words.size() == 3) {
      if (words[1] == "ascii") header.format = PlyFormat::ascii;
      else if (words[1] == "binary_little_endian") header.format = PlyFormat::littleEndian;
      else if (words[1] == "binary_big_endian") header.format = PlyFormat::bigEndian;
      else throw InputError(path, where + "unknown format '" + printable(words[1]) + "'");
      formatSeen = true;
    } else if (words[0] == "element" && words.size() == 3) {
      std::int64_t count = 0;
      if (!parseWhole(words[2], count) || count < 0) throw InputError(path, where + "element count is not a whole number");
      header.elements.push_back({std::string(words[1]), static_cast<std::uint64_t>(count), {}});
    } else if (words[0] == "property" && !header.elements.empty() && words.size() >= 3) {
      PlyProperty property;
      PlyProperty countType;
      const bool list = words[1] == "list";
      if (list && (words.size() != 5 || !plyType(words[2], countType) || !countType.integer ||
                   !plyType(words[3], property))) {
        throw InputError(path, where + "malformed list property");
      }
      if (!list && (words.size() != 3 || !plyType(words[1], property))) {
        throw InputError(path, where + "malformed property");
      }
      property.name = std::string(words.back());
      property.countSize = list ? countType.size : 0;
      header.elements.back().properties.push_back(property);
    } else {
      throw InputError(path, where + "unexpected '" + printable(line) + "'");
    }
  }
  if (!ended) throw InputError(path, "PLY header has no end_header line");
  if (!formatSeen) throw InputError(path, "PLY header has no format line");
  header.bodyStart = std::min(bodyStart, content.size());
  return header;
}

// The vertex count, and which element and property hold the faces' vertex indices.
struct PlyMeshLayout {
  std::uint64_t vertices = 0;
  std::size_t faceElement = 0;
  std::size_t indexProperty = 0;
};

PlyMeshLayout plyMeshLayout(const std::string& path, const PlyHeader& header) {
  PlyMeshLayout layout;
  bool vertexFound = false, faceFound = false;
  for (std::size_t e = 0; e < header.elements.size(); ++e) {
    const PlyElement& element = header.elements[e];
    if (element.name == "vertex") {
      int coordinates = 0;
      for (const PlyProperty& property : element.properties) {
        coordinates += property.countSize == 0 && (property.name == "x" || property.name == "y" || property.name == "z");
      }
      if (coordinates != 3) throw InputError(path, "PLY vertex element lacks x, y or z");
      layout.vertices = element.count;
      vertexFound = true;
    } else if (element.name == "face") {
      for (std::size_t p = 0; p < element.properties.size(); ++p) {
        const PlyProperty& property = element.properties[p];
        if (property.countSize > 0 && (property.name == "vertex_indices" || property.name == "vertex_index")) {
          if (!property.integer) throw InputError(path, "PLY face vertex indices are not integers");
          layout.faceElement = e;
          layout.indexProperty = p;
          faceFound = true;
        }
      }
    }
  }
  if (!vertexFound) throw InputError(path, "PLY file has no vertex element");
  if (!faceFound) throw InputError(path, "PLY file has no face element with a vertex_indices list");
  return layout;
}

// The fewest bytes the body can take: records of fixed size and empty lists (binary),
// or one character and a separator per value (ASCII). A header promising more
// than the file holds is refused before any record is read.
void requirePlyBodySize(const std::string& path, const PlyHeader& header, std::size_t available) {
  long double least = 0;
  for (const PlyElement& element : header.elements) {
    long double record = 0;
    for (const PlyProperty& property : element.properties) {
      if (header.format == PlyFormat::ascii) record += 2;
      else record += property.countSize > 0 ? property.countSize : property.size;
    }
    least += record * static_cast<long double>(element.count);
  }
  if (least > static_cast<long double>(available)) {
    std::ostringstream text;
    text << "PLY file is truncated: its header promises records of at least " << static_cast<double>(least)
         << " bytes, the file has " << available << " after its header";
    throw InputError(path, text.str());
  }
}

// Reads the values of a binary PLY body, bounds checked.
class BinaryReader {
 public:
  BinaryReader(const std::string& path, const std::string& content, std::size_t at, bool bigEndian)
      : path_(path), content_(content), at_(at), bigEndian_(bigEndian) {}

  std::int64_t integer(const PlyProperty& type, int size) {
    std::uint64_t bits = 0;
    const unsigned char* bytes = take(size);
    for (int i = 0; i < size; ++i) {
      const int from = bigEndian_ ? i : size - 1 - i;
      bits = (bits << 8) | bytes[from];
    }
    if (type.isSigned && size < 8 && (bits >> (8 * size - 1)) != 0) bits |= ~std::uint64_t{0} << (8 * size);
    return static_cast<std::int64_t>(bits);
  }
  void skip(std::uint64_t bytes) {
    if (bytes > content_.size() - at_) truncated();
    at_ += bytes;
  }

 private:
  const unsigned char* take(int size) {
    if (static_cast<std::size_t>(size) > content_.size() - at_) truncated();
    const auto* bytes = reinterpret_cast<const unsigned char*>(content_.data() + at_);
    at_ += size;
    return bytes;
  }
  [[noreturn]] void truncated() const { throw InputError(path_, "PLY file is truncated: a record runs past its end"); }

  const std::string& path_;
  const std::string& content_;
  std::size_t at_;
  bool bigEndian_;
};

void checkPlyBinaryBody(const std::string& path, const std::string& content, const PlyHeader& header,
                        const PlyMeshLayout& layout) {
  BinaryReader reader(path, content, header.bodyStart, header.format == PlyFormat::bigEndian);
  for (std::size_t e = 0; e < header.elements.size(); ++e) {
    const PlyElement& element = header.elements[e];
    for (std::uint64_t record = 0; record < element.count; ++record) {
      for (std::size_t p = 0; p < element.properties.size(); ++p) {
        const PlyProperty& property = element.properties[p];
        if (property.countSize == 0) {
          reader.skip(property.size);
          continue;
        }
        PlyProperty countType;
        countType.isSigned = false;
        const std::int64_t count = reader.integer(countType, property.countSize);
        if (count < 0 || count > static_cast<std::int64_t>(content.size())) {
          throw InputError(path, "PLY " + printable(element.name) + " " + std::to_string(record) + ": list length " +
                                     std::to_string(count) + " does not fit the file");
        }
        const bool indices = e == layout.faceElement && p == layout.indexProperty;
        if (indices && count < 3) throw InputError(path, faceDefect(record, count));
        if (!indices) {
          reader.skip(static_cast<std::uint64_t>(count) * property.size);
          continue;
        }
        for (std::int64_t i = 0; i < count; ++i) {
          const std::int64_t index = reader.integer(property, property.size);
          if (index < 0 || static_cast<std::uint64_t>(index) >= layout.vertices) {
            throw InputError(path, indexDefect(record, std::to_string(index), layout.vertices));
          }
        }
      }
    }
  }
}

// Each record on a line of its own holding its values and nothing else: the import
// library reads a record per line, and one split over lines or sharing a line would
// be read as other records than the checks saw (found by fuzzing: a vertex of two
// values made it read the face as a vertex and crash).
void checkPlyAsciiBody(const std::string& path, const std::string& content, const PlyHeader& header,
                       const PlyMeshLayout& layout) {
  const std::string_view body = std::string_view(content).substr(header.bodyStart);
  const std::size_t headerLines = static_cast<std::size_t>(
      std::count(content.begin(), content.begin() + static_cast<std::ptrdiff_t>(header.bodyStart), '\n'));
  Lines lines(body);
  std::string_view line;
  for (std::size_t e = 0; e < header.elements.size(); ++e) {
    const PlyElement& element = header.elements[e];
    for (std::uint64_t record = 0; record < element.count; ++record) {
      const std::string what = printable(element.name) + " " + std::to_string(record);
      if (!lines.next(line)) throw InputError(path, "PLY file is truncated: " + what + " is missing");
      const std::string where = "PLY line " + std::to_string(headerLines + lines.number()) + ": " + what;
      const std::vector<std::string_view> words = wordsOf(line);
      std::size_t used = 0;
      const auto next = [&] {
        if (used == words.size()) {
          throw InputError(path, where + " has fewer values than its properties (records are one per line)");
        }
        return words[used++];
      };
      const auto number = [&] {
        double value = 0;
        if (!parseNumber(next(), value)) {
          throw InputError(path, where + ": '" + printable(words[used - 1]) + "' is not a number");
        }
      };
      // Counts and indices in the digits the import library reads ("+3" it reads as 0).
      const auto whole = [&] {
        std::int64_t value = 0;
        if (!parseWhole(next(), value)) {
          throw InputError(path, where + ": '" + printable(words[used - 1]) + "' is not a whole number");
        }
        return value;
      };
      for (std::size_t p = 0; p < element.properties.size(); ++p) {
        const PlyProperty& property = element.properties[p];
        if (property.countSize == 0) {
          number();
          continue;
        }
        const std::int64_t count = whole();
        if (count < 0 || static_cast<std::size_t>(count) > words.size() - used) {
          throw InputError(path, where + ": list length " + std::to_string(count) + " but " +
                                     std::to_string(words.size() - used) + " values follow on its line");
        }
        const bool indices = e == layout.faceElement && p == layout.indexProperty;
        if (indices && count < 3) throw InputError(path, faceDefect(record, count));
        for (std::int64_t i = 0; i < count; ++i) {
          if (!indices) {
            number();
            continue;
          }
          const std::int64_t index = whole();
          if (index < 0 || static_cast<std::uint64_t>(index) >= layout.vertices) {
            throw InputError(path, indexDefect(record, printable(words[used - 1]), layout.vertices));
          }
        }
      }
      if (used != words.size()) {
        throw InputError(path, where + " has more values than its properties (records are one per line)");
      }
    }
  }
}

}  // namespace

void checkPlyFile(const std::string& path, const std::string& content) {
  const PlyHeader header = readPlyHeader(path, content);
  requirePlainText(path, std::string_view(content).substr(0, header.bodyStart), "PLY header of the", true);
  if (header.format == PlyFormat::ascii) requirePlainText(path, content, "PLY", true);
  const PlyMeshLayout layout = plyMeshLayout(path, header);
  requirePlyBodySize(path, header, content.size() - header.bodyStart);
  if (header.format == PlyFormat::ascii) {
    checkPlyAsciiBody(path, content, header, layout);
  } else {
    checkPlyBinaryBody(path, content, header, layout);
  }
}

}  // namespace freespace::detail
