#include <rtlab/core/frame.hpp>
#include <rtlab/core/rng.hpp>

#include <catch2/catch.hpp>

using namespace rtlab;

namespace {
// Largest deviation of (s, t, n) from an orthonormal right-handed basis.
float orthonormality_error(const Frame& f) {
    float e = 0.0f;
    e = std::max(e, std::abs(glm::dot(f.s, f.s) - 1.0f));
    e = std::max(e, std::abs(glm::dot(f.t, f.t) - 1.0f));
    e = std::max(e, std::abs(glm::dot(f.s, f.t)));
    e = std::max(e, std::abs(glm::dot(f.s, f.n)));
    e = std::max(e, std::abs(glm::dot(f.t, f.n)));
    e = std::max(e, glm::length(glm::cross(f.s, f.t) - f.n));
    return e;
}
}  // namespace

TEST_CASE("frames near +z and -z stay orthonormal", "[frame]") {
    // The Frisvad construction breaks down near (0, 0, -1); Duff et al.'s must not.
    for (float sign : {1.0f, -1.0f}) {
        for (float eps : {0.0f, 1e-9f, 1e-7f, 1e-5f, 1e-3f}) {
            for (const Vec3& offset : {Vec3(eps, 0, 0), Vec3(0, eps, 0), Vec3(eps, -eps, 0), Vec3(-eps, eps, 0)}) {
                const Vec3 n = glm::normalize(Vec3(0, 0, sign) + offset);
                const Frame f = Frame::from_normal(n);
                INFO("n = " << n.x << " " << n.y << " " << n.z);
                CHECK(orthonormality_error(f) < 1e-5f);
            }
        }
    }
    // -0 in z picks the negative branch of copysign and must be just as good.
    CHECK(orthonormality_error(Frame::from_normal(Vec3(0, 0, -0.0f) + Vec3(1, 0, 0))) < 1e-6f);
}

TEST_CASE("frames over the whole sphere and local-world round trips", "[frame]") {
    Rng rng(42);
    float worst = 0.0f;
    for (int i = 0; i < 100000; ++i) {
        const float z = 1.0f - 2.0f * rng.uniform();
        const float phi = 2.0f * kPi * rng.uniform();
        const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        const Vec3 n(r * std::cos(phi), r * std::sin(phi), z);
        const Frame f = Frame::from_normal(n);
        worst = std::max(worst, orthonormality_error(f));
        const Vec3 v(0.3f, -0.7f, 0.2f);
        worst = std::max(worst, glm::length(f.to_world(f.to_local(v)) - v));
    }
    CHECK(worst < 1e-5f);
}
