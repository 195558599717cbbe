#include "every_core.h"

#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace freespace {

unsigned coreCount() {
  static const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  return cores;
}

namespace {

/// Whether this thread is one of the helpers.
thread_local bool onHelper = false;

/// The helper threads. A call hands them `run` and a new round number; each helper
/// runs it once per round and counts itself out; the call waits for the count.
class Helpers {
 public:
  Helpers() {
    for (unsigned helper = 1; helper < coreCount(); ++helper) {
      try {
        threads_.emplace_back([this] { serve(); });
      } catch (const std::system_error&) {
        break;  // no more threads to be had: those started and the caller do it all
      }
    }
  }
  ~Helpers() {
    {
      const std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_all();
    for (std::thread& thread : threads_) thread.join();
  }
  Helpers(const Helpers&) = delete;
  Helpers& operator=(const Helpers&) = delete;

  /// Runs `run` on every helper and here, or here alone when another call holds the
  /// helpers; rethrows the first exception.
  void runEverywhere(const std::function<void()>& run) {
    std::unique_lock call(calling_, std::try_to_lock);
    if (!call.owns_lock() || threads_.empty()) {
      run();
      return;
    }
    {
      const std::lock_guard lock(mutex_);
      run_ = &run;
      failure_ = nullptr;
      running_ = threads_.size();
      ++round_;
    }
    wake_.notify_all();
    std::exception_ptr mine;
    try {
      run();
    } catch (...) {
      mine = std::current_exception();
    }
    std::unique_lock lock(mutex_);
    finished_.wait(lock, [&] { return running_ == 0; });
    run_ = nullptr;
    if (mine) std::rethrow_exception(mine);
    if (failure_) std::rethrow_exception(failure_);
  }

 private:
  void serve() {
    onHelper = true;
    std::uint64_t seen = 0;
    std::unique_lock lock(mutex_);
    for (;;) {
      wake_.wait(lock, [&] { return stopping_ || round_ != seen; });
      if (stopping_) return;
      seen = round_;
      const std::function<void()>& run = *run_;
      lock.unlock();
      std::exception_ptr failure;
      try {
        run();
      } catch (...) {
        failure = std::current_exception();
      }
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
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace

void onEveryThread(const std::function<void()>& run) {
  if (onHelper) {
    run();
    return;
  }
  static Helpers helpers;
  helpers.runEverywhere(run);
}

}  // namespace freespace
