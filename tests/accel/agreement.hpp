#pragma once
// Compares an accelerator's answers with brute force on the same triangle test.
#include <rtlab/accel/accelerator.hpp>
#include <rtlab/accel/hit_agreement.hpp>

#include <span>
#include <string>
#include <vector>

namespace rtlab::test {

/// The library's rule (rtlab/accel/hit_agreement.hpp), the one rtlab-accel counts mismatches by.
using rtlab::same_hit;

struct Agreement {
    int rays = 0, mismatches = 0, anyhit_mismatches = 0, hits = 0;
};

struct Answer {
    bool hit;
    MeshHit closest;
};

inline std::vector<Answer> answers(const TriangleAccelerator& accel, std::span<const Ray> rays) {
    std::vector<Answer> out;
    out.reserve(rays.size());
    for (const Ray& ray : rays) {
        Answer a{};
        a.hit = accel.intersect(ray, a.closest);
        out.push_back(a);
    }
    return out;
}

/// Compares accel's closest and any-hit answers with the reference answers to the same rays.
inline Agreement compare(const TriangleAccelerator& accel, const std::vector<Answer>& reference,
                         std::span<const Ray> rays) {
    Agreement a;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        MeshHit h;
        const bool b = accel.intersect(rays[i], h);
        ++a.rays;
        a.hits += reference[i].hit;
        if (!same_hit(b, h, reference[i].hit, reference[i].closest)) ++a.mismatches;
        if (accel.occluded(rays[i]) != reference[i].hit) ++a.anyhit_mismatches;
    }
    return a;
}

}  // namespace rtlab::test
