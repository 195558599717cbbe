#include "vtk_reader.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdlib>
#include <iterator>
#include <limits>
#include <optional>
#include <string_view>
#include <vector>

#include "freespace/input_error.h"

namespace freespace {
namespace {

using Index = std::uint32_t;

constexpr std::string_view kWhitespace = " \t\r\f\v";

std::string uppercase(std::string_view text) {
  std::string result(text);
  std::transform(result.begin(), result.end(), result.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return result;
}

std::string_view trimmed(std::string_view text) {
  const std::size_t start = text.find_first_not_of(kWhitespace);
  if (start == std::string_view::npos) return {};
  return text.substr(start, text.find_last_not_of(kWhitespace) - start + 1);
}

std::vector<std::string_view> splitLines(std::string_view content) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (start < content.size()) {
    std::size_t end = content.find('\n', start);
    if (end == std::string_view::npos) end = content.size();
    lines.push_back(content.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

bool isKnownDataType(std::string_view type) {
  static const char* const kTypes[] = {
      "BIT",  "UNSIGNED_CHAR", "CHAR",  "UNSIGNED_SHORT", "SHORT",        "UNSIGNED_INT",
      "INT",  "UNSIGNED_LONG", "LONG",  "FLOAT",          "DOUBLE",       "VTKTYPEINT64",
      "VTKTYPEUINT64", "VTKIDTYPE"};
  const std::string wanted = uppercase(type);
  return std::any_of(std::begin(kTypes), std::end(kTypes),
                     [&](const char* known) { return wanted == known; });
}

struct Token {
  std::string_view text;
  std::size_t line;  // 1-based
};

// Whitespace-separated tokens of a range of lines.
class TokenReader {
 public:
  TokenReader(const std::vector<std::string_view>& lines, std::size_t firstLineIndex)
      : lines_(lines), lineIndex_(firstLineIndex) {}

  std::optional<Token> next() { return findToken(lineIndex_, column_); }

  std::optional<Token> peek() const {
    std::size_t line = lineIndex_;
    std::size_t column = column_;
    return findToken(line, column);
  }

  // Continues after the next blank line (a METADATA block ends with one).
  void skipPastBlankLine() {
    ++lineIndex_;
    while (lineIndex_ < lines_.size() && !trimmed(lines_[lineIndex_]).empty()) ++lineIndex_;
    ++lineIndex_;
    column_ = 0;
  }

 private:
  // The token at or after (line, column), which are moved past it.
  std::optional<Token> findToken(std::size_t& line, std::size_t& column) const {
    for (; line < lines_.size(); ++line, column = 0) {
      const std::string_view text = lines_[line];
      const std::size_t start = text.find_first_not_of(kWhitespace, column);
      if (start == std::string_view::npos) continue;
      const std::size_t end = std::min(text.find_first_of(kWhitespace, start), text.size());
      column = end;
      return Token{text.substr(start, end - start), line + 1};
    }
    return std::nullopt;
  }

  const std::vector<std::string_view>& lines_;
  std::size_t lineIndex_;
  std::size_t column_ = 0;
};

// How a cell section's cells become triangles.
struct CellKind {
  const char* plural;           // in messages: "expected 6 polygons"
  std::size_t minimumPoints;    // smaller cells are an error
};

// Cell c has the point indices connectivity[offsets[c] .. offsets[c + 1]).
struct CellArray {
  std::vector<std::size_t> offsets{0};
  std::vector<Index> connectivity;
};

class LegacyVtkParser {
 public:
  LegacyVtkParser(const std::string& path, const std::string& content)
      : path_(path), lines_(splitLines(content)), tokens_(lines_, 3) {}

  TriangleSoup parse() {
    readHeader();
    readDatasetType();
    while (const std::optional<Token> keyword = tokens_.next()) {
      if (!readSection(*keyword)) break;
    }
    return std::move(soup_);
  }

 private:
  [[noreturn]] void fail(std::size_t line, const std::string& problem) const {
    throw InputError(path_, "line " + std::to_string(line) + ": " + problem);
  }

  void readHeader() const {
    const std::string_view identification = lines_.empty() ? "" : lines_[0];
    if (uppercase(identification.substr(0, 14)) != "# VTK DATAFILE") {
      throw InputError(path_,
                       "not a legacy VTK file: line 1 must be '# vtk DataFile Version x.y'");
    }
    if (lines_.size() < 3) {
      fail(lines_.size(), "file ended before line 3, which must say ASCII or BINARY");
    }
    const std::string encoding = uppercase(trimmed(lines_[2]));
    if (encoding == "BINARY") throw InputError(path_, "binary VTK is not supported");
    if (encoding != "ASCII") {
      fail(3, "expected ASCII or BINARY, found '" + std::string(trimmed(lines_[2])) + "'");
    }
  }

  void readDatasetType() {
    const std::optional<Token> keyword = tokens_.next();
    if (!keyword) fail(lines_.size(), "file ended before the DATASET line");
    if (uppercase(keyword->text) != "DATASET") {
      fail(keyword->line, "expected DATASET, found '" + std::string(keyword->text) + "'");
    }
    const Token type = nextToken(*keyword, "a dataset type");
    if (uppercase(type.text) != "POLYDATA") {
      fail(type.line, "not a POLYDATA dataset (found " + std::string(type.text) + ")");
    }
  }

  // Reads the section that `keyword` starts; false when the geometry is over.
  bool readSection(const Token& keyword) {
    const std::string name = uppercase(keyword.text);
    if (name == "POINTS") {
      readPoints(keyword);
    } else if (name == "POLYGONS") {
      addPolygons(readCells(keyword, {"polygons", 3}));
    } else if (name == "TRIANGLE_STRIPS") {
      addTriangleStrips(readCells(keyword, {"triangle strips", 3}));
    } else if (name == "VERTICES") {
      readCells(keyword, {"vertex cells", 1});
    } else if (name == "LINES") {
      readCells(keyword, {"line cells", 1});
    } else if (name == "METADATA") {
      tokens_.skipPastBlankLine();
    } else if (name == "FIELD") {
      skipField(keyword);
    } else if (name == "POINT_DATA" || name == "CELL_DATA") {
      return false;
    } else {
      fail(keyword.line, "unexpected '" + std::string(keyword.text) +
                             "' (expected POINTS, POLYGONS, TRIANGLE_STRIPS, VERTICES, LINES, "
                             "FIELD, METADATA, POINT_DATA or CELL_DATA)");
    }
    return true;
  }

  Token nextToken(const Token& section, const std::string& expected) {
    const std::optional<Token> token = tokens_.next();
    if (!token) fail(section.line, "expected " + expected + ", but the file ended");
    return *token;
  }

  std::size_t parseCount(const Token& token, const std::string& expected) const {
    std::size_t value = 0;
    const char* end = token.text.data() + token.text.size();
    const auto result = std::from_chars(token.text.data(), end, value);
    if (result.ec != std::errc() || result.ptr != end) {
      fail(token.line, "expected " + expected + ", found '" + std::string(token.text) + "'");
    }
    return value;
  }

  std::size_t readCount(const Token& section, const std::string& expected) {
    return parseCount(nextToken(section, expected), expected);
  }

  // Full double precision; "nan" and "inf" are numbers too (validation rejects them).
  double parseNumber(const Token& token) const {
    const std::string text(token.text);
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size()) {
      fail(token.line, "expected a number, found '" + text + "'");
    }
    return value;
  }

  Index parsePointIndex(const Token& token) const {
    const std::size_t index = parseCount(token, "a point index");
    if (index >= soup_.vertices.size()) {
      fail(token.line, "point index " + std::to_string(index) + " out of range (" +
                           std::to_string(soup_.vertices.size()) + " points)");
    }
    return static_cast<Index>(index);
  }

  void readDataType(const Token& section) {
    const Token type = nextToken(section, "a data type");
    if (!isKnownDataType(type.text)) {
      fail(type.line, "unknown data type '" + std::string(type.text) + "'");
    }
  }

  void readPoints(const Token& section) {
    if (havePoints_) fail(section.line, "a second POINTS section");
    havePoints_ = true;
    const std::size_t count = readCount(section, "the number of points");
    if (count > std::numeric_limits<Index>::max()) fail(section.line, "too many points");
    readDataType(section);
    const std::size_t coordinateCount = 3 * count;
    double coordinates[3];
    for (std::size_t read = 0; read < coordinateCount; ++read) {
      const std::optional<Token> token = tokens_.next();
      if (!token) {
        fail(section.line, "expected " + std::to_string(coordinateCount) +
                               " point coordinates, file ended after " + std::to_string(read));
      }
      coordinates[read % 3] = parseNumber(*token);
      if (read % 3 == 2) soup_.vertices.emplace_back(coordinates[0], coordinates[1], coordinates[2]);
    }
  }

  CellArray readCells(const Token& section, const CellKind& kind) {
    if (!havePoints_) {
      fail(section.line, std::string(section.text) + " before POINTS (point indices need them)");
    }
    const std::size_t first = readCount(section, "the number of " + std::string(kind.plural));
    const std::size_t second = readCount(section, "the size of the " + std::string(section.text) + " section");
    const std::optional<Token> following = tokens_.peek();
    if (following && uppercase(following->text) == "OFFSETS") {
      return readOffsetsAndConnectivity(section, kind, first, second);
    }
    return readCellRecords(section, kind, first, second);
  }

  // Classic layout: `cellCount` records "k i0 ... ik-1", `size` numbers in all.
  CellArray readCellRecords(const Token& section, const CellKind& kind, std::size_t cellCount,
                            std::size_t size) {
    CellArray cells;
    std::size_t numbersRead = 0;
    for (std::size_t cell = 0; cell < cellCount; ++cell) {
      const auto nextInCell = [&]() {
        const std::optional<Token> token = tokens_.next();
        if (!token) {
          fail(section.line, "expected " + std::to_string(cellCount) + " " + kind.plural +
                                 ", file ended after " + std::to_string(cell));
        }
        ++numbersRead;
        return *token;
      };
      const Token sizeToken = nextInCell();
      const std::size_t pointCount = parseCount(sizeToken, "a point count");
      requireCellSize(sizeToken.line, kind, pointCount);
      for (std::size_t i = 0; i < pointCount; ++i) {
        cells.connectivity.push_back(parsePointIndex(nextInCell()));
      }
      cells.offsets.push_back(cells.connectivity.size());
    }
    if (numbersRead != size) {
      fail(section.line, std::string(section.text) + " announces " + std::to_string(size) +
                             " numbers, but its " + std::to_string(cellCount) + " " +
                             kind.plural + " hold " + std::to_string(numbersRead));
    }
    return cells;
  }

  // Version 5 layout: "OFFSETS type" with `offsetCount` offsets (one more than the
  // cells), then "CONNECTIVITY type" with `connectivityCount` point indices.
  CellArray readOffsetsAndConnectivity(const Token& section, const CellKind& kind,
                                       std::size_t offsetCount, std::size_t connectivityCount) {
    expectKeyword(section, "OFFSETS");
    readDataType(section);
    CellArray cells;
    cells.offsets.clear();
    for (std::size_t i = 0; i < offsetCount; ++i) {
      const Token token = nextListToken(section, offsetCount, "offsets", i);
      const std::size_t offset = parseCount(token, "an offset");
      const std::size_t previous = cells.offsets.empty() ? 0 : cells.offsets.back();
      if (offset < previous || (i == 0 && offset != 0) || offset > connectivityCount) {
        fail(token.line, "offset " + std::to_string(offset) +
                             " is out of order (offsets start at 0, never decrease and end at " +
                             std::to_string(connectivityCount) + ")");
      }
      if (i > 0) requireCellSize(token.line, kind, offset - previous);
      cells.offsets.push_back(offset);
    }
    if (cells.offsets.empty()) cells.offsets.push_back(0);
    if (cells.offsets.back() != connectivityCount) {
      fail(section.line, "the last offset must be the connectivity size " +
                             std::to_string(connectivityCount));
    }
    expectKeyword(section, "CONNECTIVITY");
    readDataType(section);
    for (std::size_t i = 0; i < connectivityCount; ++i) {
      const Token token = nextListToken(section, connectivityCount, "point indices", i);
      cells.connectivity.push_back(parsePointIndex(token));
    }
    return cells;
  }

  Token nextListToken(const Token& section, std::size_t expectedCount, const std::string& what,
                      std::size_t read) {
    const std::optional<Token> token = tokens_.next();
    if (!token) {
      fail(section.line, "expected " + std::to_string(expectedCount) + " " + what +
                             ", file ended after " + std::to_string(read));
    }
    return *token;
  }

  void expectKeyword(const Token& section, const std::string& keyword) {
    const Token token = nextToken(section, keyword);
    if (uppercase(token.text) != keyword) {
      fail(token.line, "expected " + keyword + ", found '" + std::string(token.text) + "'");
    }
  }

  void requireCellSize(std::size_t line, const CellKind& kind, std::size_t pointCount) const {
    if (pointCount < kind.minimumPoints) {
      fail(line, std::string(kind.plural) + " need at least " + std::to_string(kind.minimumPoints) +
                     " points, found one with " + std::to_string(pointCount));
    }
  }

  // FIELD name arrayCount, then per array "name components tuples type" and its
  // values; a METADATA block may follow an array.
  void skipField(const Token& section) {
    nextToken(section, "a field name");
    const std::size_t arrayCount = readCount(section, "the number of field arrays");
    std::size_t arraysSkipped = 0;
    while (arraysSkipped < arrayCount) {
      const Token name = nextToken(section, "a field array");
      if (uppercase(name.text) == "METADATA") {
        tokens_.skipPastBlankLine();
        continue;
      }
      ++arraysSkipped;
      const std::size_t components = readCount(name, "the number of components");
      const std::size_t tuples = readCount(name, "the number of tuples");
      readDataType(name);
      const std::size_t valueCount = components * tuples;
      for (std::size_t i = 0; i < valueCount; ++i) {
        nextListToken(name, valueCount, "values of field array " + std::string(name.text), i);
      }
    }
  }

  void addPolygons(const CellArray& cells) {
    for (std::size_t cell = 0; cell + 1 < cells.offsets.size(); ++cell) {
      const Index* points = cells.connectivity.data() + cells.offsets[cell];
      const std::size_t count = cells.offsets[cell + 1] - cells.offsets[cell];
      for (std::size_t i = 1; i + 1 < count; ++i) {
        soup_.triangles.push_back({points[0], points[i], points[i + 1]});
      }
    }
  }

  // Strip triangle i is (i, i+1, i+2), with its first two points swapped when i is
  // odd so that all triangles share the first one's orientation.
  void addTriangleStrips(const CellArray& cells) {
    for (std::size_t cell = 0; cell + 1 < cells.offsets.size(); ++cell) {
      const Index* points = cells.connectivity.data() + cells.offsets[cell];
      const std::size_t count = cells.offsets[cell + 1] - cells.offsets[cell];
      for (std::size_t i = 0; i + 2 < count; ++i) {
        if (i % 2 == 0) {
          soup_.triangles.push_back({points[i], points[i + 1], points[i + 2]});
        } else {
          soup_.triangles.push_back({points[i + 1], points[i], points[i + 2]});
        }
      }
    }
  }

  const std::string& path_;
  const std::vector<std::string_view> lines_;
  TokenReader tokens_;
  TriangleSoup soup_;
  bool havePoints_ = false;
};

}  // namespace

TriangleSoup readLegacyVtk(const std::string& path, const std::string& content) {
  return LegacyVtkParser(path, content).parse();
}

}  // namespace freespace
