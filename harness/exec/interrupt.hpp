// SIGINT and SIGTERM during a sweep. The handler only raises a flag; the sweep stops taking
// runs, the runs in flight stop at their next step and are dropped (they are not results),
// and the command exits 128 + the signal after telling how to resume. The finished runs are
// already on disk (harness/journal.hpp).
#pragma once

namespace rotbench {

// While one lives, SIGINT and SIGTERM raise the flag instead of ending the process; the
// previous handlers come back when it dies. The flag is cleared when it is made.
class InterruptGuard {
public:
    InterruptGuard();
    ~InterruptGuard();
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;
};

// The signal that was caught (SIGINT, SIGTERM or SIGHUP), -1 when the sweep was asked to stop for
// another reason (request_stop), or 0. Cheap: checked at every step.
int interrupt_signal();
// Stops the sweep as a signal would (a file it must write cannot be written).
void request_stop();

}  // namespace rotbench
