#pragma once
/// \brief Sphere, intersected with a cancellation-free quadratic.
#include <rtlab/geometry/quadratic.hpp>
#include <rtlab/geometry/shape.hpp>

namespace rtlab {

/// \brief Sphere by centre and radius. uv: u = longitude (0 at -x, increasing towards -z, i.e. eastwards
/// seen from +y), v = 1 at the north pole (+y) and 0 at the south pole, so an equirectangular planet map
/// whose first row is the north pole appears upright (textures take v = 0 as the image's bottom row).
class Sphere final : public Shape {
public:
    Sphere(const Point3& centre, float radius);
    AABB bounds() const override;
    bool intersect(const Ray& ray, SurfaceHit& hit) const override;
    // The two tests a scene's list runs on every sphere for every ray are inline, so that a caller holding a
    // Sphere (the render library's lists) runs them without a call.
    bool occluded(const Ray& ray) const override {
        float t;
        return nearest_root(ray, t);
    }
    bool defers_record() const override { return true; }
    bool intersect_distance(const Ray& ray, float& t) const override { return nearest_root(ray, t); }
    void complete_hit(const Ray& ray, float t, SurfaceHit& hit) const override;
    void complete_hit_without_uv(const Ray& ray, float t, SurfaceHit& hit) const override;

    /// The parts of the distance test that depend on the ray and the centre only. Spheres with one centre (a
    /// glass shell's two surfaces) share them: a list works them out once per ray for such a run of spheres.
    struct RayTerms {
        Vec3 oc{0.0f};                        // origin - centre
        float a = 0.0f, b = 0.0f, oo = 0.0f;  // d.d, oc.d, oc.oc
        float perp_length = 0.0f;             // |oc - (b / a) d|, once perp_known
        bool perp_known = false;
    };
    RayTerms ray_terms(const Ray& ray) const;
    /// intersect_distance() on terms from ray_terms() of this ray and a sphere with this very centre (its tmax
    /// may differ); fills in the terms it works out.
    bool intersect_distance(const Ray& ray, RayTerms& terms, float& t) const;
    const Point3& centre() const { return m_centre; }
    float radius() const { return m_radius; }
    using Shape::uv_footprint;
    std::optional<UvFootprint> uv_footprint(const Mat4& to_world) const override;
    /// complete_hit() (with_uv) or complete_hit_without_uv(), and without_tangent: hit.tangent left as it
    /// was, for a caller whose shading never reads it (the unit tangent costs a square root and a division).
    void complete_hit_for(const Ray& ray, float t, SurfaceHit& hit, bool with_uv, bool with_tangent) const;

private:
    bool nearest_root(const Ray& ray, float& t) const;
    void fill(const Ray& ray, float t, SurfaceHit& hit, bool with_uv, bool with_tangent) const;
    Point3 m_centre;
    float m_radius;
};

inline Sphere::RayTerms Sphere::ray_terms(const Ray& ray) const {
    RayTerms terms;
    terms.oc = ray.origin - m_centre;
    terms.a = glm::dot(ray.direction, ray.direction);
    terms.b = glm::dot(terms.oc, ray.direction);
    terms.oo = glm::dot(terms.oc, terms.oc);
    return terms;
}

inline bool Sphere::nearest_root(const Ray& ray, float& t) const {
    RayTerms terms = ray_terms(ray);
    return intersect_distance(ray, terms, t);
}

inline bool Sphere::intersect_distance(const Ray& ray, RayTerms& terms, float& t) const {
    const Vec3& d = ray.direction;
    const float a = terms.a;
    const float b = terms.b;
    const float c = terms.oo - m_radius * m_radius;
    // Starting outside and moving away: both roots are negative as stable_roots() rounds them (q < 0, so
    // c / q and q / a are <= 0), which no tmin >= 0 admits; the test costs two compares of numbers the roots need
    // anyway. Tried: this test, the wide test below, the roots' order and the choice of root, the quad's test, the
    // spawn offset and the sphere hit's error bounds made branch-free (& of the compares, bit masks), the same bits:
    // 38% fewer mispredicted branches in callgrind's simulation (rtlab-whitted 320x240, 2.37 M -> 1.46 M) but 5%
    // more instructions, and 5-6% more CPU time at 1280x960 (11 alternating rounds); this CPU predicts them better.
    if (b > 0.0f && c > 0.0f && ray.tmin >= 0.0f) return false;
    // |oc|^2 - b^2 / a loses everything for a far ray; the perpendicular vector keeps full precision.
    if (!terms.perp_known) {
        // A line clearly wide of the sphere is let go before the division and square root: a |oc|^2 - b^2 is a
        // perp^2 within about 20 float steps of a |oc|^2 (1.2e-6 of it), so beyond a r^2 + 1e-5 a |oc|^2 the true
        // perp exceeds r by more than 4e-6 |oc|, where perp_length below errs by at most 1e-6 |oc|: it would
        // come out above r too and disc negative, the same miss found cheaper. No NaN or overflow passes the
        // compares, and a r^2 > 1e-30 keeps that disc (about -8e-6 a r^2 at least) from rounding to -0.
        const float r2 = m_radius * m_radius;
        const float wide = terms.oo * a - b * b;
        if (wide > a * (r2 + 1e-5f * terms.oo) && wide < kInfinity && a * r2 > 1e-30f) return false;
        terms.perp_length = glm::length(terms.oc - (b / a) * d);
        terms.perp_known = true;
    }
    const float disc = a * (m_radius - terms.perp_length) * (m_radius + terms.perp_length);
    float t0, t1;
    if (!geometry::stable_roots(a, b, c, disc, t0, t1)) return false;
    if (t0 > ray.tmin && t0 < ray.tmax)
        t = t0;
    else if (t1 > ray.tmin && t1 < ray.tmax)
        t = t1;
    else
        return false;
    return true;
}

}  // namespace rtlab
