#pragma once
// --packets: coherent rays traced one at a time and in packets of a 4 x 2 pixel tile (intersect_packet,
// occluded_packet) by every method, in alternating rounds, with the packets' differences from the single
// rays' answers.
#include "options.hpp"
#include "report.hpp"
#include "scoring.hpp"
#include "timing.hpp"

#include <rtlab/accel/accelerator.hpp>

#include <tbb/task_arena.h>

namespace rtlab::accel_app {

/// The primary set in 4 x 2 tiles and shadow rays from its hits (by the first method, one ray at a time)
/// towards a point above the mesh, each traced by every built method singly and in packets: a table row
/// for each (method "kd-sah" and "kd-sah 4x2"), then the packets' bitwise differences and their speed
/// against the other methods'. Throws rtlab::Error when the primary size is not a multiple of 4.
void run_packet_sets(const Options& options, const TriangleMesh& mesh, const std::vector<Built>& built,
                     const TriangleAccelerator* reference, Report& report, tbb::task_arena& arena);

}  // namespace rtlab::accel_app
