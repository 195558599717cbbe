#pragma once

#include <atomic>
#include <stdexcept>

namespace freespace {

/// Thrown by a computation that was asked to stop.
class Cancelled : public std::runtime_error {
 public:
  Cancelled() : std::runtime_error("cancelled") {}
};

/// A request to stop a long computation, polled by its loops (often enough that a
/// construction stops within a small fraction of a second). A default one never
/// asks.
class Cancellation {
 public:
  Cancellation() = default;
  explicit Cancellation(const std::atomic<bool>& requested) : requested_(&requested) {}

  /// Throws Cancelled once stopping was requested.
  void check() const {
    if (requested_ && requested_->load(std::memory_order_relaxed)) throw Cancelled();
  }

 private:
  const std::atomic<bool>* requested_ = nullptr;
};

}  // namespace freespace
