#pragma once

// Reading the text of mesh files for the checks before import (mesh_file_checks.h):
// words, numbers, lines, and the messages the checks share.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace freespace::detail {

/// Splits a line into whitespace-separated words.
std::vector<std::string_view> wordsOf(std::string_view line);

/// Whether the whole word is a number in the decimal syntax the import library reads
/// (or inf, infinity, nan), and its value.
bool parseNumber(std::string_view word, double& value);

/// Whether the whole word is a whole number within 64 bits (digits, an optional minus
/// sign), and its value.
bool parseWhole(std::string_view word, std::int64_t& value);

/// The lines of a text, one at a time, with their numbers (from 1).
class Lines {
 public:
  explicit Lines(std::string_view text) : text_(text) {}
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
  std::size_t at_ = 0;
  std::size_t number_ = 0;
};

/// Text formats hold no control characters but tabs and line ends: the import
/// library reads a NUL byte as the end of a line, and its counts then disagree with
/// ours. In formats of lines (`ofLines`), a carriage return ends a line only before
/// a line feed (the import library ends a line at any, the checks would not: a
/// record would be split in two). Throws InputError naming `path` and `format`.
void requirePlainText(const std::string& path, std::string_view text, const std::string& format, bool ofLines);

/// Text from a file as a message may quote it: at most 80 bytes, those that are not
/// printable ASCII as '?'.
std::string printable(std::string_view text);

/// "face F has N vertices (at least 3 needed)".
std::string faceDefect(std::size_t face, std::int64_t corners);

/// "face F uses vertex I of N (out of range)".
std::string indexDefect(std::size_t face, const std::string& index, std::uint64_t vertices);

}  // namespace freespace::detail
