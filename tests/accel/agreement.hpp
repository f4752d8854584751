#pragma once
// Compares an accelerator's answers with brute force on the same triangle test.
#include <rtlab/accel/accelerator.hpp>

#include <cmath>
#include <span>
#include <string>

namespace rtlab::test {

/// The mismatch rule of the issue: hit/miss disagreement, |dt| > 1e-4 relative, or a different
/// primitive at a t more than 1e-4 relative apart.
inline bool same_hit(bool hit_a, const MeshHit& a, bool hit_b, const MeshHit& b) {
    if (hit_a != hit_b) return false;
    if (!hit_a) return true;
    const float tol = 1e-4f * std::max(1.0f, std::max(std::abs(a.t), std::abs(b.t)));
    return std::abs(a.t - b.t) <= tol;
}

struct Agreement {
    int rays = 0, mismatches = 0, anyhit_mismatches = 0, hits = 0;
};

inline Agreement compare(const TriangleAccelerator& accel, const TriangleAccelerator& reference, std::span<const Ray> rays) {
    Agreement a;
    for (const Ray& ray : rays) {
        MeshHit h1, h2;
        const bool b1 = accel.intersect(ray, h1);
        const bool b2 = reference.intersect(ray, h2);
        ++a.rays;
        a.hits += b2;
        if (!same_hit(b1, h1, b2, h2)) ++a.mismatches;
        if (accel.occluded(ray) != b2) ++a.anyhit_mismatches;
    }
    return a;
}

}  // namespace rtlab::test
