#include "mapped_input_file.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>

#include "freespace/input_error.h"
#include "regular_file.h"

namespace freespace {

namespace {

/// Closes the descriptor when the mapping is made or fails (the mapping outlives it).
class Descriptor {
 public:
  explicit Descriptor(int fd) : fd_(fd) {}
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

}  // namespace

MappedInputFile::MappedInputFile(const std::string& path) {
  // O_NONBLOCK: opening a FIFO must not wait for a writer before it is refused below.
  const Descriptor file(::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK));
  if (file.get() < 0) throwCannotOpen(path, errno);
  struct stat info {};
  if (::fstat(file.get(), &info) != 0) throwCannotOpen(path, errno);
  requireRegularFile(path, info);
  size_ = static_cast<std::size_t>(info.st_size);
  if (size_ == 0) return;  // nothing to map
  void* mapped = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE | MAP_POPULATE, file.get(), 0);
  if (mapped == MAP_FAILED) throw InputError(path, "cannot read file: " + std::generic_category().message(errno));
  data_ = static_cast<const char*>(mapped);
}

MappedInputFile::~MappedInputFile() {
  if (data_ != nullptr) ::munmap(const_cast<char*>(data_), size_);
}

}  // namespace freespace
