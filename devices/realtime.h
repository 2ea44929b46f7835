#pragma once
// Real-time scheduling for the acquisition thread: SCHED_FIFO and locked memory when the
// system permits it, and a warning saying what was not possible (and how to allow it) when not.

#include <QString>

namespace nb::devices {

struct RealtimeResult {
    bool fifo = false;         // SCHED_FIFO granted to the calling thread
    bool memoryLocked = false; // mlockall succeeded
    QString warning;           // empty when everything asked for was granted
};

// Applies to the calling thread. `priority` 1..99.
RealtimeResult makeCurrentThreadRealtime(int priority = 80);

}  // namespace nb::devices
