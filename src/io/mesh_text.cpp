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

namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }

// How many digits `word` holds from `at` on, which is moved past them.
std::size_t skipDigits(std::string_view word, std::size_t& at) {
  const std::size_t start = at;
  while (at < word.size() && isDigit(word[at])) ++at;
  return at - start;
}

bool equalsIgnoringCase(std::string_view word, std::string_view expected) {
  return word.size() == expected.size() &&
         std::equal(word.begin(), word.end(), expected.begin(),
                    [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == b; });
}

// The decimal syntax the import library reads (and inf, infinity or nan): an optional
// sign, digits with an optional point (at least one digit), an optional exponent. Forms
// only strtod knows (hexadecimal, "nan(...)") would be read as other numbers than ours.
bool isDecimal(std::string_view word) {
  std::size_t at = word.empty() || (word[0] != '-' && word[0] != '+') ? 0 : 1;
  const std::string_view rest = word.substr(at);
  if (equalsIgnoringCase(rest, "inf") || equalsIgnoringCase(rest, "infinity") || equalsIgnoringCase(rest, "nan")) {
    return true;
  }
  std::size_t digits = skipDigits(word, at);
  if (at < word.size() && word[at] == '.') digits += skipDigits(word, ++at);
  if (digits == 0) return false;
  if (at < word.size() && (word[at] == 'e' || word[at] == 'E')) {
    ++at;
    if (at < word.size() && (word[at] == '-' || word[at] == '+')) ++at;
    if (skipDigits(word, at) == 0) return false;
  }
  return at == word.size();
}

}  // namespace

bool parseNumber(std::string_view word, double& value) {
  if (!isDecimal(word)) return false;
  const std::string text(word);
  value = std::strtod(text.c_str(), nullptr);
  return true;
}

bool parseWhole(std::string_view word, std::int64_t& value) {
  // Digits with an optional minus sign only: the import library reads "+3" as 0.
  std::size_t at = !word.empty() && word[0] == '-' ? 1 : 0;
  if (skipDigits(word, at) == 0 || at != word.size()) return false;
  const std::string text(word);
  errno = 0;
  value = std::strtoll(text.c_str(), nullptr, 10);
  return errno == 0;
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
