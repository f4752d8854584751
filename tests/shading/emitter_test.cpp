// The area lights' and the environment's sampling: chi-square of the sampled directions against pdf_li, and the
// irradiance they give a point against the closed forms (the mean within 3 standard errors).
#include <rtlab/core/frame.hpp>
#include <rtlab/core/rng.hpp>
#include <rtlab/geometry/disk.hpp>
#include <rtlab/geometry/quad.hpp>
#include <rtlab/geometry/sphere.hpp>
#include <rtlab/shading/emitter.hpp>
#include <rtlab/shading/light_set.hpp>
#include <rtlab/shading_testing/chi_square.hpp>
#include <rtlab/shading_testing/statistics.hpp>

#include <catch2/catch.hpp>

#include "sample_scale.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

using namespace rtlab;

namespace {

// An emitter with the shape that ray-traces it, so that a direction's density can be worked out from the point
// the direction meets.
struct Case {
    std::string name;
    std::shared_ptr<const AreaEmitter> emitter;
    std::shared_ptr<const Shape> shape;
    bool two_sided = false;
    bool inward = false;  // a sphere emitting on its inside
};

EmitterShape quad_triangles(const Point3& c, const Vec3& u, const Vec3& v) {
    EmitterShape s;
    s.triangles.push_back({c, c + u, c + u + v});
    s.triangles.push_back({c, c + u + v, c + v});
    return s;
}

Case quad_case(bool two_sided) {
    const Point3 c(-0.5f, 1.0f, -0.3f);
    const Vec3 u(1.2f, 0.0f, 0.0f), v(0.0f, 0.2f, 0.7f);  // tilted; faces u x v
    return {two_sided ? "two-sided quad" : "quad",
            std::make_shared<AreaEmitter>(quad_triangles(c, u, v), RGB(1.0f), two_sided),
            std::make_shared<Quad>(c, u, v), two_sided};
}

Case disk_case() {
    EmitterShape s;
    s.kind = EmitterShape::Kind::disk;
    s.centre = Point3(0.3f, 1.5f, 0.2f);
    s.normal = glm::normalize(Vec3(0.2f, -1.0f, 0.1f));
    s.radius = 0.8f;
    s.inner_radius = 0.2f;
    return {"annulus", std::make_shared<AreaEmitter>(s, RGB(1.0f), false),
            std::make_shared<Disk>(s.centre, s.normal, s.radius, s.inner_radius)};
}

Case sphere_case(const Point3& centre, float radius, bool inward) {
    EmitterShape s;
    s.kind = EmitterShape::Kind::sphere;
    s.centre = centre;
    s.radius = radius;
    s.inward = inward;
    return {inward ? "sphere from inside" : "sphere", std::make_shared<AreaEmitter>(s, RGB(1.0f), false),
            std::make_shared<Sphere>(centre, radius), false, inward};
}

// A point of the light's surface with the area it stands for and its emitting normal.
struct AreaPoint {
    Point3 y;
    Normal3 n;
    double area;
};

// The light's surface cut into m x m cells of equal area (quads by their edges, disks by r^2 and phi, spheres by
// z and phi), each given by its midpoint.
std::vector<AreaPoint> surface_points(const Case& c, int m) {
    std::vector<AreaPoint> out;
    const double a = double(c.emitter->area()) / (double(m) * m);
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j) {
            const float s = (i + 0.5f) / m, t = (j + 0.5f) / m;
            if (const auto* q = dynamic_cast<const Quad*>(c.shape.get())) {
                out.push_back({q->corner() + s * q->edge_u() + t * q->edge_v(),
                               glm::normalize(glm::cross(q->edge_u(), q->edge_v())), a});
            } else if (const auto* d = dynamic_cast<const Disk*>(c.shape.get())) {
                const float ri2 = d->inner_radius() * d->inner_radius();
                const float r = std::sqrt(ri2 + s * (d->radius() * d->radius() - ri2)), phi = 2.0f * kPi * t;
                const Frame f = Frame::from_normal(d->normal());
                out.push_back(
                    {d->centre() + f.to_world(Vec3(r * std::cos(phi), r * std::sin(phi), 0.0f)), d->normal(), a});
            } else {
                const auto& sp = dynamic_cast<const Sphere&>(*c.shape);
                const float z = 1.0f - 2.0f * s, rr = std::sqrt(std::max(0.0f, 1.0f - z * z)), phi = 2.0f * kPi * t;
                const Vec3 dir(rr * std::cos(phi), rr * std::sin(phi), z);
                out.push_back({sp.centre() + sp.radius() * dir, c.inward ? -dir : dir, a});
            }
        }
    return out;
}

// The chi-square test of sample_li's directions from p against pdf_li. The expected count of each (cos theta, phi)
// cell is pdf_li integrated over the cell's solid angle, worked out over the light's surface instead (dw = |cos_l|
// dA / d^2, for the points p sees from their emitting side), where a fine grid of the surface resolves the edges of
// the light that make the density jump on the sphere of directions.
void check_chi_square(const Case& c, const Point3& p, std::uint64_t seed, double level) {
    constexpr int kCos = 16, kPhi = 32, kCells = kCos * kPhi;
    auto cell = [](const Vec3& w) {
        double phi = std::atan2(double(w.y), double(w.x));
        if (phi < 0.0) phi += 2.0 * std::numbers::pi;
        const int i =
            std::clamp(static_cast<int>((std::clamp(double(w.z), -1.0, 1.0) + 1.0) * 0.5 * kCos), 0, kCos - 1);
        const int j = std::clamp(static_cast<int>(phi / (2.0 * std::numbers::pi) * kPhi), 0, kPhi - 1);
        return i * kPhi + j;
    };
    const int n = 200000 / test::kSampleScale;
    std::vector<double> observed(kCells + 1, 0.0), expected(kCells + 1, 0.0);
    Rng rng(seed);
    for (int k = 0; k < n; ++k) {
        const auto s = c.emitter->sample_li(p, rng.uniform2());
        observed[s ? cell(s->wi) : kCells] += 1.0;
    }
    double integral = 0.0;
    for (const AreaPoint& y : surface_points(c, 1500 / test::kSampleScale)) {
        const Vec3 d = y.y - p;
        const double dist2 = glm::dot(d, d);
        const Vec3 w = d / float(std::sqrt(dist2));
        const float cos_l = -glm::dot(w, y.n);
        if (!(cos_l > 0.0f) && !c.two_sided) continue;
        // From outside, a sphere shows p only the points facing it.
        if (const auto* sp = dynamic_cast<const Sphere*>(c.shape.get());
            sp && !c.inward && glm::dot(y.y - sp->centre(), p - y.y) <= 0.0f)
            continue;
        const double pdf = c.emitter->pdf_li(p, w, y.y, y.n);
        const double mass = pdf * std::abs(cos_l) * y.area / dist2;
        expected[cell(w)] += mass * n;
        integral += mass;
    }
    expected[kCells] = std::max(0.0, 1.0 - integral) * n;
    for (int b = 0; b <= kCells; ++b)
        if (observed[b] > 0.0 && expected[b] < 1e-3 * n / kCells)
            FAIL(c.name << ": draws in cell " << b << " where pdf_li has none");
    shading_testing::ChiSquareResult r;
    shading_testing::chi_square_from_counts(observed, expected, r);
    INFO(c.name << ": chi2 " << r.statistic << " dof " << r.dof << " p " << r.p_value << " pdf integral " << integral
                << "; worst " << r.worst);
    CHECK(r.p_value > level);
    CHECK(integral == Approx(1.0).margin(2e-3));
}

// The irradiance at p (normal n) from sample_li: the mean of L cos / pdf with its standard error.
std::pair<double, double> irradiance(const Emitter& e, const Point3& p, const Normal3& n, int count) {
    Rng rng(7);
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < count; ++i) {
        double x = 0.0;
        if (const auto s = e.sample_li(p, rng.uniform2()))
            x = double(s->radiance.r) * std::max(0.0, double(glm::dot(s->wi, n))) / double(s->pdf);
        sum += x;
        sum2 += x * x;
    }
    const double mean = sum / count;
    return {mean, std::sqrt(std::max(0.0, sum2 / count - mean * mean) / (count - 1))};
}

}  // namespace

TEST_CASE("Area lights sample directions by their pdf_li", "[emitter]") {
    const std::vector<Case> cases{quad_case(false), quad_case(true), disk_case(),
                                  sphere_case(Point3(0.2f, 2.0f, -0.4f), 0.7f, false),
                                  sphere_case(Point3(0.1f, 0.3f, -0.2f), 1.5f, true)};
    // Sidak over every case and viewpoint, so that the family fails by chance once in a thousand runs.
    const double level = shading_testing::sidak_level(1e-3, static_cast<int>(cases.size()) * 2);
    std::uint64_t seed = 11;
    for (const Case& c : cases)
        for (const Point3& p : {Point3(0.0f), Point3(0.35f, 0.2f, 0.1f)}) check_chi_square(c, p, seed++, level);
}

TEST_CASE("A uniform environment samples the sphere of directions uniformly", "[emitter]") {
    const UniformEnvironment env(RGB(1.0f), 1.0f);
    Rng rng(5);
    const shading_testing::ChiSquareResult r = shading_testing::chi_square_test(
        [&](Rng& g) -> std::optional<Vec3> { return env.sample_li(Point3(0.0f), g.uniform2())->wi; },
        [&](const Vec3& w) { return double(env.pdf_li(Point3(0.0f), w, Point3(0.0f), w)); }, {}, rng,
        100000 / test::kSampleScale);
    INFO("chi2 " << r.statistic << " p " << r.p_value);
    CHECK(r.p_value > 1e-3);
    CHECK(r.pdf_integral == Approx(1.0).margin(1e-3));
}

TEST_CASE("Irradiance under sphere disk and quad lights matches the closed forms", "[emitter]") {
    const int n = 40000 / test::kSampleScale;
    const Point3 p(0.0f);
    const Normal3 up(0.0f, 1.0f, 0.0f);
    auto check = [](const char* what, std::pair<double, double> got, double expected) {
        INFO(what << ": " << got.first << " +- " << got.second << ", expected " << expected);
        CHECK(std::abs(got.first - expected) <= 3.0 * got.second + 1e-6 * expected);
        CHECK(got.second < 0.02 * expected);  // the estimate is informative
    };
    {  // a sphere of radius r whose centre is at distance d straight above: E = pi L (r / d)^2
        const float r = 0.5f, d = 2.0f;
        const Case c = sphere_case(Point3(0.0f, d, 0.0f), r, false);
        check("sphere overhead", irradiance(*c.emitter, p, up, n), kPi * (r / d) * (r / d));
    }
    {  // a sphere off to the side, lit wholly above the horizon: still pi L (r / d)^2 cos(angle to the centre)
        const Point3 centre(1.0f, 1.5f, 0.5f);
        const float r = 0.4f;
        const Case c = sphere_case(centre, r, false);
        const float d = glm::length(centre);
        check("sphere aside", irradiance(*c.emitter, p, up, n), kPi * (r / d) * (r / d) * (centre.y / d));
    }
    {  // a coaxial disk facing down at height h: E = pi L r^2 / (h^2 + r^2)
        EmitterShape s;
        s.kind = EmitterShape::Kind::disk;
        s.centre = Point3(0.0f, 1.2f, 0.0f);
        s.normal = Normal3(0.0f, -1.0f, 0.0f);
        s.radius = 0.9f;
        const AreaEmitter e(s, RGB(1.0f), false);
        check("disk", irradiance(e, p, up, n), kPi * 0.81 / (1.44 + 0.81));
    }
    {  // a rectangle facing down, not centred: Lambert's polygon formula E = L/2 sum gamma_i (v_i x v_i+1 . n)/|.|
        const Point3 corner(-0.3f, 1.0f, -0.6f);
        const Vec3 u(0.9f, 0.0f, 0.0f), v(0.0f, 0.0f, 1.1f);  // u x v = -y: faces down
        const AreaEmitter e(quad_triangles(corner, u, v), RGB(1.0f), false);
        const std::array<Vec3, 4> vs{corner, corner + u, corner + u + v, corner + v};
        double sum = 0.0;
        for (int i = 0; i < 4; ++i) {
            const glm::dvec3 a = glm::normalize(glm::dvec3(vs[i])), b = glm::normalize(glm::dvec3(vs[(i + 1) % 4]));
            const glm::dvec3 c = glm::cross(a, b);
            sum += std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)) * glm::normalize(c).y;
        }
        check("quad", irradiance(e, p, up, n), std::abs(0.5 * sum));
    }
}

TEST_CASE("Lights are chosen in proportion to their power", "[emitter]") {
    LightSet set;
    const Case a = sphere_case(Point3(0.0f, 3.0f, 0.0f), 1.0f, false);  // power pi * 4 pi
    EmitterShape s;
    s.kind = EmitterShape::Kind::sphere;
    s.radius = 2.0f;
    s.centre = Point3(5.0f, 0.0f, 0.0f);
    auto b = std::make_shared<AreaEmitter>(s, RGB(0.5f), false);  // 0.5 * 4 * the first's area
    set.add(a.emitter);
    set.add(b);
    set.add(std::make_shared<AreaEmitter>(s, RGB(0.0f), false));  // no power: never chosen
    set.finish();
    CHECK(set.entries()[0].probability == Approx(1.0 / 3.0));
    CHECK(set.entries()[1].probability == Approx(2.0 / 3.0));
    CHECK(set.entries()[2].probability == 0.0f);
    int first = 0;
    const int n = 30000;
    for (int i = 0; i < n; ++i) {
        const LightSet::Entry* e = set.choose((i + 0.5f) / n);
        REQUIRE(e != nullptr);
        REQUIRE(e != &set.entries()[2]);
        first += e == &set.entries()[0];
    }
    CHECK(first == Approx(n / 3.0).margin(2));
}
