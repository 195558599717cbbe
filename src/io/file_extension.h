#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace freespace::detail {

/// The extension of `path` in lower case, with its dot (".obj"), or "" for none.
inline std::string lowercaseExtension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

}  // namespace freespace::detail
