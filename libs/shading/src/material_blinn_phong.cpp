// Material "blinn-phong": diffuse plus Blinn's specular lobe, in the angle between normal and half vector.
//
// Parameters
//   kd         diffuse colour or texture                                 default 0.8
//   ks         specular colour or texture                                default 0.2
//   exponent   exponent (>= 0), number or texture (grey)           default 25
//   + the Whitted terms of every material (builtin_params.cpp: kWhittedDoc)
//
// physical: the energy-normalised BlinnPhongBrdf (kd / pi + ks c(e) (n.h)^e, brdf.hpp) times cos(theta_i);
// classic: kd (n.l) + ks (n.h)^e, h = (l + v) / |l + v|.
#include <rtlab/shading/brdf.hpp>

#include "builtin_params.hpp"
#include "sampled_reflection.hpp"

#include <cmath>

namespace rtlab::shading_detail {

namespace {
class BlinnPhongMaterial final : public SampledReflection<BlinnPhongMaterial> {
public:
    BlinnPhongMaterial(Whitted w, std::shared_ptr<const Texture> kd, std::shared_ptr<const Texture> ks,
                       std::shared_ptr<const Texture> exponent)
        : SampledReflection(std::move(w)),
          m_kd(std::move(kd)),
          m_ks(std::move(ks)),
          m_exponent(std::move(exponent), 0.0f, kMaxExponent, 0.0f) {
        if (m_kd.is_constant() && m_ks.is_constant() && m_exponent.is_constant()) local_terms_are_constant();
    }

    RGB direct(const SurfaceTerms& t, const Vec3& wo, const Vec3& wi, Convention c) const override {
        if (!(wo.z > 0.0f && wi.z > 0.0f)) return {};
        if (c == Convention::physical) return BlinnPhongBrdf(t.diffuse, t.specular, t.shape_u).eval(wo, wi) * wi.z;
        const Vec3 h = wo + wi;  // wo.z, wi.z > 0: never zero
        const float nh = h.z / glm::length(h);
        return t.diffuse * wi.z + t.specular * std::pow(nh, t.shape_u);
    }

    /// The physical model of brdf.hpp at one hit: SampledReflection's lobes.
    BlinnPhongBrdf brdf(const SurfaceTerms& t) const { return BlinnPhongBrdf(t.diffuse, t.specular, t.shape_u); }

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

TypeSpec blinn_phong_spec() {
    return lobe_spec("Blinn-Phong: physical kd / pi + ks c(e) (n.h)^e, normalised; classic kd (n.l) + ks (n.h)^e",
                     "exponent e of n.h, h the half vector: larger is a smaller, sharper highlight");
}
}  // namespace

void register_blinn_phong(MaterialRegistry& registry) {
    registry.add(
        "blinn-phong",
        [](const Params& p) -> std::shared_ptr<Material> {
            auto kd = colour_param(p, "kd", RGB(0.8f));
            auto ks = colour_param(p, "ks", RGB(0.2f));
            auto e = scalar_param(p, "exponent", 25.0f, 0.0f, kMaxExponent);
            return std::make_shared<BlinnPhongMaterial>(read_whitted(p, {}), std::move(kd), std::move(ks),
                                                        std::move(e));
        },
        blinn_phong_spec());
}

}  // namespace rtlab::shading_detail
