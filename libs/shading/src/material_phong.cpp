// Material "phong": diffuse plus Phong's specular lobe around the mirror direction.
//
// Parameters
//   kd         diffuse colour or texture                                 default 0.8
//   ks         specular colour or texture                                default 0.2
//   exponent   Phong exponent (>= 0), number or texture (grey)           default 25
//   + the Whitted terms of every material (builtin_params.cpp: kWhittedDoc)
//
// physical: the energy-normalised Phong BRDF (PhongBrdf: kd / pi + ks (e + 2) / (2 pi) cos^e alpha) times
// cos(theta_i); classic: the course's kd (n.l) + ks (r.v)^e, r the mirror image of the light direction.
#include <rtlab/shading/brdf.hpp>

#include "builtin_params.hpp"
#include "sampled_reflection.hpp"

#include <cmath>

namespace rtlab::shading_detail {

namespace {
class PhongMaterial final : public SampledReflection<PhongMaterial> {
public:
    PhongMaterial(Whitted w, std::shared_ptr<const Texture> kd, std::shared_ptr<const Texture> ks,
                  std::shared_ptr<const Texture> exponent)
        : SampledReflection(std::move(w)),
          m_kd(std::move(kd)),
          m_ks(std::move(ks)),
          m_exponent(std::move(exponent), 0.0f, kMaxExponent, 0.0f) {
        if (m_kd.is_constant() && m_ks.is_constant() && m_exponent.is_constant()) local_terms_are_constant();
    }

    RGB direct(const SurfaceTerms& t, const Vec3& wo, const Vec3& wi, Convention c) const override {
        if (!(wo.z > 0.0f && wi.z > 0.0f)) return {};
        if (c == Convention::physical) return PhongBrdf(t.diffuse, t.specular, t.shape_u).eval(wo, wi) * wi.z;
        const Vec3 r(-wi.x, -wi.y, wi.z);  // the light direction mirrored about the normal
        const float rv = std::max(0.0f, glm::dot(r, wo));
        return t.diffuse * wi.z + t.specular * std::pow(rv, t.shape_u);
    }

    /// The physical model of brdf.hpp at one hit: SampledReflection's lobes.
    PhongBrdf brdf(const SurfaceTerms& t) const { return PhongBrdf(t.diffuse, t.specular, t.shape_u); }

protected:
    void local_terms(const TextureLookup& q, SurfaceTerms& t) const override {
        t.diffuse = m_kd.eval(q);
        t.specular = m_ks.eval(q);
        t.shape_u = m_exponent.eval(q);
    }

private:
    ColourChannel m_kd, m_ks;
    ScalarChannel m_exponent;
};

TypeSpec phong_spec() {
    return lobe_spec("Phong: physical kd / pi + ks (e + 2) / (2 pi) cos^e alpha; classic kd (n.l) + ks (r.v)^e",
                     "Phong exponent e: larger is a smaller, sharper highlight");
}
}  // namespace

void register_phong(MaterialRegistry& registry) {
    registry.add(
        "phong",
        [](const Params& p) -> std::shared_ptr<Material> {
            auto kd = colour_param(p, "kd", RGB(0.8f));
            auto ks = colour_param(p, "ks", RGB(0.2f));
            auto e = scalar_param(p, "exponent", 25.0f, 0.0f, kMaxExponent);
            return std::make_shared<PhongMaterial>(read_whitted(p, {}), std::move(kd), std::move(ks), std::move(e));
        },
        phong_spec());
}

}  // namespace rtlab::shading_detail
