#include "scoring.hpp"

#include <rtlab/accel/hit_agreement.hpp>

#include <tbb/parallel_for.h>

#include <algorithm>

namespace rtlab::accel_app {

namespace {

constexpr std::size_t kBruteReferenceTriangles = 200000;

// Rays of the reference's sample whose closest hit differs from its answer; `sample_only`: hits answers
// the sample alone (brute force), not the whole set.
std::int64_t count_mismatches(const Reference& ref, const std::vector<MeshHit>& hits, bool sample_only) {
    if (ref.sample.empty()) return -1;
    std::int64_t mismatches = 0;
    for (std::size_t k = 0; k < ref.sample.size(); ++k) {
        const MeshHit& h = hits[sample_only ? k : ref.sample[k]];
        mismatches += !same_hit(h.hit(), h, ref.hit[k] != 0, ref.hits[k]);
    }
    return mismatches;
}

}  // namespace

std::vector<std::size_t> even_sample(std::size_t n, std::size_t count) {
    std::vector<std::size_t> s;
    if (n == 0) return s;
    count = std::min(count, n);
    for (std::size_t k = 0; k < count; ++k) s.push_back(k * n / count);
    return s;
}

std::vector<Ray> sample_rays(const std::vector<Ray>& rays, std::size_t count) {
    std::vector<Ray> sampled;
    for (std::size_t i : even_sample(rays.size(), count)) sampled.push_back(rays[i]);
    return sampled;
}

std::unique_ptr<TriangleAccelerator> make_reference(const TriangleMesh& mesh, const BuildOptions& options,
                                                    tbb::task_arena& arena) {
    const auto known = accelerator_methods();
    const bool have_embree = std::find(known.begin(), known.end(), "embree") != known.end();
    BuildOptions reference_options = options;
    reference_options.triangle_test = TriangleTest::watertight;
    std::unique_ptr<TriangleAccelerator> reference;
    if (mesh.triangle_count() <= kBruteReferenceTriangles)
        reference = make_accelerator("brute", mesh, reference_options);
    else if (have_embree)
        arena.execute([&] { reference = make_accelerator("embree", mesh, reference_options); });
    return reference;
}

Reference reference_answers(const TriangleAccelerator* reference, const std::vector<Ray>& rays, std::size_t sample_size,
                            tbb::task_arena& arena) {
    Reference ref;
    if (!reference) return ref;
    ref.name = std::string(reference->name());
    ref.sample = even_sample(rays.size(), sample_size);
    ref.hits.resize(ref.sample.size());
    ref.hit.resize(ref.sample.size());
    arena.execute([&] {
        tbb::parallel_for(std::size_t{0}, ref.sample.size(), [&](std::size_t k) {
            MeshHit h;
            ref.hit[k] = reference->intersect(rays[ref.sample[k]], h) ? 1 : 0;
            ref.hits[k] = h;
        });
    });
    return ref;
}

Score score(const Built& built, const Traced& traced, const Reference& reference, const TriangleMesh& mesh) {
    Score s;
    s.method = built.method;
    s.build_s = built.build_s;
    s.stats = built.accel->stats();
    if (s.stats.bytes >= 0 && mesh.triangle_count() > 0)
        s.bytes_per_triangle = static_cast<double>(s.stats.bytes) / static_cast<double>(mesh.triangle_count());
    s.rays = traced.rays->size();
    s.closest_mrays = static_cast<double>(s.rays) / median(traced.closest_s) / 1e6;
    s.any_mrays = static_cast<double>(s.rays) / median(traced.any_s) / 1e6;
    s.mismatches = count_mismatches(reference, traced.hits, built.method == "brute");
    return s;
}

}  // namespace rtlab::accel_app
