#pragma once

namespace rtlab::app {

/// Sets the C heap up for one short render (glibc on Linux, not under the address sanitizer; nothing elsewhere):
/// freed memory is kept for reuse, and the heap's first 64 MB are advised into huge pages. run_program() calls it
/// before the program's body, before any thread starts.
void prepare_heap();

}  // namespace rtlab::app
