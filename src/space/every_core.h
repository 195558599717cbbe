#pragma once

// Work spread over the machine's cores (docs/design.md section 7, threads).

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <functional>
#include <future>
#include <system_error>
#include <thread>
#include <vector>

namespace freespace {

/// The machine's cores (at least 1), asked of the system once (it reads a file each
/// time).
inline unsigned coreCount() {
  static const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  return cores;
}

/// Runs work(k) for k = 0 to count - 1 on every core (a thread each, the caller's
/// among them), k handed out in order, each while keepGoing() says so; an exception
/// thrown by work stops them all and is thrown again here.
template <class Work>
void onEveryCore(std::size_t count, const std::function<bool()>& keepGoing, const Work& work) {
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  const auto run = [&] {
    try {
      for (std::size_t k = next++; k < count && !failed && keepGoing(); k = next++) work(k);
    } catch (...) {
      failed = true;
      throw;
    }
  };
  std::vector<std::future<void>> helpers;
  const std::size_t threads = std::min<std::size_t>(count, coreCount());
  try {
    for (std::size_t helper = 1; helper < threads; ++helper) helpers.push_back(std::async(std::launch::async, run));
  } catch (const std::system_error&) {
    // No more threads to be had: those started and this one do it all.
  }
  run();
  for (std::future<void>& helper : helpers) helper.get();
}

}  // namespace freespace
