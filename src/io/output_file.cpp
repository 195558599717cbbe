#include "freespace/io/output_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "freespace/input_error.h"

namespace freespace {

namespace {

// Temporary files being written, for removePendingOutputs. A slot is claimed (1),
// then its path is filled in and it is published (2); handlers remove published ones.
struct PendingSlot {
  std::atomic<int> state{0};
  std::array<char, 4096> path{};
};
std::array<PendingSlot, 8> pendingSlots;

std::string reason(int error) { return std::generic_category().message(error); }

mode_t currentUmask() {
  static const mode_t mask = [] {
    const mode_t current = ::umask(0);
    ::umask(current);
    return current;
  }();
  return mask;
}

// A temporary file next to `target`, of a unique name, removed unless committed.
class TemporaryFile {
 public:
  explicit TemporaryFile(const std::string& target) : target_(target) {
    const std::filesystem::path targetPath(target);
    std::string pattern = (targetPath.parent_path() / ("." + targetPath.filename().string() + ".XXXXXX")).string();
    const int descriptor = ::mkstemp(pattern.data());
    if (descriptor < 0) throw InputError(target, "cannot write: " + reason(errno));
    ::fchmod(descriptor, 0666 & ~currentUmask());  // as a file the program created itself
    ::close(descriptor);
    path_ = pattern;
    publish();
  }
  ~TemporaryFile() {
    if (!committed_) ::unlink(path_.c_str());
    unpublish();
  }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  const std::string& path() const { return path_; }

  // Moves the file to the target: replacing it if `overwrite`, else only if there is
  // none (decided by the kernel, so two writers never both succeed).
  void commit(bool overwrite) {
    const int moved = overwrite ? ::rename(path_.c_str(), target_.c_str()) : renameUnlessTaken();
    if (moved != 0 && errno == EEXIST) throw InputError(target_, "already exists (not overwritten)");
    if (moved != 0) throw InputError(target_, "cannot write: " + reason(errno));
    committed_ = true;
  }

 private:
  void publish() {
    for (PendingSlot& slot : pendingSlots) {
      int free = 0;
      if (path_.size() >= slot.path.size() || !slot.state.compare_exchange_strong(free, 1)) continue;
      std::memcpy(slot.path.data(), path_.c_str(), path_.size() + 1);
      slot.state = 2;
      slot_ = &slot;
      return;
    }
  }
  void unpublish() {
    if (slot_) slot_->state = 0;
  }

  // rename() that fails with EEXIST if the target exists; a file system without
  // RENAME_NOREPLACE gets a hard link instead (also atomic), then the name removed.
  int renameUnlessTaken() const {
    if (::renameat2(AT_FDCWD, path_.c_str(), AT_FDCWD, target_.c_str(), RENAME_NOREPLACE) == 0) return 0;
    if (errno != EINVAL && errno != ENOSYS) return -1;
    if (::link(path_.c_str(), target_.c_str()) != 0) return -1;
    ::unlink(path_.c_str());
    return 0;
  }

  std::string target_;
  std::string path_;
  PendingSlot* slot_ = nullptr;
  bool committed_ = false;
};

// Writes through `write` into `path`, opened for writing as it is; every write checked.
void writeChecked(const std::string& path, const std::string& name, std::ios::openmode mode,
                  const std::function<void(std::ostream&)>& write) {
  std::ofstream out(path, mode);
  if (!out) throw InputError(name, "cannot write: " + reason(errno));
  errno = 0;
  write(out);
  out.flush();
  const int afterWrite = errno;
  out.close();
  if (!out) throw InputError(name, "cannot write: " + (afterWrite != 0 ? reason(afterWrite) : reason(errno)));
}

}  // namespace

bool checkOutputPath(const std::string& path, bool overwrite) {
  if (path.empty()) throw InputError(path, "cannot write: no file name");
  struct stat existing {};
  if (::stat(path.c_str(), &existing) != 0) return true;
  if (S_ISDIR(existing.st_mode)) throw InputError(path, "cannot write: is a folder");
  if (!S_ISREG(existing.st_mode)) return false;
  if (!overwrite) throw InputError(path, "already exists (not overwritten)");
  return true;
}

void writeFile(const std::string& path, bool overwrite, const std::function<void(std::ostream&)>& write) {
  if (!checkOutputPath(path, overwrite)) {
    writeChecked(path, path, std::ios::binary | std::ios::out, write);  // a device or a pipe
    return;
  }
  TemporaryFile temporary(path);
  writeChecked(temporary.path(), path, std::ios::binary | std::ios::trunc, write);
  temporary.commit(overwrite);
}

void removePendingOutputs() noexcept {
  for (PendingSlot& slot : pendingSlots) {
    if (slot.state.load() == 2) ::unlink(slot.path.data());
  }
}

}  // namespace freespace
