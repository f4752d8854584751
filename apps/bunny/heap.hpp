#pragma once

namespace rtlab::bunny {

/// Sets the C heap up for one short render (glibc on Linux; nothing elsewhere): freed memory is kept for reuse,
/// and the heap's first 64 MB are advised into huge pages. Call first thing in main, before threads start.
void prepare_heap();

}  // namespace rtlab::bunny
