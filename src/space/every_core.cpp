#include "every_core.h"

#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <system_error>
#include <thread>

#include <unistd.h>

namespace freespace {

unsigned coreCount() {
  static const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  return cores;
}

namespace {

/// Whether this thread is one of the helpers, or is running a call that has them.
thread_local bool onHelper = false, inCall = false;

/// Runs `run`; the exception it threw, if any.
std::exception_ptr failureOf(const std::function<void()>& run) {
  try {
    run();
  } catch (...) {
    return std::current_exception();
  }
  return nullptr;
}

/// The helper threads. A call hands them `run` and a new round number; each helper
/// runs it once per round and counts itself out; the call waits for the count.
class Helpers {
 public:
  Helpers() {
    for (unsigned helper = 1; helper < coreCount(); ++helper) {
      try {
        std::thread([this] { serve(); }).detach();
        ++threads_;
      } catch (const std::system_error&) {
        break;  // no more threads to be had: those started and the caller do it all
      }
    }
  }
  Helpers(const Helpers&) = delete;
  Helpers& operator=(const Helpers&) = delete;

  /// Runs `run` on every helper and here, or here alone when another call holds the
  /// helpers; rethrows the first exception.
  void runEverywhere(const std::function<void()>& run) {
    std::unique_lock call(calling_, std::try_to_lock);
    // (A forked child has none of the helpers.)
    if (!call.owns_lock() || threads_ == 0 || getpid() != process_) {
      run();
      return;
    }
    inCall = true;
    {
      const std::lock_guard lock(mutex_);
      run_ = &run;
      failure_ = nullptr;
      running_ = threads_;
      ++round_;
    }
    wake_.notify_all();
    const std::exception_ptr mine = failureOf(run);
    std::unique_lock lock(mutex_);
    finished_.wait(lock, [&] { return running_ == 0; });
    run_ = nullptr;
    inCall = false;
    if (mine) std::rethrow_exception(mine);
    if (failure_) std::rethrow_exception(failure_);
  }

 private:
  void serve() {
    onHelper = true;
    std::uint64_t seen = 0;
    std::unique_lock lock(mutex_);
    for (;;) {
      wake_.wait(lock, [&] { return round_ != seen; });
      seen = round_;
      const std::function<void()>& run = *run_;
      lock.unlock();
      const std::exception_ptr failure = failureOf(run);
      lock.lock();
      if (failure && !failure_) failure_ = failure;
      if (--running_ == 0) finished_.notify_all();
    }
  }

  std::mutex calling_;  // held by the call that has the helpers
  std::mutex mutex_;    // guards what follows
  std::condition_variable wake_, finished_;
  const std::function<void()>* run_ = nullptr;
  std::uint64_t round_ = 0;
  std::size_t running_ = 0;
  std::exception_ptr failure_;
  std::size_t threads_ = 0;
  const pid_t process_ = getpid();
};

}  // namespace

void onEveryThread(const std::function<void()>& run) {
  if (onHelper || inCall) {
    run();
    return;
  }
  // Never destroyed: the process's end stops the helpers (joining them at exit would
  // throw if a helper itself ended the process, and a call during static destruction
  // would find them gone).
  static Helpers& helpers = *new Helpers;
  helpers.runEverywhere(run);
}

}  // namespace freespace
