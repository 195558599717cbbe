#pragma once

#include "freespace/geometry/cancellation.h"

namespace freespace::cli {

/// Handles SIGINT, SIGTERM, SIGHUP and SIGQUIT for the whole run. Inside a
/// StoppableSection the first such signal asks the computation to stop (it throws
/// Cancelled, and main exits with 128 + the signal); anywhere else, or at a second
/// signal, the temporary files of writes in progress are removed and the program
/// exits with 128 + the signal at once.
void installStopHandlers();

/// The signal that asked to stop, 0 if none did.
int stopSignal();

/// While it lives, stop signals ask its cancellation() to stop.
class StoppableSection {
 public:
  StoppableSection();
  ~StoppableSection();
  StoppableSection(const StoppableSection&) = delete;
  StoppableSection& operator=(const StoppableSection&) = delete;

  Cancellation cancellation() const;
};

}  // namespace freespace::cli
