#pragma once

// Work spread over the machine's cores (docs/design.md section 7, threads).

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>

namespace freespace {

/// The machine's cores (at least 1), asked of the system once (it reads a file each
/// time).
unsigned coreCount();

/// Runs `run` on each of the process's helper threads (one fewer than the cores,
/// started on the first call and kept until the process ends: a query calls this
/// hundreds of times, and a new thread each time cost its start and a fresh memory
/// heap; a forked child runs on its own thread) and on the caller's, and
/// returns once all have returned; the first exception any threw is thrown again
/// here. Called from a helper, or while another call runs, `run` runs on the caller's
/// thread alone.
void onEveryThread(const std::function<void()>& run);

/// Runs work(k) for k = 0 to count - 1 on every core (the caller's among them), k
/// handed out in order, each while keepGoing() says so; an exception thrown by work
/// stops them all and is thrown again here.
template <class Work>
void onEveryCore(std::size_t count, const std::function<bool()>& keepGoing, const Work& work) {
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  onEveryThread([&] {
    try {
      for (std::size_t k = next++; k < count && !failed && keepGoing(); k = next++) work(k);
    } catch (...) {
      failed = true;
      throw;
    }
  });
}

}  // namespace freespace
