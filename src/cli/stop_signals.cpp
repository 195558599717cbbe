#include "stop_signals.h"

#include <unistd.h>

#include <atomic>
#include <csignal>

#include "freespace/io/output_file.h"

namespace freespace::cli {

namespace {

std::atomic<bool> stoppable{false};
std::atomic<bool> stopRequested{false};
std::atomic<int> stopRequestedBy{0};

void onStopSignal(int signal) {
  const bool again = stopRequested.exchange(true);
  stopRequestedBy = signal;
  if (stoppable && !again) return;  // the computation polls stopRequested
  removePendingOutputs();
  ::_exit(128 + signal);
}

}  // namespace

void installStopHandlers() {
  for (int signal : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) std::signal(signal, onStopSignal);
}

int stopSignal() { return stopRequestedBy; }

StoppableSection::StoppableSection() { stoppable = true; }

StoppableSection::~StoppableSection() { stoppable = false; }

Cancellation StoppableSection::cancellation() const { return Cancellation(stopRequested); }

}  // namespace freespace::cli
