#include "mesh_file_checks.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <map>
#include <sstream>
#include <string_view>
#include <vector>

#include <pugixml.hpp>

#include "freespace/input_error.h"

namespace freespace::detail {

namespace {

// ---------------------------------------------------------------------------------
// Text helpers

// Splits a line into whitespace-separated words.
std::vector<std::string_view> wordsOf(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t at = 0;
  while (at < line.size()) {
    while (at < line.size() && std::isspace(static_cast<unsigned char>(line[at]))) ++at;
    const std::size_t start = at;
    while (at < line.size() && !std::isspace(static_cast<unsigned char>(line[at]))) ++at;
    if (at > start) words.push_back(line.substr(start, at - start));
  }
  return words;
}

bool parseNumber(std::string_view word, double& value) {
  const std::string text(word);
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return !text.empty() && end == text.c_str() + text.size();
}

bool parseWhole(std::string_view word, std::int64_t& value) {
  const std::string text(word);
  char* end = nullptr;
  errno = 0;
  value = std::strtoll(text.c_str(), &end, 10);
  return !text.empty() && end == text.c_str() + text.size() && errno == 0;
}

// The lines of a text, one at a time, with their numbers (from 1).
class Lines {
 public:
  explicit Lines(std::string_view text, std::size_t from = 0) : text_(text), at_(from) {}
  bool next(std::string_view& line) {
    if (at_ >= text_.size()) return false;
    const std::size_t end = std::min(text_.find('\n', at_), text_.size());
    line = text_.substr(at_, end - at_);
    at_ = end + 1;
    ++number_;
    return true;
  }
  std::size_t number() const { return number_; }

 private:
  std::string_view text_;
  std::size_t at_;
  std::size_t number_ = 0;
};

// Text formats hold no control characters but tabs and line ends: the import library
// reads a NUL byte as the end of a line, and its counts then disagree with ours. In
// formats of lines, a carriage return ends a line only before a line feed (the import
// library ends a line at any, we would not: a record would be split in two).
void requirePlainText(const std::string& path, std::string_view text, const std::string& format, bool ofLines) {
  for (std::size_t at = 0; at < text.size(); ++at) {
    const auto c = static_cast<unsigned char>(text[at]);
    const bool lineEnd = c == '\n' || (c == '\r' && (!ofLines || (at + 1 < text.size() && text[at + 1] == '\n')));
    if (c < 0x20 && c != '\t' && !lineEnd) {
      throw InputError(path, format + " file holds a control character (byte " + std::to_string(c) + " at offset " +
                                 std::to_string(at) + ")");
    }
  }
}

// Text from a file as a message may quote it: bytes that are not printable ASCII
// become '?'.
std::string printable(std::string_view text) {
  std::string result(text.substr(0, 80));
  for (char& c : result) {
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7e) c = '?';
  }
  return result;
}

std::string faceDefect(std::size_t face, std::int64_t corners) {
  return "face " + std::to_string(face) + " has " + std::to_string(corners) + " vertices (at least 3 needed)";
}

std::string indexDefect(std::size_t face, const std::string& index, std::uint64_t vertices) {
  return "face " + std::to_string(face) + " uses vertex " + index + " of " + std::to_string(vertices) +
         " (out of range)";
}

// ---------------------------------------------------------------------------------
// PLY

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

void checkPlyAsciiBody(const std::string& path, const std::string& content, const PlyHeader& header,
                       const PlyMeshLayout& layout) {
  std::size_t at = header.bodyStart;
  const auto nextWord = [&](std::string_view& word) {
    while (at < content.size() && std::isspace(static_cast<unsigned char>(content[at]))) ++at;
    const std::size_t start = at;
    while (at < content.size() && !std::isspace(static_cast<unsigned char>(content[at]))) ++at;
    if (at == start) throw InputError(path, "PLY file is truncated: it ends before the records its header promises");
    word = std::string_view(content).substr(start, at - start);
  };
  std::string_view word;
  const auto number = [&](const std::string& what) {
    nextWord(word);
    double value = 0;
    if (!parseNumber(word, value)) throw InputError(path, "PLY " + what + ": '" + printable(word) + "' is not a number");
    return value;
  };
  for (std::size_t e = 0; e < header.elements.size(); ++e) {
    const PlyElement& element = header.elements[e];
    for (std::uint64_t record = 0; record < element.count; ++record) {
      const std::string what = printable(element.name) + " " + std::to_string(record);
      for (std::size_t p = 0; p < element.properties.size(); ++p) {
        const PlyProperty& property = element.properties[p];
        if (property.countSize == 0) {
          number(what);
          continue;
        }
        const double count = number(what);
        if (count != std::floor(count) || count < 0 || count > 1e9) {
          throw InputError(path, "PLY " + what + ": list length is not a whole number");
        }
        const bool indices = e == layout.faceElement && p == layout.indexProperty;
        if (indices && count < 3) throw InputError(path, faceDefect(record, static_cast<std::int64_t>(count)));
        for (double i = 0; i < count; ++i) {
          const double index = number(what);
          if (indices && (index != std::floor(index) || index < 0 || index >= static_cast<double>(layout.vertices))) {
            throw InputError(path, indexDefect(record, printable(word), layout.vertices));
          }
        }
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

void checkOffFile(const std::string& path, const std::string& content) {
  requirePlainText(path, content, "OFF", true);
  Lines lines(content);
  std::string_view line;
  std::vector<std::string_view> words;
  // The next line with words, comments removed; false at the end.
  const auto nextWords = [&] {
    while (lines.next(line)) {
      words = wordsOf(line.substr(0, std::min(line.find('#'), line.size())));
      if (!words.empty()) return true;
    }
    return false;
  };
  if (!nextWords()) throw InputError(path, "OFF file is empty");
  const std::string_view keyword = words[0];
  if (keyword.size() < 3 || keyword.substr(keyword.size() - 3) != "OFF") {
    throw InputError(path, "OFF file does not start with OFF");
  }
  if (keyword.find('4') != std::string_view::npos || keyword.find('n') != std::string_view::npos) {
    throw InputError(path, "only three-dimensional OFF files are read ('" + printable(keyword) + "')");
  }
  std::vector<std::string_view> counts(words.begin() + 1, words.end());
  if (counts.empty()) {
    if (!nextWords()) throw InputError(path, "OFF file has no counts");
    counts = words;
  }
  std::int64_t vertices = 0, faces = 0;
  if (counts.size() < 2 || !parseWhole(counts[0], vertices) || !parseWhole(counts[1], faces) || vertices < 0 ||
      faces < 0) {
    throw InputError(path, "OFF counts line is not two or three whole numbers");
  }
  // A vertex takes at least 6 bytes ("0 0 0\n"), a face at least 8 ("3 0 1 2\n").
  if (6.0L * vertices + 8.0L * faces > static_cast<long double>(content.size())) {
    throw InputError(path, "OFF file is truncated: it promises " + std::to_string(vertices) + " vertices and " +
                               std::to_string(faces) + " faces in " + std::to_string(content.size()) + " bytes");
  }
  for (std::int64_t v = 0; v < vertices; ++v) {
    double coordinate = 0;
    if (!nextWords()) throw InputError(path, "OFF file is truncated: vertex " + std::to_string(v) + " is missing");
    if (words.size() < 3 || !parseNumber(words[0], coordinate) || !parseNumber(words[1], coordinate) ||
        !parseNumber(words[2], coordinate)) {
      throw InputError(path, "OFF line " + std::to_string(lines.number()) + ": vertex " + std::to_string(v) +
                                 " is not three numbers");
    }
  }
  for (std::int64_t f = 0; f < faces; ++f) {
    if (!nextWords()) throw InputError(path, "OFF file is truncated: face " + std::to_string(f) + " is missing");
    std::int64_t corners = 0;
    if (!parseWhole(words[0], corners)) {
      throw InputError(path, "OFF line " + std::to_string(lines.number()) + ": face " + std::to_string(f) +
                                 " does not start with its vertex count");
    }
    if (corners < 3) throw InputError(path, faceDefect(f, corners));
    if (static_cast<std::int64_t>(words.size()) - 1 < corners) {
      throw InputError(path, "OFF line " + std::to_string(lines.number()) + ": face " + std::to_string(f) + " lists " +
                                 std::to_string(words.size() - 1) + " of its " + std::to_string(corners) + " vertices");
    }
    for (std::int64_t i = 1; i <= corners; ++i) {
      std::int64_t index = 0;
      if (!parseWhole(words[i], index) || index < 0 || index >= vertices) {
        throw InputError(path, indexDefect(f, printable(words[i]), static_cast<std::uint64_t>(vertices)));
      }
    }
  }
}

void checkObjFaces(const std::string& path, const std::string& content) {
  requirePlainText(path, content, "OBJ", true);
  Lines lines(content);
  std::string_view line;
  while (lines.next(line)) {
    if (line.size() < 2 || line[0] != 'f' || !std::isspace(static_cast<unsigned char>(line[1]))) continue;
    const std::size_t corners = wordsOf(line.substr(0, std::min(line.find('#'), line.size()))).size() - 1;
    if (corners < 3) {
      throw InputError(path, "OBJ line " + std::to_string(lines.number()) + ": a face with " + std::to_string(corners) +
                                 " vertices (at least 3 needed)");
    }
  }
}

namespace {

// ---------------------------------------------------------------------------------
// COLLADA

constexpr int kDeepestCollada = 256;

// Calls visit(element, depth) for every element, depth first, without recursion.
template <class Visitor>
void forEachElement(const pugi::xml_node& root, Visitor visit) {
  std::vector<std::pair<pugi::xml_node, int>> stack{{root, 0}};
  while (!stack.empty()) {
    const auto [node, depth] = stack.back();
    stack.pop_back();
    if (node.type() == pugi::node_element) visit(node, depth);
    for (pugi::xml_node child = node.last_child(); child; child = child.previous_sibling()) {
      stack.emplace_back(child, depth + 1);
    }
  }
}

std::size_t countWords(const char* text) {
  std::size_t count = 0;
  for (bool inWord = false; *text; ++text) {
    const bool space = std::isspace(static_cast<unsigned char>(*text));
    count += !space && !inWord;
    inWord = !space;
  }
  return count;
}

std::string elementDefect(const pugi::xml_node& element, const std::string& defect) {
  const std::string id = element.attribute("id").value();
  return "COLLADA <" + printable(element.name()) + (id.empty() ? "" : " id=\"" + printable(id) + "\"") + ">: " + defect;
}

// Nodes reachable from each node through nested nodes and <instance_node>: a cycle
// makes the import library recurse for ever.
void requireNoInstanceCycle(const std::string& path, const pugi::xml_document& document) {
  std::map<std::string, pugi::xml_node> byId;
  forEachElement(document, [&](const pugi::xml_node& element, int) {
    if (std::strcmp(element.name(), "node") == 0 && element.attribute("id")) byId[element.attribute("id").value()] = element;
  });
  // The nodes a node leads to: its nested nodes and the nodes it instances.
  const auto successors = [&](const pugi::xml_node& node) {
    std::vector<pugi::xml_node> next;
    for (const pugi::xml_node& child : node.children()) {
      if (std::strcmp(child.name(), "node") == 0) next.push_back(child);
      if (std::strcmp(child.name(), "instance_node") != 0) continue;
      const std::string url = child.attribute("url").value();
      const auto target = url.rfind('#', 0) == 0 ? byId.find(url.substr(1)) : byId.end();
      if (target != byId.end()) next.push_back(target->second);
    }
    return next;
  };
  std::map<const void*, int> state;  // 1 on the walk, 2 done
  forEachElement(document, [&](const pugi::xml_node& start, int) {
    if (std::strcmp(start.name(), "node") != 0 || state[start.internal_object()] != 0) return;
    std::vector<std::pair<pugi::xml_node, std::vector<pugi::xml_node>>> walk{{start, successors(start)}};
    state[start.internal_object()] = 1;
    while (!walk.empty()) {
      auto& [node, next] = walk.back();
      if (next.empty()) {
        state[node.internal_object()] = 2;
        walk.pop_back();
        continue;
      }
      const pugi::xml_node successor = next.back();
      next.pop_back();
      const int seen = state[successor.internal_object()];
      if (seen == 1) throw InputError(path, elementDefect(successor, "instances itself (through <instance_node>)"));
      if (seen == 0) {
        state[successor.internal_object()] = 1;
        walk.emplace_back(successor, successors(successor));
      }
    }
  });
}

// Whole numbers in [0, limit) only; false at the first other word.
bool indicesBelow(const char* text, long double limit) {
  std::istringstream words(text);
  for (std::string word; words >> word;) {
    std::int64_t value = 0;
    if (!parseWhole(word, value) || value < 0 || static_cast<long double>(value) >= limit) return false;
  }
  return true;
}

// <float_array> counts, <accessor> reach and index lists.
void requireConsistentArrays(const std::string& path, const pugi::xml_document& document) {
  std::map<std::string, std::size_t> arraySizes;
  std::size_t values = 0;
  forEachElement(document, [&](const pugi::xml_node& element, int) {
    const bool floats = std::strcmp(element.name(), "float_array") == 0;
    if (!floats && std::strcmp(element.name(), "int_array") != 0) return;
    const std::size_t words = countWords(element.child_value());
    std::int64_t count = -1;
    if (!parseWhole(element.attribute("count").value(), count) || count != static_cast<std::int64_t>(words)) {
      throw InputError(path, elementDefect(element, "count=\"" + printable(element.attribute("count").value()) +
                                                        "\" but " + std::to_string(words) + " values"));
    }
    if (element.attribute("id")) arraySizes[element.attribute("id").value()] = words;
    values += words;
  });
  forEachElement(document, [&](const pugi::xml_node& element, int) {
    const std::string name = element.name();
    if (name == "accessor") {
      const std::string source = element.attribute("source").value();
      const auto array = source.rfind('#', 0) == 0 ? arraySizes.find(source.substr(1)) : arraySizes.end();
      std::int64_t count = 0, stride = 1, offset = 0;
      const bool numbers = parseWhole(element.attribute("count").value(), count) &&
                           (!element.attribute("stride") || parseWhole(element.attribute("stride").value(), stride)) &&
                           (!element.attribute("offset") || parseWhole(element.attribute("offset").value(), offset));
      if (array == arraySizes.end()) {
        throw InputError(path, elementDefect(element, "source=\"" + printable(source) + "\" names no array of the file"));
      }
      if (!numbers || count < 0 || stride < 1 || offset < 0 ||
          static_cast<long double>(count) * stride + offset > static_cast<long double>(array->second)) {
        throw InputError(path, elementDefect(element, "reads beyond its array"));
      }
    } else if ((name == "p" || name == "v" || name == "vcount" || name == "h") &&
               !indicesBelow(element.child_value(), std::max<long double>(values, countWords(element.child_value())))) {
      throw InputError(path, elementDefect(element.parent(), "<" + name + "> holds something other than indices of "
                                                             "the file's values"));
    }
  });
}

// The values a primitive element's index lists must hold: the count of its
// primitives times the corners each takes, times the inputs' stride (the largest
// input offset plus one); <polylist> takes its corners from <vcount>, the
// one-list-per-primitive kinds count their lists.
void requireCompletePrimitives(const std::string& path, const pugi::xml_document& document) {
  forEachElement(document, [&](const pugi::xml_node& element, int) {
    const std::string name = element.name();
    const bool oneList = name == "triangles" || name == "lines" || name == "polylist";
    const bool listEach = name == "polygons" || name == "trifans" || name == "tristrips" || name == "linestrips";
    if (!oneList && !listEach) return;
    std::int64_t count = 0;
    if (!parseWhole(element.attribute("count").value(), count) || count < 0) {
      throw InputError(path, elementDefect(element, "count is not a whole number"));
    }
    if (listEach) {
      std::int64_t lists = 0;
      for (const pugi::xml_node& child : element.children()) lists += std::strcmp(child.name(), "p") == 0 || std::strcmp(child.name(), "ph") == 0;
      if (lists != count) {
        throw InputError(path, elementDefect(element, "count=\"" + std::to_string(count) + "\" but " +
                                                          std::to_string(lists) + " <p> lists"));
      }
      return;
    }
    std::int64_t stride = 1;
    for (const pugi::xml_node& input : element.children("input")) {
      std::int64_t offset = 0;
      if (input.attribute("offset") && (!parseWhole(input.attribute("offset").value(), offset) || offset < 0 || offset > 64)) {
        throw InputError(path, elementDefect(element, "an <input> offset is not a small whole number"));
      }
      stride = std::max(stride, offset + 1);
    }
    long double corners = static_cast<long double>(count) * (name == "triangles" ? 3 : 2);
    if (name == "polylist") {
      const pugi::xml_node vcount = element.child("vcount");
      std::istringstream words(vcount.child_value());
      corners = 0;
      std::int64_t polygons = 0;
      for (std::string word; words >> word; ++polygons) {
        std::int64_t size = 0;
        if (!parseWhole(word, size) || size < 1) {
          throw InputError(path, elementDefect(element, "<vcount> holds '" + printable(word) + "'"));
        }
        corners += static_cast<long double>(size);
      }
      if (!vcount || polygons != count) {
        throw InputError(path, elementDefect(element, "count=\"" + std::to_string(count) + "\" but " +
                                                          std::to_string(polygons) + " sizes in <vcount>"));
      }
    }
    const long double values = static_cast<long double>(countWords(element.child("p").child_value()));
    if (count > 0 && values != corners * static_cast<long double>(stride)) {
      std::ostringstream text;
      text << static_cast<double>(corners) << " corners of " << stride << " indices each need "
           << static_cast<double>(corners * stride) << " values in <p>, it has " << static_cast<double>(values);
      throw InputError(path, elementDefect(element, text.str()));
    }
  });
}

}  // namespace

void checkColladaFile(const std::string& path, const std::string& content) {
  // XML allows no other control characters; the import library looped for ever on a
  // vertical tab between indices.
  requirePlainText(path, content, "COLLADA", false);
  pugi::xml_document document;
  const pugi::xml_parse_result parsed = document.load_buffer(content.data(), content.size());
  if (!parsed) {
    throw InputError(path, "COLLADA file is not well-formed XML at byte " + std::to_string(parsed.offset) + ": " +
                               parsed.description());
  }
  forEachElement(document, [&](const pugi::xml_node& element, int depth) {
    if (depth > kDeepestCollada) {
      throw InputError(path, "COLLADA elements nested deeper than " + std::to_string(kDeepestCollada) + " (<" +
                                 printable(element.name()) + ">)");
    }
  });
  requireNoInstanceCycle(path, document);
  requireConsistentArrays(path, document);
  requireCompletePrimitives(path, document);
}

}  // namespace freespace::detail
