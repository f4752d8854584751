#include <rtlab/core/error.hpp>
#include <rtlab/core/rng.hpp>
#include <rtlab/geometry/box.hpp>
#include <rtlab/geometry/cylinder.hpp>
#include <rtlab/geometry/disk.hpp>
#include <rtlab/geometry/instance.hpp>
#include <rtlab/geometry/quad.hpp>
#include <rtlab/geometry/sphere.hpp>
#include <rtlab/geometry/triangle_shape.hpp>

#include <catch2/catch.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

using namespace rtlab;

namespace {
SurfaceHit must_hit(const Shape& s, const Ray& r) {
    SurfaceHit h;
    REQUIRE(s.intersect(r, h));
    REQUIRE(s.occluded(r));
    return h;
}
bool misses(const Shape& s, const Ray& r) {
    SurfaceHit h;
    return !s.intersect(r, h) && !s.occluded(r);
}
// Every field of a hit record but uv, bit for bit.
void check_same_hit(const SurfaceHit& a, const SurfaceHit& b) {
    CHECK(a.t == b.t);
    CHECK(a.point == b.point);
    CHECK(a.point_error == b.point_error);
    CHECK(a.object_point == b.object_point);
    CHECK(a.geometric_normal == b.geometric_normal);
    CHECK(a.shading_normal == b.shading_normal);
    CHECK(a.tangent == b.tangent);
    CHECK(a.front_face == b.front_face);
    CHECK(a.shape == b.shape);
}
float log_uniform(Rng& rng, float lo_exp, float hi_exp) {
    return std::pow(10.0f, lo_exp + (hi_exp - lo_exp) * rng.uniform());
}
Vec3 random_direction(Rng& rng) {
    for (;;) {
        const Vec3 v(2.0f * rng.uniform() - 1.0f, 2.0f * rng.uniform() - 1.0f, 2.0f * rng.uniform() - 1.0f);
        const float l = glm::length(v);
        if (l > 0.1f && l <= 1.0f) return v / l;
    }
}

}  // namespace

TEST_CASE("sphere: outside, inside, grazing and from the surface", "[shapes]") {
    const Sphere s({0, 0, 0}, 2.0f);
    SurfaceHit h = must_hit(s, Ray{{0, 0, -10}, {0, 0, 1}});
    CHECK(h.t == Approx(8.0f));
    CHECK(h.geometric_normal.z == Approx(-1.0f));
    CHECK(h.front_face);
    h = must_hit(s, Ray{{0.5f, 0, 0}, {1, 0, 0}});  // from inside: the exit, seen from the back
    CHECK(h.t == Approx(1.5f));
    CHECK_FALSE(h.front_face);
    CHECK(must_hit(s, Ray{{2.0f * (1.0f - 1e-6f), 0, -10}, {0, 0, 1}}).t ==
          Approx(10.0f).epsilon(1e-2));                                 // grazing inside
    CHECK(misses(s, Ray{{2.0f * (1.0f + 1e-5f), 0, -10}, {0, 0, 1}}));  // grazing outside
    // Leaving the surface outwards with tmin = 0: no hit further than rounding from the origin.
    const Point3 on = glm::normalize(Vec3(1, 2, 3)) * 2.0f;
    SurfaceHit self;
    if (s.intersect(Ray{on, glm::normalize(on)}, self)) CHECK(self.t < 1e-5f);
    CHECK(misses(s, Ray{on, glm::normalize(on), 1e-4f, kInfinity}));
    // Entering from the surface: the far side at t = 4 (through the centre).
    CHECK(must_hit(s, Ray{on, -glm::normalize(on), 1e-4f, kInfinity}).t == Approx(4.0f));
    CHECK_THROWS_AS(Sphere({0, 0, 0}, 0.0f), Error);
}

TEST_CASE("sphere: huge and tiny scales and far offsets keep precision", "[shapes]") {
    for (float r : {1e-4f, 1.0f, 1e5f}) {
        for (float offset : {0.0f, 1e6f}) {
            const Point3 c(offset, offset, 0);
            const Sphere s(c, r);
            const float distance = 1e3f * r;
            SurfaceHit h = must_hit(s, Ray{c + Vec3(0, 0, -distance), {0, 0, 1}});
            INFO("r " << r << " offset " << offset);
            // At an offset of 1e6 a float step is 0.06: the hit point cannot be better than that.
            const float tol = std::max(1e-5f * distance, offset > 0 ? 0.2f : 0.0f);
            CHECK(std::abs(h.t - (distance - r)) <= tol);
            CHECK(std::isfinite(h.uv.x));
            // A far ray aimed just inside the silhouette still hits (no cancellation in the discriminant).
            const Vec3 target = c + Vec3(0.999f * r, 0, 0);
            const Point3 origin = c + Vec3(0, 0, -distance);
            if (offset == 0.0f) CHECK(s.occluded(Ray{origin, target - origin}));
        }
    }
}

TEST_CASE("sphere: lines just wide of it or just through it keep the full test's answer", "[shapes]") {
    // The hard case for the cheap rejection of wide lines: perpendicular distances a hair above and below the
    // radius, from near and far origins, at tiny and huge scales, with unnormalised directions. The reference is
    // the full test (perpendicular, discriminant, stable roots) written out here as the sphere computes it.
    auto full = [](const Point3& centre, float r, const Ray& ray, float& t) {
        const Vec3 oc = ray.origin - centre;
        const float a = glm::dot(ray.direction, ray.direction), b = glm::dot(oc, ray.direction);
        const float c = glm::dot(oc, oc) - r * r;
        if (b > 0.0f && c > 0.0f && ray.tmin >= 0.0f) return false;
        const float perp = glm::length(oc - (b / a) * ray.direction);
        const float disc = a * (r - perp) * (r + perp);
        float t0, t1;
        if (!geometry::stable_roots(a, b, c, disc, t0, t1)) return false;
        if (t0 > ray.tmin && t0 < ray.tmax)
            t = t0;
        else if (t1 > ray.tmin && t1 < ray.tmax)
            t = t1;
        else
            return false;
        return true;
    };
    Rng rng(2026, 11);
    int hits = 0, misses_seen = 0;
    for (int k = 0; k < 20000; ++k) {
        const float scale = log_uniform(rng, -6.0f, 6.0f);
        const Point3 centre = random_direction(rng) * (scale * log_uniform(rng, -3.0f, 3.0f));
        const float r = scale * log_uniform(rng, -1.0f, 1.0f);
        const Sphere sphere(centre, r);
        // A line at r (1 + e) from the centre, e of either sign from 1e-8 to 1e-2.
        const Vec3 towards = random_direction(rng);
        Vec3 side = glm::cross(towards, random_direction(rng));
        side /= glm::length(side);
        const float e = (rng.uniform() < 0.5f ? -1.0f : 1.0f) * log_uniform(rng, -8.0f, -2.0f);
        const Point3 closest = centre + side * (r * (1.0f + e));
        const Point3 origin = closest - towards * (r * log_uniform(rng, -2.0f, 4.0f));
        const Ray ray{origin, towards * log_uniform(rng, -3.0f, 3.0f), 0.0f, kInfinity};
        float want_t = 0.0f, got_t = 0.0f;
        const bool want = full(centre, r, ray, want_t);
        INFO("ray " << k);
        REQUIRE(sphere.intersect_distance(ray, got_t) == want);
        REQUIRE(sphere.occluded(ray) == want);
        if (want) REQUIRE(std::bit_cast<std::uint32_t>(got_t) == std::bit_cast<std::uint32_t>(want_t));
        (want ? hits : misses_seen) += 1;
    }
    CHECK(hits > 5000);
    CHECK(misses_seen > 5000);
}

TEST_CASE("sphere uv puts the north pole at v = 1 and is continuous in u", "[shapes]") {
    const Sphere s({0, 0, 0}, 1.0f);
    CHECK(must_hit(s, Ray{{0, 5, 0}, {0, -1, 0}}).uv.y == Approx(1.0f));
    CHECK(must_hit(s, Ray{{0, -5, 0}, {0, 1, 0}}).uv.y == Approx(0.0f).margin(1e-6));
    const SurfaceHit eq = must_hit(s, Ray{{-5, 0, 0}, {1, 0, 0}});  // -x: u = 0 or 1 (the seam)
    CHECK((eq.uv.x == Approx(0.0f).margin(1e-6) || eq.uv.x == Approx(1.0f)));
    CHECK(must_hit(s, Ray{{5, 0, 0}, {-1, 0, 0}}).uv.x == Approx(0.5f));
    const SurfaceHit h = must_hit(s, Ray{{0.3f, 0.2f, -5}, {0, 0, 1}});
    CHECK(std::abs(glm::dot(h.tangent, h.shading_normal)) < 1e-5f);
    CHECK(glm::length(h.tangent) == Approx(1.0f));
}

TEST_CASE("cylinder: side, caps, open tube and any axis", "[shapes]") {
    const Cylinder c({0, 0, 0}, {0, 0, 4}, 1.0f, true);
    SurfaceHit h = must_hit(c, Ray{{-5, 0, 2}, {1, 0, 0}});
    CHECK(h.t == Approx(4.0f));
    CHECK(h.geometric_normal.x == Approx(-1.0f));
    CHECK(h.uv.y == Approx(0.5f));
    h = must_hit(c, Ray{{0.2f, 0.1f, -3}, {0, 0, 1}});  // along the axis: the base cap
    CHECK(h.t == Approx(3.0f));
    CHECK(h.geometric_normal.z == Approx(-1.0f));
    CHECK(misses(c, Ray{{-5, 0, 5}, {1, 0, 0}}));  // above the top
    const Cylinder open({0, 0, 0}, {0, 0, 4}, 1.0f, false);
    CHECK(misses(open, Ray{{0.2f, 0.1f, -3}, {0, 0, 1}}));  // along the axis through an open tube
    h = must_hit(open, Ray{{0, 0, 2}, {1, 0, 0}});          // from inside the tube: its inner wall
    CHECK(h.t == Approx(1.0f));
    CHECK_FALSE(h.front_face);
    // A tilted cylinder from (1,1,1) along (1,1,1): a ray perpendicular to the axis through its middle.
    const Vec3 axis = glm::normalize(Vec3(1, 1, 1));
    const Cylinder tilted({1, 1, 1}, Point3(1, 1, 1) + 6.0f * axis, 0.5f, true);
    const Point3 mid = Point3(1, 1, 1) + 3.0f * axis;
    const Vec3 across = glm::normalize(glm::cross(axis, Vec3(0, 0, 1)));
    h = must_hit(tilted, Ray{mid - 4.0f * across, across});
    CHECK(h.t == Approx(3.5f));
    CHECK(glm::dot(h.geometric_normal, -across) == Approx(1.0f));
}

TEST_CASE("disk and quad: inside, edges, outside and parallel", "[shapes]") {
    const Disk d({0, 0, 1}, {0, 0, 2}, 1.0f);
    CHECK(must_hit(d, Ray{{0.5f, 0.5f, 3}, {0, 0, -1}}).t == Approx(2.0f));
    CHECK(misses(d, Ray{{0.8f, 0.8f, 3}, {0, 0, -1}}));
    CHECK(misses(d, Ray{{-5, 0, 1}, {1, 0, 0}}));  // in its plane
    const Quad q({0, 0, 0}, {2, 0, 0}, {0, 3, 0});
    SurfaceHit h = must_hit(q, Ray{{0.5f, 2.25f, 1}, {0, 0, -1}});
    CHECK(h.uv.x == Approx(0.25f));
    CHECK(h.uv.y == Approx(0.75f));
    CHECK(h.geometric_normal.z == Approx(1.0f));
    CHECK(must_hit(q, Ray{{2, 3, 1}, {0, 0, -1}}).uv == Vec2(1, 1));  // the far corner is inside
    CHECK(misses(q, Ray{{2.01f, 1, 1}, {0, 0, -1}}));
    CHECK_THROWS_AS(Quad({0, 0, 0}, {1, 0, 0}, {2, 0, 0}), Error);
}

TEST_CASE("annulus: the hole misses, the ring hits, u runs from the hole's edge to the rim", "[shapes]") {
    // Saturn's rings: inner radius 2, outer 4, in the plane z = 0 seen from above.
    const Disk ring({0, 0, 0}, {0, 0, 1}, 4.0f, 2.0f);
    CHECK(misses(ring, Ray{{0, 0, 5}, {0, 0, -1}}));      // the centre is in the hole
    CHECK(misses(ring, Ray{{1.99f, 0, 5}, {0, 0, -1}}));  // just inside the hole
    CHECK(misses(ring, Ray{{0, 4.01f, 5}, {0, 0, -1}}));  // just beyond the rim
    CHECK_FALSE(ring.occluded(Ray{{0, 1.5f, 5}, {0, 0, -1}}));
    CHECK(ring.occluded(Ray{{0, 2.5f, 5}, {0, 0, -1}}));
    SurfaceHit h = must_hit(ring, Ray{{2.0f, 0, 5}, {0, 0, -1}});  // the hole's edge belongs to the ring
    CHECK(h.uv.x == Approx(0.0f).margin(1e-6));
    h = must_hit(ring, Ray{{0, -3.0f, 5}, {0, 0, -1}});
    CHECK(h.t == Approx(5.0f));
    CHECK(h.uv.x == Approx(0.5f));
    h = must_hit(ring, Ray{{4.0f, 0, 5}, {0, 0, -1}});
    CHECK(h.uv.x == Approx(1.0f));
    // A full disk keeps u = r / radius.
    const Disk full({0, 0, 0}, {0, 0, 1}, 4.0f);
    CHECK(must_hit(full, Ray{{0, -3.0f, 5}, {0, 0, -1}}).uv.x == Approx(0.75f));
    // The bounds are the outer disk's.
    CHECK(ring.bounds().hi.x == Approx(4.0f));
    CHECK_THROWS_AS(Disk({0, 0, 0}, {0, 0, 1}, 4.0f, 4.0f), Error);
    CHECK_THROWS_AS(Disk({0, 0, 0}, {0, 0, 1}, 4.0f, -1.0f), Error);
    CHECK_THROWS_AS(Disk({0, 0, 0}, {0, 0, 1}, 4.0f, std::nanf("")), Error);
}

TEST_CASE("box: faces, inside rays and normals", "[shapes]") {
    const Box b(AABB{{0, 0, 0}, {1, 2, 3}});
    SurfaceHit h = must_hit(b, Ray{{0.5f, 1, -2}, {0, 0, 1}});
    CHECK(h.t == Approx(2.0f));
    CHECK(h.geometric_normal == Normal3(0, 0, -1));
    h = must_hit(b, Ray{{0.5f, 1, 1}, {1, 0, 0}});  // from inside
    CHECK(h.t == Approx(0.5f));
    CHECK(h.geometric_normal == Normal3(1, 0, 0));
    CHECK_FALSE(h.front_face);
    CHECK(misses(b, Ray{{0.5f, 1, -2}, {0, 0, -1}}));
}

TEST_CASE("mesh triangle interpolates normals and uvs", "[shapes]") {
    auto mesh = std::make_shared<TriangleMesh>();
    mesh->positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh->normals = {glm::normalize(Vec3(-1, -1, 1)), {0, 0, 1}, {0, 0, 1}};
    mesh->uvs = {{0, 0}, {1, 0}, {0, 1}};
    mesh->triangles = {{0, 1, 2}};
    const TriangleShape t(mesh, 0);
    const SurfaceHit h = must_hit(t, Ray{{0.25f, 0.25f, 1}, {0, 0, -1}});
    CHECK(h.t == Approx(1.0f));
    CHECK(h.uv.x == Approx(0.25f));
    CHECK(h.geometric_normal == Normal3(0, 0, 1));
    CHECK(h.shading_normal.x < 0.0f);  // pulled towards corner 0's normal
    CHECK(glm::length(h.shading_normal) == Approx(1.0f));
    CHECK(std::abs(glm::dot(h.tangent, h.shading_normal)) < 1e-5f);
    CHECK_THROWS_AS(TriangleShape(mesh, 1), Error);
}

TEST_CASE("instances move, scale and keep normals perpendicular", "[shapes]") {
    const auto unit = std::make_shared<Sphere>(Point3(0, 0, 0), 1.0f);
    // An ellipsoid: x stretched by 3, moved to (10, 0, 0).
    const Mat4 m = glm::scale(glm::translate(Mat4(1.0f), Vec3(10, 0, 0)), Vec3(3, 1, 1));
    const Instance e(unit, m);
    CHECK(e.bounds().lo.x == Approx(7.0f));
    CHECK(e.bounds().hi.x == Approx(13.0f));
    SurfaceHit h = must_hit(e, Ray{{0, 0, 0}, {1, 0, 0}});
    CHECK(h.t == Approx(7.0f));
    CHECK(h.point.x == Approx(7.0f));
    // Off-axis hit: the normal of x^2/9 + y^2 = 1 at (x, y) is (x / 9, y) normalised.
    h = must_hit(e, Ray{{10 + 1.5f, 5, 0}, {0, -1, 0}});
    const Vec3 expected = glm::normalize(Vec3(1.5f / 9.0f, std::sqrt(1.0f - 0.25f), 0));
    CHECK(glm::length(h.geometric_normal - expected) < 1e-4f);
    CHECK_THROWS_AS(Instance(unit, Mat4(0.0f)), Error);
}

TEST_CASE("instances skip rays clear of their world box without changing a single answer", "[shapes]") {
    // The hard case: a box shape fills its own bounds, so rays grazing its faces and edges are the ones a
    // world-space bound too tight would lose. Rotations, non-uniform scales and far translations (where the
    // transforms' rounding is largest), rays aimed at corners, edges and faces with tiny offsets either way.
    Rng rng(2026, 24);
    const AABB inner{{-1.0f, -0.5f, -0.8f}, {0.7f, 1.1f, 0.9f}};
    const auto box = std::make_shared<Box>(inner);
    const auto sphere = std::make_shared<Sphere>(Point3(0.2f, -0.1f, 0.3f), 0.6f);
    int hits = 0, misses_seen = 0;
    for (int k = 0; k < 200; ++k) {
        const float far = k % 3 == 0 ? 0.0f : log_uniform(rng, -1.0f, k % 3 == 1 ? 2.0f : 5.0f);
        Mat4 m = glm::translate(Mat4(1.0f), random_direction(rng) * far);
        m = glm::rotate(m, 6.2831853f * rng.uniform(), random_direction(rng));
        m = glm::scale(
            m, Vec3(log_uniform(rng, -2.0f, 2.0f), log_uniform(rng, -2.0f, 2.0f), log_uniform(rng, -2.0f, 2.0f)));
        const Mat4 inverse = glm::inverse(m);  // what the instance itself computes
        for (const std::shared_ptr<const Shape>& shape :
             {std::shared_ptr<const Shape>(box), std::shared_ptr<const Shape>(sphere)}) {
            const Instance instance(shape, m);
            for (int i = 0; i < 300; ++i) {
                // A target near the inner bounds' surface: a corner, an edge or a face point, nudged by a few
                // float steps of its size in either direction.
                Point3 target;
                for (int a = 0; a < 3; ++a) {
                    const float pick = rng.uniform();
                    target[a] = pick < 0.35f  ? inner.lo[a]
                                : pick < 0.7f ? inner.hi[a]
                                              : inner.lo[a] + rng.uniform() * (inner.hi[a] - inner.lo[a]);
                    target[a] += (2.0f * rng.uniform() - 1.0f) * 1e-6f * static_cast<float>(rng.uniform_u32(64));
                }
                const Point3 world_target = Point3(m * Vec4(target, 1.0f));
                const float scale = glm::length(Vec3(m * Vec4(inner.hi - inner.lo, 0.0f))) + 1e-3f;
                const Point3 origin = world_target + random_direction(rng) * (scale * log_uniform(rng, -1.0f, 3.0f));
                const Vec3 dir = (world_target - origin) * log_uniform(rng, -3.0f, 3.0f);
                const float tmax = rng.uniform() < 0.8f ? kInfinity : log_uniform(rng, -3.0f, 3.0f);
                const Ray ray{origin, dir, 0.0f, tmax};
                const Ray local{Point3(inverse * Vec4(ray.origin, 1.0f)), Vec3(inverse * Vec4(ray.direction, 0.0f)),
                                ray.tmin, ray.tmax};
                SurfaceHit expected, got;
                const bool want = shape->intersect(local, expected);
                INFO("transform " << k << " ray " << i);
                REQUIRE(instance.intersect(ray, got) == want);
                REQUIRE(instance.occluded(ray) == shape->occluded(local));
                if (want) REQUIRE(std::bit_cast<std::uint32_t>(got.t) == std::bit_cast<std::uint32_t>(expected.t));
                (want ? hits : misses_seen) += 1;
            }
        }
    }
    CHECK(hits > 15000);
    CHECK(misses_seen > 15000);
}

TEST_CASE("two-step closest hits give the one-step record bit for bit whether deferred or not", "[shapes]") {
    // Sphere defers its record (its own two steps); Box and Quad take the defaults (intersect twice).
    const Sphere sphere({0.3f, -0.2f, 0.1f}, 1.3f);
    const Box box(AABB{{-1.0f, -0.5f, -0.8f}, {0.7f, 1.1f, 0.9f}});
    const Quad quad({-1.0f, 0.0f, -1.0f}, {2.0f, 0.0f, 0.0f}, {0.0f, 0.3f, 2.0f});
    CHECK(sphere.defers_record());
    CHECK_FALSE(box.defers_record());
    Rng rng(7);
    int hits = 0;
    for (const Shape* shape :
         {static_cast<const Shape*>(&sphere), static_cast<const Shape*>(&box), static_cast<const Shape*>(&quad)}) {
        for (int i = 0; i < 2000; ++i) {
            const Point3 o = 4.0f * Vec3(rng.uniform(), rng.uniform(), rng.uniform()) - 2.0f;
            const Vec3 d = Vec3(rng.uniform(), rng.uniform(), rng.uniform()) - 0.5f;
            // Half of the rays start inside the shape's bounds, a tenth are cut short by tmax.
            const Ray ray{o, d, 0.0f, i % 10 == 0 ? 0.5f : kInfinity};
            SurfaceHit one;
            const bool hit = shape->intersect(ray, one);
            float t = -1.0f;
            REQUIRE(shape->intersect_distance(ray, t) == hit);
            if (!hit) continue;
            ++hits;
            SurfaceHit two;
            shape->complete_hit(ray, t, two);
            CHECK(t == one.t);
            check_same_hit(two, one);
            CHECK(two.uv == one.uv);
            // Without uv: every other field the same, the uv left at its default where the shape skips it.
            SurfaceHit three;
            three.uv = Vec2(-7.0f);
            shape->complete_hit_without_uv(ray, t, three);
            check_same_hit(three, one);
            CHECK(three.uv == (shape == &sphere ? Vec2(0.0f) : one.uv));
        }
    }
    CHECK(hits > 600);  // 945 of the 6,000 rays hit (measured): enough that the comparison means something
}
