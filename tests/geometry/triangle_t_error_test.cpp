// The watertight test's conservative bound on the error of t: a ray spawned off a triangle (spawn.hpp)
// never hits that triangle again, at any scale. Without the bound, rounding in t now and then reports the
// ray's own origin surface at a tiny positive t.
#include <rtlab/geometry/spawn.hpp>
#include <rtlab/geometry/triangle_intersect.hpp>
#include <rtlab/geometry/triangle_shape.hpp>

#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include "test_meshes.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <random>
#include <vector>

using namespace rtlab;

namespace {

std::mt19937 g_rng(31);

float uniform() { return std::uniform_real_distribution<float>(0.0f, 1.0f)(g_rng); }

Vec3 random_unit() {
    const float z = 1.0f - 2.0f * uniform(), phi = 2.0f * kPi * uniform();
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// A direction within 1e-4..1e-2 (cosine) of the plane with normal n, on either side: the hardest case,
// where the offset along the normal buys the least distance.
Vec3 grazing(const Normal3& n) {
    Vec3 tangent = random_unit();
    tangent = glm::normalize(tangent - glm::dot(tangent, n) * n);
    const float c = std::pow(10.0f, -4.0f + 2.0f * uniform()) * (uniform() < 0.5f ? -1.0f : 1.0f);
    return glm::normalize(tangent * std::sqrt(1.0f - c * c) + c * n);
}

// 20,000 triangles of size `size` (0.5 to 1.5 times it from a centre point to each corner), each around a
// point within 1e-3 * size of the world's origin, in random planes: the hit points there have tiny
// coordinates, so their error bound and offset are tiny, while the triangle's far corners make the error of
// t large. Without the t error bound this test measured 20, 17, 11 and 12 of 200,000 spawned rays hitting
// their own triangle at sizes 1e-4, 1, 1e3 and 1e6 (the bumpy sphere: 0).
struct Fan {
    std::shared_ptr<TriangleMesh> mesh = std::make_shared<TriangleMesh>();
    std::vector<Point3> centres;
};
Fan fan(float size) {
    Fan f;
    for (std::uint32_t i = 0; i < 20000; ++i) {
        const Vec3 n = random_unit(), e1 = glm::normalize(glm::cross(n, random_unit())), e2 = glm::cross(n, e1);
        const Point3 centre = 1e-3f * size * random_unit();
        const float angle = 2.0f * kPi * uniform();
        for (int k = 0; k < 3; ++k) {
            const float a = angle + static_cast<float>(k) * 2.0f * kPi / 3.0f + 0.5f * (uniform() - 0.5f);
            f.mesh->positions.push_back(centre + size * (0.5f + uniform()) * (std::cos(a) * e1 + std::sin(a) * e2));
        }
        f.mesh->triangles.push_back({3 * i, 3 * i + 1, 3 * i + 2});
        f.centres.push_back(centre);
    }
    return f;
}

// An icosphere with every vertex moved radially by up to 20% (triangles of every orientation), scaled by
// `size` and moved `size` away from the origin, with a random point on each triangle.
Fan bumpy_sphere(float size) {
    Fan f;
    *f.mesh = test::icosphere(4);
    const Mat4 t = glm::scale(glm::translate(Mat4(1.0f), size * Vec3(0.6f, -0.48f, 0.64f)), Vec3(size));
    for (auto& p : f.mesh->positions) p = Point3(t * Vec4((0.8f + 0.4f * uniform()) * p, 1.0f));
    for (std::size_t i = 0; i < f.mesh->triangle_count(); ++i) {
        float b1 = uniform(), b2 = uniform();
        if (b1 + b2 > 1.0f) b1 = 1.0f - b1, b2 = 1.0f - b2;
        const Point3 p0 = f.mesh->corner(i, 0);
        f.centres.push_back(p0 + b1 * (f.mesh->corner(i, 1) - p0) + b2 * (f.mesh->corner(i, 2) - p0));
    }
    return f;
}

struct Count {
    long spawned = 0, own_hits = 0;
};

// From every triangle: the hit by a ray from a random side aimed at its point, then 5 rays in uniform
// directions and 5 grazing ones spawned from it. Counts the rays that hit their own triangle again.
Count rehits(const Fan& f, float size) {
    Count n;
    for (std::uint32_t i = 0; i < f.mesh->triangle_count(); ++i) {
        const TriangleShape triangle(f.mesh, i);
        const Point3 origin = f.centres[i] + 2.0f * size * random_unit();
        SurfaceHit hit;
        if (!triangle.intersect(Ray{origin, f.centres[i] - origin}, hit)) continue;
        for (int j = 0; j < 10; ++j) {
            const Vec3 dir = j < 5 ? random_unit() : grazing(hit.geometric_normal);
            ++n.spawned;
            if (triangle.occluded(spawn_ray(hit, dir))) ++n.own_hits;
        }
    }
    return n;
}

}  // namespace

TEST_CASE("spawned rays never hit their own triangle again at scales 1e-4 to 1e6", "[triangle][spawn]") {
    long total = 0;
    for (float size : {1e-4f, 1.0f, 1e3f, 1e6f}) {
        for (bool near_origin : {true, false}) {
            const Fan f = near_origin ? fan(size) : bumpy_sphere(size);
            const Count n = rehits(f, size);
            const char* kind = near_origin ? "large triangles around the origin" : "bumpy sphere";
            std::printf("t error bound: size %g, %s: %ld of %ld spawned rays hit their own triangle\n", size, kind,
                        n.own_hits, n.spawned);
            INFO("size " << size << " " << kind << ": " << n.own_hits << " of " << n.spawned);
            CHECK(n.spawned >= 10L * static_cast<long>(f.mesh->triangle_count()) * 9 / 10);
            CHECK(n.own_hits == 0);
            total += n.spawned;
        }
    }
    CHECK(total > 900000);
}

TEST_CASE("the t error bound is a few ulps of t whatever the length of the direction", "[triangle]") {
    // Unit magnitudes everywhere: a few float epsilons.
    const float unit = watertight_t_error(1.0f, 1.0f, 1.0f, 1.0f, 1.0f, 1.0f);
    CHECK(unit > 3.0f * std::numeric_limits<float>::epsilon());
    CHECK(unit < 100.0f * std::numeric_limits<float>::epsilon());
    // A triangle 1 unit across at distance 1, hit at t = 1, with the direction's length 1 / k: the scaled z
    // and t grow k times, the edge functions and 1 / det do not change. The bound must grow with t, not
    // faster (pbrt's, which bounds the shear's error with the scaled z, grows like k^2 and then rejects
    // true hits of short directions).
    for (float k : {1.0f, 1024.0f, 1048576.0f}) {
        const float bound = watertight_t_error(1.0f, 1.0f, 1.0f, k, 1.0f, 1.0f);
        INFO("direction length 1/" << k << ": bound " << bound);
        CHECK(bound <= k * unit);
        CHECK(bound < 1e-5f * k);
    }
    // Hits at the true t are kept for directions of any length and vertices at any scale.
    for (float size : {1e-4f, 1.0f, 1e6f}) {
        for (float length : {1e-6f, 1e-2f, 1.0f, 1e4f}) {
            const Point3 p0 = size * Point3(0, 0, 0), p1 = size * Point3(1, 0, 0), p2 = size * Point3(0, 1, 0);
            const Ray ray{size * Point3(0.25f, 0.25f, 1.0f), Vec3(0.0f, 0.0f, -length)};
            const auto h = intersect_watertight(WatertightRay(ray), 0.0f, kInfinity, p0, p1, p2);
            INFO("size " << size << " direction length " << length);
            REQUIRE(h);
            CHECK(h->t == Approx(size / length).epsilon(1e-6));
        }
    }
}
