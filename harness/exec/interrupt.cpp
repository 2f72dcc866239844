#include "harness/exec/interrupt.hpp"

#include <atomic>
#include <csignal>

namespace rotbench {
namespace {

std::atomic<int> caught{0};  // lock-free on every target we build for: safe in a handler
static_assert(std::atomic<int>::is_always_lock_free);

struct sigaction previous_int, previous_term, previous_hup;

extern "C" void raise_flag(int signal) { caught.store(signal, std::memory_order_relaxed); }

}  // namespace

InterruptGuard::InterruptGuard() {
    caught.store(0);
    struct sigaction action {};
    action.sa_handler = raise_flag;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &previous_int);
    sigaction(SIGTERM, &action, &previous_term);
    // The terminal closed, or a batch system's notice; unless ignored on purpose (nohup).
    sigaction(SIGHUP, nullptr, &previous_hup);
    if (previous_hup.sa_handler != SIG_IGN) sigaction(SIGHUP, &action, nullptr);
}

InterruptGuard::~InterruptGuard() {
    caught.store(0);  // a later sweep in this process is not interrupted
    sigaction(SIGINT, &previous_int, nullptr);
    sigaction(SIGTERM, &previous_term, nullptr);
    sigaction(SIGHUP, &previous_hup, nullptr);
}

int interrupt_signal() { return caught.load(std::memory_order_relaxed); }

void request_stop() {
    int none = 0;
    caught.compare_exchange_strong(none, -1);
}

}  // namespace rotbench
