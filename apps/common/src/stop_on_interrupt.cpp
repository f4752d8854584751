#include <rtlab/app/stop_on_interrupt.hpp>

#include <csignal>

namespace rtlab::app {

namespace {
// A lock-free atomic is safe to touch from a signal handler.
std::atomic<bool> g_stop{false};
static_assert(std::atomic<bool>::is_always_lock_free);
struct sigaction g_previous_int, g_previous_term;

extern "C" void on_signal(int signal) {
    if (g_stop.exchange(true)) {
        // The second Ctrl-C: the user wants out now.
        std::signal(signal, SIG_DFL);
        std::raise(signal);
    }
}
}  // namespace

StopOnInterrupt::StopOnInterrupt() {
    g_stop = false;
    struct sigaction action {};
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &g_previous_int);
    sigaction(SIGTERM, &action, &g_previous_term);
}

StopOnInterrupt::~StopOnInterrupt() {
    sigaction(SIGINT, &g_previous_int, nullptr);
    sigaction(SIGTERM, &g_previous_term, nullptr);
}

const std::atomic<bool>& StopOnInterrupt::flag() const { return g_stop; }

}  // namespace rtlab::app
