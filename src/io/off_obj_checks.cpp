// The checks of OFF and OBJ files before import (mesh_file_checks.h).
#include "mesh_file_checks.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <string_view>
#include <vector>

#include "freespace/input_error.h"
#include "mesh_text.h"

namespace freespace::detail {

ImportText checkOffFile(const std::string& path, const std::string& content) {
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
  // The same records as OFF and as OBJ text: the import library reads one of them.
  std::string offText = "OFF\n" + std::to_string(vertices) + " " + std::to_string(faces) + " 0\n", objText;
  std::int64_t largestFace = 0;
  for (std::int64_t v = 0; v < vertices; ++v) {
    double coordinate = 0;
    if (!nextWords()) throw InputError(path, "OFF file is truncated: vertex " + std::to_string(v) + " is missing");
    if (words.size() < 3 || !parseNumber(words[0], coordinate) || !parseNumber(words[1], coordinate) ||
        !parseNumber(words[2], coordinate)) {
      throw InputError(path, "OFF line " + std::to_string(lines.number()) + ": vertex " + std::to_string(v) +
                                 " is not three numbers");
    }
    const std::string coordinates =
        std::string(words[0]).append(" ").append(words[1]).append(" ").append(words[2]).append("\n");
    offText += coordinates;
    objText.append("v ").append(coordinates);
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
    largestFace = std::max(largestFace, corners);
    offText.append(std::to_string(corners));
    objText.append("f");
    for (std::int64_t i = 1; i <= corners; ++i) {
      std::int64_t index = 0;
      if (!parseWhole(words[i], index) || index < 0 || index >= vertices) {
        throw InputError(path, indexDefect(f, printable(words[i]), static_cast<std::uint64_t>(vertices)));
      }
      offText.append(" ").append(std::to_string(index));
      objText.append(" ").append(std::to_string(index + 1));
    }
    offText.append("\n");
    objText.append("\n");
  }
  if (largestFace > kLargestOffFaceImported) return {std::move(objText), "obj"};
  return {std::move(offText), "off"};
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

}  // namespace freespace::detail
