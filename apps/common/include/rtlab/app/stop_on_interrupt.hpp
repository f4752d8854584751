#pragma once
/// \brief Ctrl-C as a request to stop the render and write what is done.
#include <atomic>

namespace rtlab::app {

/// \brief While alive, SIGINT and SIGTERM set a stop flag (pass &flag() as RenderCallbacks::stop) instead
/// of ending the process; a second signal ends it the usual way. The previous handlers come back on
/// destruction. One at a time per process.
class StopOnInterrupt {
public:
    StopOnInterrupt();
    StopOnInterrupt(const StopOnInterrupt&) = delete;
    StopOnInterrupt& operator=(const StopOnInterrupt&) = delete;
    ~StopOnInterrupt();

    const std::atomic<bool>& flag() const;
    bool interrupted() const { return flag().load(); }
};

}  // namespace rtlab::app
