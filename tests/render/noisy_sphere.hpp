#pragma once
// Test helper: a cheap analytic scene whose pixels differ, and counts of every ray kind, for renderer tests.
#include "image_bytes.hpp"

#include <rtlab/core/image.hpp>
#include <rtlab/render/radiance_source.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace rtlab::test {

/// A unit sphere at (0, 0, -4) with a sky behind it. A hit counts a shadow ray, and a reflected and a refracted
/// one on parts of the sphere, and is coloured by shade(light), light being the cosine towards (1, 1, 1).
template <class Shade>
RGB noisy_sphere(const Ray& r, RayCounters& counters, Shade&& shade) {
    const Vec3 oc = r.origin - Point3(0, 0, -4);
    const float b = glm::dot(oc, r.direction), c = glm::dot(oc, oc) - 1.0f, disc = b * b - c;
    if (disc < 0.0f) return RGB(0.1f, 0.2f, 0.4f * std::abs(r.direction.y));
    const Vec3 n = glm::normalize(oc + (-b - std::sqrt(disc)) * r.direction);
    ++counters.shadow;
    if (n.y > 0.5f) ++counters.reflected;
    if (n.x > 0.5f) ++counters.refracted;
    return shade(std::max(0.0f, glm::dot(n, glm::normalize(Vec3(1, 1, 1)))));
}

}  // namespace rtlab::test
