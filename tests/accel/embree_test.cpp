#include <rtlab/accel/accelerator.hpp>

#include <catch2/catch.hpp>

#include "test_meshes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

using namespace rtlab;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// Rays Debian's libembree3 would assert on; every method must answer them as misses without crashing.
std::vector<Ray> rejected_rays() {
    const Point3 o(0.0f, 0.0f, -3.0f);
    const Vec3 d(0.0f, 0.0f, 1.0f);
    return {
        Ray{Point3(kNaN, 0.0f, -3.0f), d},
        Ray{o, Vec3(0.0f, kNaN, 1.0f)},
        Ray{Point3(0.0f, 0.0f, -kInfinity), d},
        Ray{o, Vec3(0.0f, 0.0f, kInfinity)},
        Ray{o, Vec3(0.0f)},
        Ray{o, Vec3(-0.0f, 0.0f, -0.0f)},
        Ray{o, d, 5.0f, 1.0f},  // tmin > tmax
        Ray{o, d, 2.0f, 2.0f},  // empty open interval
        Ray{o, d, kNaN, 10.0f},
        Ray{o, d, 0.0f, kNaN},
    };
}

}  // namespace

TEST_CASE("every method answers NaN or inf components and zero directions and empty intervals as misses", "[accel]") {
    const TriangleMesh mesh = test::icosphere(2);
    for (const std::string& method : accelerator_methods()) {
        const auto accel = make_accelerator(method, mesh);
        int hits = 0, blocked = 0;
        for (const Ray& ray : rejected_rays()) {
            MeshHit h;
            hits += accel->intersect(ray, h);
            blocked += accel->occluded(ray);
        }
        INFO(method);
        CHECK(hits == 0);
        CHECK(blocked == 0);
        // The same method still answers an ordinary ray afterwards.
        MeshHit h;
        REQUIRE(accel->intersect(Ray{Point3(0.0f, 0.0f, -3.0f), Vec3(0.0f, 0.0f, 1.0f)}, h));
        CHECK(h.t == Approx(2.0f).margin(0.01f));
    }
}

TEST_CASE("hits at exactly tmin or tmax are outside the open interval for every method", "[accel]") {
    // One triangle in the plane z = 1, ray along +z from the origin: t = 1 exactly.
    TriangleMesh mesh;
    mesh.positions = {Point3(-1.0f, -1.0f, 1.0f), Point3(1.0f, -1.0f, 1.0f), Point3(0.0f, 1.0f, 1.0f)};
    mesh.triangles = {{0, 1, 2}};
    const Point3 o(0.0f, 0.0f, 0.0f);
    const Vec3 d(0.0f, 0.0f, 1.0f);
    for (const std::string& method : accelerator_methods()) {
        INFO(method);
        const auto accel = make_accelerator(method, mesh);
        MeshHit h;
        CHECK_FALSE(accel->intersect(Ray{o, d, 0.0f, 1.0f}, h));
        CHECK_FALSE(accel->intersect(Ray{o, d, 1.0f, 2.0f}, h));
        CHECK_FALSE(accel->occluded(Ray{o, d, 0.0f, 1.0f}));
        CHECK_FALSE(accel->occluded(Ray{o, d, 1.0f, 2.0f}));
        REQUIRE(accel->intersect(Ray{o, d, 0.0f, std::nextafter(1.0f, 2.0f)}, h));
        if (method == "embree") {
            // Embree's kernels (chosen by the CPU they run on) compute t in their own order: within 2 ulp.
            CHECK(std::abs(h.t - 1.0f) <= 2.0f * std::numeric_limits<float>::epsilon());
        } else {
            CHECK(h.t == 1.0f);
        }
        CHECK(accel->occluded(Ray{o, d, std::nextafter(1.0f, 0.0f), 2.0f}));
    }
}

TEST_CASE("barycentrics follow FORMATS.md for every method including Embree", "[accel]") {
    // point = (1-u-v) p0 + u p1 + v p2; the ray aims at 0.2 p0 + 0.3 p1 + 0.5 p2.
    TriangleMesh mesh;
    mesh.positions = {Point3(0.0f, 0.0f, 0.0f), Point3(4.0f, 0.0f, 0.0f), Point3(0.0f, 2.0f, 0.0f)};
    mesh.triangles = {{0, 1, 2}};
    const Point3 target = 0.2f * mesh.positions[0] + 0.3f * mesh.positions[1] + 0.5f * mesh.positions[2];
    const Ray ray{target + Vec3(0.5f, 0.25f, 2.0f), Vec3(-0.5f, -0.25f, -2.0f)};
    for (const std::string& method : accelerator_methods()) {
        INFO(method);
        MeshHit h;
        REQUIRE(make_accelerator(method, mesh)->intersect(ray, h));
        CHECK(h.primitive == 0u);
        CHECK(h.t == Approx(1.0f).margin(1e-5));
        CHECK(h.u == Approx(0.3f).margin(1e-5));
        CHECK(h.v == Approx(0.5f).margin(1e-5));
    }
}
