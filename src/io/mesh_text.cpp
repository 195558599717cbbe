#include "mesh_text.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>

#include "freespace/input_error.h"

namespace freespace::detail {

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

}  // namespace freespace::detail
