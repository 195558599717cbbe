// Work on every core (src/space/every_core.h): the helper threads are kept between
// calls, so each call must run every item once, give back the first exception, and
// leave the helpers ready for the next; calls from inside work, and calls from
// several threads at once, run on the caller's thread.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "space/every_core.h"

namespace freespace {
namespace {

const auto always = [] { return true; };

TEST(EveryCore, EachItemRunsOnceCallAfterCall) {
  for (const std::size_t count : {0u, 1u, 2u, 7u, 1000u}) {
    for (int call = 0; call < 50; ++call) {
      std::vector<std::atomic<int>> runs(count);
      onEveryCore(count, always, [&](std::size_t k) { ++runs[k]; });
      for (std::size_t k = 0; k < count; ++k) ASSERT_EQ(runs[k], 1) << "item " << k << " of " << count;
    }
  }
}

TEST(EveryCore, UsesMoreThanOneThreadWhereThereAreCores) {
  if (coreCount() < 2) GTEST_SKIP() << "one core";
  std::set<std::thread::id> threads;
  std::mutex mutex;
  // Items slow enough that the helpers take some.
  onEveryCore(200, always, [&](std::size_t) {
    std::this_thread::sleep_for(std::chrono::microseconds(200));
    const std::lock_guard lock(mutex);
    threads.insert(std::this_thread::get_id());
  });
  EXPECT_GE(threads.size(), 2u);
}

TEST(EveryCore, AnExceptionStopsTheWorkAndIsThrownAgainThenTheNextCallRuns) {
  std::atomic<int> ran{0};
  EXPECT_THROW(onEveryCore(100000, always,
                           [&](std::size_t k) {
                             ++ran;
                             if (k == 10) throw std::runtime_error("item 10");
                           }),
               std::runtime_error);
  EXPECT_LT(ran, 100000);
  std::atomic<int> after{0};
  onEveryCore(100, always, [&](std::size_t) { ++after; });
  EXPECT_EQ(after, 100);
}

TEST(EveryCore, AHelpersExceptionIsThrownAgainInTheCaller) {
  if (coreCount() < 2) GTEST_SKIP() << "one core";
  const std::thread::id caller = std::this_thread::get_id();
  // Items slow enough that the helpers take some; each helper throws at its first.
  EXPECT_THROW(onEveryCore(1000, always,
                           [&](std::size_t) {
                             std::this_thread::sleep_for(std::chrono::microseconds(100));
                             if (std::this_thread::get_id() != caller) throw std::runtime_error("helper");
                           }),
               std::runtime_error);
  std::atomic<int> after{0};
  onEveryCore(100, always, [&](std::size_t) { ++after; });
  EXPECT_EQ(after, 100);
}

TEST(EveryCore, KeepGoingStopsHandingOutItems) {
  std::atomic<int> ran{0};
  onEveryCore(100000, [&] { return ran < 50; }, [&](std::size_t) { ++ran; });
  EXPECT_GE(ran, 50);
  EXPECT_LE(ran, 50 + static_cast<int>(coreCount()));
}

TEST(EveryCore, CallsInsideWorkAndFromOtherThreadsRunEveryItem) {
  std::atomic<int> inner{0};
  onEveryCore(8, always, [&](std::size_t) { onEveryCore(10, always, [&](std::size_t) { ++inner; }); });
  EXPECT_EQ(inner, 80);
  std::atomic<int> total{0};
  std::vector<std::thread> callers;
  for (int caller = 0; caller < 4; ++caller) {
    callers.emplace_back([&] {
      for (int call = 0; call < 20; ++call) onEveryCore(25, always, [&](std::size_t) { ++total; });
    });
  }
  for (std::thread& caller : callers) caller.join();
  EXPECT_EQ(total, 4 * 20 * 25);
}

}  // namespace
}  // namespace freespace
