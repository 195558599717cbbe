#pragma once

#include <cstddef>
#include <string>

namespace freespace {

/// A user's regular file mapped read-only into memory: its bytes are read in place,
/// from the system's file cache, without a copy into fresh memory (a saved free space
/// is hundreds of megabytes). A file that cannot be opened or mapped is an
/// InputError naming the path and the reason, as openInputFile gives.
class MappedInputFile {
 public:
  explicit MappedInputFile(const std::string& path);
  ~MappedInputFile();
  MappedInputFile(const MappedInputFile&) = delete;
  MappedInputFile& operator=(const MappedInputFile&) = delete;

  const char* data() const { return data_; }
  std::size_t size() const { return size_; }

 private:
  const char* data_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace freespace
