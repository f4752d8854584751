// refract() and fresnel_dielectric must agree on where total internal reflection starts: a ray refract()
// reflects totally while F < 1 loses 1 - F of its energy, and a ray it sends on while F == 1 is transmitted
// with no weight. Checked densely around the critical angle, float by float, and through tilted normals the
// way the Whitted recursion calls them.
#include <rtlab/shading/optics.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

using namespace rtlab;

namespace {

struct Sweep {
    std::int64_t tried = 0, disagree = 0, refracted = 0, reflected = 0;
    double worst_energy = 0.0;    // |R + T - 1|, T the energy refract() sends on: 1 - R, or 0 when it reflects
    double worst_physical = 0.0;  // |R + T - 1|, T Fresnel's transmittance from the refracted direction (double)
};

// Fresnel transmittance (T_s + T_p) / 2 in double, from the incident and the transmitted cosines.
double transmittance(double cos_i, double cos_t, double eta) {
    const double t_s = 2.0 * eta * cos_i / (eta * cos_i + cos_t);
    const double t_p = 2.0 * eta * cos_i / (cos_i + eta * cos_t);
    return cos_t / (eta * cos_i) * 0.5 * (t_s * t_s + t_p * t_p);
}

// One incident direction d towards a surface of normal n, as the Whitted recursion passes it on.
void visit(Sweep& s, const Vec3& d, const Normal3& n, float eta) {
    const auto t = refract(d, n, eta);
    const float cos_i = glm::dot(-d, n);
    const float f = fresnel_dielectric(cos_i, eta);
    ++s.tried;
    // Total reflection by refract() while F < 1 loses energy. The other way round, F == 1 for a refracted ray
    // is a wrong call of total reflection too, except at grazing incidence, where F rounds to 1 in float (and
    // is 1 at cos_i = 0) whether or not the ray could pass.
    const bool agree = t ? f < 1.0f || cos_i < 1e-3f : f == 1.0f;
    s.disagree += !agree;
    const double r = f;
    const double sent_on = t ? 1.0 - r : 0.0;
    s.worst_energy = std::max(s.worst_energy, std::abs(r + sent_on - 1.0));
    if (t) {
        ++s.refracted;
        const glm::dvec3 td(*t), nd(n), dd(d);
        const double cos_i = -glm::dot(dd, nd) / glm::length(dd);
        const double cos_t = -glm::dot(td, nd) / glm::length(td);
        s.worst_physical = std::max(s.worst_physical, std::abs(r + transmittance(cos_i, cos_t, eta) - 1.0));
    } else {
        ++s.reflected;
    }
}

// A unit normal tilted away from +z, and the direction at angle theta to it in a plane of azimuth phi.
struct Tilted {
    Normal3 n;
    Vec3 u, v;
};
Tilted tilted(float tilt, float spin) {
    const Normal3 n(std::sin(tilt) * std::cos(spin), std::sin(tilt) * std::sin(spin), std::cos(tilt));
    const Vec3 u = glm::normalize(glm::cross(std::abs(n.x) < 0.9f ? Vec3(1, 0, 0) : Vec3(0, 1, 0), n));
    return {n, u, glm::cross(n, u)};
}

constexpr float kEtas[] = {1.01f, 1.33f, 1.5f, 2.4f};

}  // namespace

TEST_CASE("refract and fresnel_dielectric agree within 1e-3 rad of the critical angle", "[optics]") {
    for (float base : kEtas) {
        for (float eta : {base, 1.0f / base}) {
            // eta < 1 has no critical angle: its sweep is the same band of angles, all refracted.
            const double critical = std::asin(1.0 / std::max(base, 1.0f));
            Sweep s;
            constexpr int n = 200000;
            const Normal3 up(0.0f, 0.0f, 1.0f);
            for (int i = 0; i < n; ++i) {
                const double theta = critical + 1e-3 * (2.0 * i / (n - 1) - 1.0);
                visit(s, Vec3(static_cast<float>(std::sin(theta)), 0.0f, -static_cast<float>(std::cos(theta))), up,
                      eta);
            }
            INFO("eta " << eta << ": " << s.disagree << " disagreements of " << s.tried << ", " << s.reflected
                        << " totally reflected, energy error " << s.worst_energy << ", Fresnel R + T error "
                        << s.worst_physical);
            CHECK(s.tried == n);
            CHECK(s.disagree == 0);
            CHECK(s.worst_energy < 1e-6);
            CHECK(s.worst_physical < 1e-6);  // measured at most 6.7e-7 (eta 2.4)
            if (eta > 1.0f) {                // both sides of the critical angle were reached
                CHECK(s.reflected > n / 3);
                CHECK(s.refracted > n / 3);
            } else {
                CHECK(s.reflected == 0);
            }
        }
    }
}

TEST_CASE("refract and fresnel_dielectric agree at every float cosine next to the critical one", "[optics]") {
    for (float base : kEtas) {
        const float eta = base;
        const float critical_cos = static_cast<float>(std::sqrt(1.0 - 1.0 / (double(eta) * eta)));
        Sweep s;
        // 20000 consecutive floats on either side: every cosine the rounding could put on the wrong side.
        float c = critical_cos;
        for (int i = 0; i < 20000; ++i) c = std::nextafter(c, 0.0f);
        for (int i = 0; i < 40001; ++i, c = std::nextafter(c, 2.0f)) {
            const float sin_i = std::sqrt(std::max(0.0f, 1.0f - c * c));
            // Normal +z: dot(-d, n) is exactly c, the float being tested.
            visit(s, Vec3(sin_i, 0.0f, -c), Normal3(0.0f, 0.0f, 1.0f), eta);
        }
        INFO("eta " << eta << ": " << s.disagree << " disagreements of " << s.tried << ", " << s.reflected
                    << " totally reflected, energy error " << s.worst_energy << ", Fresnel R + T error "
                    << s.worst_physical);
        CHECK(s.disagree == 0);
        CHECK(s.worst_energy < 1e-6);
        CHECK(s.worst_physical < 1e-6);
        CHECK(s.reflected > 1000);
        CHECK(s.refracted > 1000);
    }
}

TEST_CASE("refract and fresnel_dielectric agree through tilted normals at every angle", "[optics]") {
    std::mt19937 rng(21);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    for (float base : kEtas) {
        for (float eta : {base, 1.0f / base}) {
            const double critical = eta > 1.0f ? std::asin(1.0 / eta) : 0.5 * M_PI;
            Sweep s;
            for (int i = 0; i < 100000; ++i) {
                const Tilted f = tilted(3.0f * u01(rng), 6.283185f * u01(rng));
                // Half near the critical angle (or grazing, for eta < 1), half anywhere in the hemisphere.
                const double theta =
                    i % 2 == 0 ? std::min(critical + 2e-3 * (u01(rng) - 0.5), 0.5 * M_PI) : 0.5 * M_PI * u01(rng);
                const float phi = 6.283185f * u01(rng);
                const Vec3 along = std::cos(phi) * f.u + std::sin(phi) * f.v;
                const Vec3 d = static_cast<float>(std::sin(theta)) * along - static_cast<float>(std::cos(theta)) * f.n;
                visit(s, d, f.n, eta);
            }
            INFO("eta " << eta << ": " << s.disagree << " disagreements of " << s.tried << ", " << s.reflected
                        << " totally reflected, energy error " << s.worst_energy << ", Fresnel R + T error "
                        << s.worst_physical);
            CHECK(s.disagree == 0);
            CHECK(s.worst_energy < 1e-6);
            // Float rounding of the tilted directions themselves: measured at most 3.4e-6 (eta 1.01).
            CHECK(s.worst_physical < 1e-5);
            if (eta > 1.0f) CHECK(s.reflected > 10000);
        }
    }
}
