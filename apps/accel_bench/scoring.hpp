#pragma once
// The reference answers on a sample of each ray set, and the figures of one method on one set: throughput,
// size and mismatches against the reference.
#include "timing.hpp"

#include <rtlab/accel/accelerator.hpp>

#include <tbb/task_arena.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace rtlab::accel_app {

/// `count` indices spread evenly over [0, n) (all of them when count >= n).
std::vector<std::size_t> even_sample(std::size_t n, std::size_t count);
std::vector<Ray> sample_rays(const std::vector<Ray>& rays, std::size_t count);

/// The reference's answers to a sample of one ray set.
struct Reference {
    std::string name;                 // "brute" or "embree"; empty without a reference
    std::vector<std::size_t> sample;  // indices of the rays it answered
    std::vector<MeshHit> hits;        // hits[k] answers rays[sample[k]]
    std::vector<unsigned char> hit;   // not vector<bool>: filled in parallel, one byte per ray
};

/// Brute force up to 200k triangles, else Embree when built with it, else none (nullptr); always with the
/// watertight test.
std::unique_ptr<TriangleAccelerator> make_reference(const TriangleMesh& mesh, const BuildOptions& options,
                                                    tbb::task_arena& arena);

/// The reference's answers to an even sample of `rays`; an empty Reference when there is no reference.
Reference reference_answers(const TriangleAccelerator* reference, const std::vector<Ray>& rays, std::size_t sample_size,
                            tbb::task_arena& arena);

/// One method on one ray set; -1 marks a figure that does not apply.
struct Score {
    std::string method;
    double build_s = 0;
    AccelStats stats;
    double bytes_per_triangle = -1;  // the structure's own bytes (nodes, indices, leaf layouts)
    std::size_t rays = 0;            // rays traced (the sample only for brute force)
    double closest_mrays = 0, any_mrays = 0;
    std::int64_t mismatches = -1;  // sampled rays whose closest hit is not the reference's (same_hit)
};

Score score(const Built& built, const Traced& traced, const Reference& reference, const TriangleMesh& mesh);

}  // namespace rtlab::accel_app
