#pragma once
// The re-intersection harness of the spawn tests (after pbrt-v4's Reintersect test), shared by
// tests/geometry/spawn_test.cpp and tests/accel/spawn_test.cpp (which adds meshes over kd-trees).
//
// For one scene (a convex solid, or a flat shape) it makes surface hits with rays from outside, spawns
// rays from them with spawn.hpp and counts failures: an outward ray (or any ray from a flat shape) that
// hits anything; an inward ray that misses the solid or hits it closer than half the exact chord (its own
// surface again), unless the chord is shorter than the offset itself (counted apart); a connection ray
// (spawn_ray_to, to another hit on the solid or to a point outside) that anything blocks. The same rays
// from the naive point o + t d with a fixed epsilon of 1e-4 are the control.
#include <rtlab/core/aabb.hpp>
#include <rtlab/core/math.hpp>
#include <rtlab/core/ray.hpp>
#include <rtlab/geometry/quad.hpp>
#include <rtlab/geometry/shape.hpp>
#include <rtlab/geometry/spawn.hpp>
#include <rtlab/geometry/triangle_mesh.hpp>

#include <glm/gtc/matrix_inverse.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace rtlab::spawn_check {

using DVec3 = glm::dvec3;

/// Where the line p + t d (d not normalised) is inside a convex solid, exactly (in double): [enter, exit],
/// empty when enter > exit.
struct Span {
    double enter, exit;
    bool empty() const { return !(enter <= exit); }
};
using SpanFn = std::function<Span(const DVec3& p, const DVec3& d)>;
inline constexpr double kInf = std::numeric_limits<double>::infinity();

inline SpanFn sphere_span(const Point3& centre, float radius) {
    return [c = DVec3(centre), r = double(radius)](const DVec3& p, const DVec3& d) {
        const DVec3 oc = p - c;
        const double a = glm::dot(d, d), b = glm::dot(oc, d), cc = glm::dot(oc, oc) - r * r;
        const double disc = b * b - a * cc;
        if (disc < 0.0) return Span{kInf, -kInf};
        return Span{(-b - std::sqrt(disc)) / a, (-b + std::sqrt(disc)) / a};
    };
}

/// A convex polytope as planes n . x <= offset (n outward).
struct Plane {
    DVec3 n;
    double offset;
};
inline Plane plane_through(const Point3& a, const Point3& b, const Point3& c) {
    const DVec3 n = glm::normalize(glm::cross(DVec3(b) - DVec3(a), DVec3(c) - DVec3(a)));
    return {n, glm::dot(n, DVec3(a))};
}
inline SpanFn polytope_span(std::vector<Plane> planes) {
    return [planes = std::move(planes)](const DVec3& p, const DVec3& d) {
        Span s{-kInf, kInf};
        for (const Plane& pl : planes) {
            const double dn = glm::dot(pl.n, d), dist = pl.offset - glm::dot(pl.n, p);
            if (dn > 0.0)
                s.exit = std::min(s.exit, dist / dn);
            else if (dn < 0.0)
                s.enter = std::max(s.enter, dist / dn);
            else if (dist < 0.0)
                return Span{kInf, -kInf};
        }
        return s;
    };
}

/// A capped cylinder from base to top.
inline SpanFn cylinder_span(const Point3& base, const Point3& top, float radius) {
    const DVec3 b(base), axis = glm::normalize(DVec3(top) - DVec3(base));
    const double h = glm::length(DVec3(top) - DVec3(base)), r = radius;
    return [b, axis, h, r](const DVec3& p, const DVec3& d) {
        const DVec3 w = p - b;
        const double wz = glm::dot(w, axis), dz = glm::dot(d, axis);
        const DVec3 wp = w - wz * axis, dp = d - dz * axis;
        Span s{-kInf, kInf};
        const double a = glm::dot(dp, dp), bb = glm::dot(wp, dp), c = glm::dot(wp, wp) - r * r;
        if (a > 0.0) {
            const double disc = bb * bb - a * c;
            if (disc < 0.0) return Span{kInf, -kInf};
            s = {(-bb - std::sqrt(disc)) / a, (-bb + std::sqrt(disc)) / a};
        } else if (c > 0.0) {
            return Span{kInf, -kInf};
        }
        if (dz != 0.0) {
            const double t0 = -wz / dz, t1 = (h - wz) / dz;
            s.enter = std::max(s.enter, std::min(t0, t1));
            s.exit = std::min(s.exit, std::max(t0, t1));
        } else if (wz < 0.0 || wz > h) {
            return Span{kInf, -kInf};
        }
        return s;
    };
}

/// The solid inside an affine transform: the line's parameters are the same in object space.
inline SpanFn transformed_span(SpanFn inner, const Mat4& object_to_world) {
    const glm::dmat4 inv = glm::inverse(glm::dmat4(object_to_world));
    return [inner = std::move(inner), inv](const DVec3& p, const DVec3& d) {
        return inner(DVec3(inv * glm::dvec4(p, 1.0)), DVec3(inv * glm::dvec4(d, 0.0)));
    };
}

/// The first parameter in (tmin, tmax) where the ray crosses the solid's surface, or -1 when it crosses none.
inline double first_crossing(const SpanFn& solid, const Ray& r) {
    const Span s = solid(DVec3(r.origin), DVec3(r.direction));
    if (s.empty()) return -1.0;
    for (double t : {s.enter, s.exit})
        if (t > r.tmin && t < r.tmax) return t;
    return -1.0;
}

/// The planes of a closed convex triangle mesh.
inline std::vector<Plane> mesh_planes(const TriangleMesh& mesh) {
    std::vector<Plane> planes;
    for (std::size_t i = 0; i < mesh.triangle_count(); ++i)
        planes.push_back(plane_through(mesh.corner(i, 0), mesh.corner(i, 1), mesh.corner(i, 2)));
    return planes;
}

/// The cube [-0.5, 0.5]^3 through an affine transform as 12 triangles (8 shared vertices, outward winding):
/// large triangles, where the hit point is no bigger than the triangle.
inline TriangleMesh cube_mesh(const Mat4& m) {
    TriangleMesh mesh;
    for (int c = 0; c < 8; ++c)
        mesh.positions.push_back(
            Point3(m * Vec4((c & 1) ? 0.5f : -0.5f, (c & 2) ? 0.5f : -0.5f, (c & 4) ? 0.5f : -0.5f, 1.0f)));
    // Faces as corner quadruples, counter-clockwise seen from outside.
    const int faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    for (const auto& f : faces) {
        mesh.triangles.push_back({std::uint32_t(f[0]), std::uint32_t(f[1]), std::uint32_t(f[2])});
        mesh.triangles.push_back({std::uint32_t(f[0]), std::uint32_t(f[2]), std::uint32_t(f[3])});
    }
    if (glm::determinant(Mat3(m)) < 0.0f)
        for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
    return mesh;
}

/// An axis-aligned box as six Quads whose edges meet exactly (lo + extent == hi in floats), and its planes.
/// hi is moved by a float step where it must be.
inline std::vector<std::shared_ptr<const Shape>> quad_box(const Point3& lo, Point3& hi, std::vector<Plane>* planes) {
    Vec3 e = hi - lo;
    for (int a = 0; a < 3; ++a)
        while (lo[a] + e[a] != hi[a]) hi[a] = lo[a] + e[a], e[a] = hi[a] - lo[a];
    std::vector<std::shared_ptr<const Shape>> quads;
    for (int a = 0; a < 3; ++a) {
        const int a1 = (a + 1) % 3, a2 = (a + 2) % 3;
        Vec3 u(0.0f), v(0.0f);
        u[a1] = e[a1];
        v[a2] = e[a2];
        Point3 upper = lo;
        upper[a] = hi[a];
        quads.push_back(std::make_shared<Quad>(upper, u, v));  // u x v = +axis
        quads.push_back(std::make_shared<Quad>(lo, v, u));     // -axis
        DVec3 n(0.0);
        n[a] = 1.0;
        planes->push_back({n, double(hi[a])});
        planes->push_back({-n, -double(lo[a])});
    }
    return quads;
}

/// Shapes as one shape, by brute force (to put a closed set of quads or triangles in an Instance).
class Group final : public Shape {
public:
    explicit Group(std::vector<std::shared_ptr<const Shape>> shapes) : m_shapes(std::move(shapes)) {}
    AABB bounds() const override {
        AABB b;
        for (const auto& s : m_shapes) b.expand(s->bounds());
        return b;
    }
    bool intersect(const Ray& ray, SurfaceHit& hit) const override {
        Ray r = ray;
        bool found = false;
        for (const auto& s : m_shapes)
            if (s->intersect(r, hit)) found = true, r.tmax = hit.t;
        return found;
    }
    bool occluded(const Ray& ray) const override {
        for (const auto& s : m_shapes)
            if (s->occluded(ray)) return true;
        return false;
    }

private:
    std::vector<std::shared_ptr<const Shape>> m_shapes;
};

/// One test scene: the shapes (closest hit over all), the solid they bound (none for a flat shape), and a
/// bounding sphere to aim the rays that make the source hits.
struct Case {
    std::string name;
    std::vector<std::shared_ptr<const Shape>> shapes;
    SpanFn solid;  // empty: a flat shape, every spawned ray must miss
    Point3 centre;
    float radius;

    bool intersect(const Ray& ray, SurfaceHit& hit) const {
        Ray r = ray;
        bool found = false;
        for (const auto& s : shapes)
            if (s->intersect(r, hit)) found = true, r.tmax = hit.t;
        return found;
    }
    bool occluded(const Ray& ray) const {
        for (const auto& s : shapes)
            if (s->occluded(ray)) return true;
        return false;
    }
};

struct Counts {
    long outward = 0, outward_fail = 0, outward_fail_fixed = 0;
    long inward = 0, inward_fail = 0, inward_fail_fixed = 0, inward_short = 0, inward_far = 0;
    long connect = 0, connect_fail = 0, connect_fail_fixed = 0, connect_short = 0;
    long failures() const { return outward_fail + inward_fail + connect_fail; }
    long failures_fixed() const { return outward_fail_fixed + inward_fail_fixed + connect_fail_fixed; }
    void add(const Counts& c) {
        outward += c.outward, outward_fail += c.outward_fail, outward_fail_fixed += c.outward_fail_fixed;
        inward += c.inward, inward_fail += c.inward_fail, inward_fail_fixed += c.inward_fail_fixed;
        inward_short += c.inward_short, inward_far += c.inward_far;
        connect += c.connect, connect_fail += c.connect_fail, connect_fail_fixed += c.connect_fail_fixed;
        connect_short += c.connect_short;
    }
};

inline constexpr float kFixedEpsilon = 1e-4f;

struct Source {
    SurfaceHit hit;
    Point3 naive;  // o + t d of the ray that found it
};

inline Vec3 random_unit(std::mt19937& rng) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const float z = 1.0f - 2.0f * u(rng), phi = 2.0f * kPi * u(rng);
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

/// A direction on n's side: uniform over the hemisphere, or grazing (cosine 1e-4 to 1e-2 from the plane).
inline Vec3 outward_direction(std::mt19937& rng, const Normal3& n, bool grazing) {
    Vec3 w = random_unit(rng);
    if (glm::dot(w, n) < 0.0f) w = -w;
    if (!grazing) return w;
    std::uniform_real_distribution<float> lg(-4.0f, -2.0f);
    Vec3 tangent = w - glm::dot(w, n) * n;
    if (!(glm::dot(tangent, tangent) > 0.0f)) return w;
    tangent = glm::normalize(tangent);
    const float c = std::pow(10.0f, lg(rng));
    return glm::normalize(tangent * std::sqrt(1.0f - c * c) + c * n);
}

/// `sources` hits found by rays from outside the case's bounding sphere aimed inside it; per hit,
/// 2 uniform and 2 grazing outward rays, the same reversed inward, one connection to a point outside and
/// (solids) one to the next hit.
///
/// Outward rays (and every ray from a flat shape) must hit nothing. An inward ray must hit the solid no
/// nearer than half the exact distance from its own origin to the far side (closer is its own surface
/// again); a connection must not be blocked. Rays whose offset origin or end has jumped past the far side
/// of a thin solid (the exact geometry of the offset ray differs from that of the ideal one: the far side
/// is no further than the offset, or a connection's end is outside the solid) are counted apart ("short").
/// The fixed-epsilon control is judged by the ideal geometry on the same rays (the short ones left out).
inline Counts run(const Case& c, int sources, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<Source> found;
    for (int attempt = 0; static_cast<int>(found.size()) < sources && attempt < 50 * sources; ++attempt) {
        const Point3 origin = c.centre + 3.0f * c.radius * random_unit(rng);
        const Point3 target = c.centre + 0.7f * c.radius * std::cbrt(u(rng)) * random_unit(rng);
        const Ray ray{origin, target - origin};
        SurfaceHit hit;
        if (c.intersect(ray, hit)) found.push_back({hit, ray.at(hit.t)});
    }
    Counts k;
    const bool solid = static_cast<bool>(c.solid);
    const bool debug = std::getenv("SPAWN_DEBUG") != nullptr;
    // The parameter of the first hit, -1 for a miss.
    auto first_hit = [&](const Ray& r) {
        SurfaceHit h;
        return c.intersect(r, h) ? double(h.t) : -1.0;
    };
    // A connection is short when the exact solid has a surface within the offset ray's range.
    auto crosses = [&](const Ray& r) { return solid && first_crossing(c.solid, r) >= 0.0; };
    auto fixed_segment = [](const Point3& from, const Point3& to) {
        const float len = glm::length(to - from);
        return Ray{from, (to - from) / len, kFixedEpsilon, len - kFixedEpsilon};
    };
    for (std::size_t i = 0; i < found.size(); ++i) {
        const SurfaceHit& s = found[i].hit;
        const Point3 naive = found[i].naive;
        const Normal3 n = s.geometric_normal;
        for (int j = 0; j < 4; ++j) {
            const Vec3 w = outward_direction(rng, n, j >= 2);
            ++k.outward;
            if (first_hit(spawn_ray(s, w)) >= 0.0) ++k.outward_fail;
            if (first_hit(Ray{naive, w, kFixedEpsilon, kInfinity}) >= 0.0) ++k.outward_fail_fixed;
            const Ray in = spawn_ray(s, -w);
            const Ray in_fixed{naive, -w, kFixedEpsilon, kInfinity};
            ++k.inward;
            if (!solid) {
                if (first_hit(in) >= 0.0) ++k.inward_fail;
                if (first_hit(in_fixed) >= 0.0) ++k.inward_fail_fixed;
                continue;
            }
            const double offset = glm::length(DVec3(in.origin) - DVec3(s.point));
            const double expected = first_crossing(c.solid, in);
            if (expected <= offset) {
                ++k.inward_short;
                continue;
            }
            const double ours = first_hit(in);
            if (ours < 0.5 * expected)
                ++k.inward_fail;
            else if (ours > 1.5 * expected)
                ++k.inward_far;
            const Span ideal = c.solid(DVec3(s.point), DVec3(-w));
            if (first_hit(in_fixed) < 0.5 * ideal.exit) ++k.inward_fail_fixed;
            if (debug && ours > 1.5 * expected && k.inward_far < 4)
                std::printf(
                    "  inward far: expected %.9g offset %.9g cos %.3g hit at %.9g origin %.9g %.9g %.9g dir %.9g %.9g "
                    "%.9g\n",
                    expected, offset, double(glm::dot(-w, n)), ours, in.origin.x, in.origin.y, in.origin.z, -w.x, -w.y,
                    -w.z);
            if (debug && ours < 0.5 * expected && k.inward_fail < 6)
                std::printf(
                    "  inward fail: expected %.9g offset %.9g cos %.3g hit at %.9g origin %a %a %a dir %a %a %a\n",
                    expected, offset, double(glm::dot(-w, n)), ours, in.origin.x, in.origin.y, in.origin.z,
                    in.direction.x, in.direction.y, in.direction.z);
        }
        auto connect = [&](const Ray& ray, const Ray& fixed) {
            if (crosses(ray)) {
                ++k.connect_short;
                return;
            }
            ++k.connect;
            if (c.occluded(ray)) ++k.connect_fail;
            if (c.occluded(fixed)) ++k.connect_fail_fixed;
        };
        const Point3 target = s.point + c.radius * outward_direction(rng, n, false);
        connect(spawn_ray_to(s, target), fixed_segment(naive, target));
        if (solid && i + 1 < found.size())
            connect(spawn_ray_to(s, found[i + 1].hit), fixed_segment(naive, found[i + 1].naive));
    }
    return k;
}

inline void print_header() {
    std::printf("%-26s %7s %5s %5s | %7s %5s %5s %5s %5s | %7s %5s %5s %5s\n", "case", "outward", "fail", "fixed",
                "inward", "fail", "fixed", "short", "far", "connect", "fail", "fixed", "short");
}
inline void print(const std::string& name, const Counts& k) {
    std::printf("%-26s %7ld %5ld %5ld | %7ld %5ld %5ld %5ld %5ld | %7ld %5ld %5ld %5ld\n", name.c_str(), k.outward,
                k.outward_fail, k.outward_fail_fixed, k.inward, k.inward_fail, k.inward_fail_fixed, k.inward_short,
                k.inward_far, k.connect, k.connect_fail, k.connect_fail_fixed, k.connect_short);
    std::fflush(stdout);
}

/// The scales of the tests: a shape of size s placed at distance s from the world's origin for s = 1e-4,
/// 1, 1e5, 1e6 (required: no failure), and two mixed ones: a unit shape a million units out, only 16 float
/// steps across, and a 1e-4 shape at distance 1 (required: fewer failures than the fixed epsilon).
struct Scale {
    const char* name;
    float size;
    float distance;
    bool mixed = false;
};
inline const std::vector<Scale>& scales() {
    static const std::vector<Scale> s = {{"1e-4", 1e-4f, 1e-4f},
                                         {"1", 1.0f, 1.0f},
                                         {"1e5", 1e5f, 1e5f},
                                         {"1e6", 1e6f, 1e6f},
                                         {"1 at 1e6", 1.0f, 1e6f, true},
                                         {"1e-4 at 1", 1e-4f, 1.0f, true}};
    return s;
}
inline Point3 place(const Scale& s) { return s.distance * Point3(0.6f, -0.48f, 0.64f); }

}  // namespace rtlab::spawn_check
