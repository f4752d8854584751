// Material "ashikhmin-shirley": anisotropic Phong (Ashikhmin and Shirley 2000), a glossy coat over a
// diffuse base; brushed metal with nu != nv. The exponents follow the surface tangent (SurfaceHit::tangent,
// dP/du): the Whitted integrator's local frame has the tangent as +x, so nu runs along it.
//
// Parameters
//   rd    diffuse colour or texture                                       default 0.5
//   rs    specular colour at normal incidence, in [0, 1], colour or
//         texture (textured values are clamped to 1)                      default 0.05
//   nu    exponent along the tangent, in [0, 1e15], number or texture     default 100
//   nv    exponent along the bitangent, in [0, 1e15], number or texture   default nu
//   + the Whitted terms of every material (builtin_params.cpp: kWhittedDoc)
//
// physical: AshikhminShirleyBrdf times cos(theta_i); classic: the same times pi.
#include <rtlab/shading/brdf.hpp>

#include "builtin_params.hpp"
#include "sampled_reflection.hpp"

#include <algorithm>
#include <string>

namespace rtlab::shading_detail {

namespace {
class AshikhminShirleyMaterial final : public SampledReflection<AshikhminShirleyMaterial> {
public:
    AshikhminShirleyMaterial(Whitted w, std::shared_ptr<const Texture> rd, std::shared_ptr<const Texture> rs,
                             std::shared_ptr<const Texture> nu, std::shared_ptr<const Texture> nv)
        : SampledReflection(std::move(w)),
          m_rd(std::move(rd)),
          m_rs(std::move(rs)),
          m_nu(std::move(nu), 0.0f, kMaxExponent, 0.0f),
          m_nv(std::move(nv), 0.0f, kMaxExponent, 0.0f) {
        if (m_rd.is_constant() && m_rs.is_constant() && m_nu.is_constant() && m_nv.is_constant())
            local_terms_are_constant();
    }

    RGB direct(const SurfaceTerms& t, const Vec3& wo, const Vec3& wi, Convention c) const override {
        if (!(wo.z > 0.0f && wi.z > 0.0f)) return {};
        const AshikhminShirleyBrdf f(t.diffuse, t.specular, t.shape_u, t.shape_v);
        return f.eval(wo, wi) * (c == Convention::physical ? wi.z : wi.z * kPi);
    }

    /// The physical model of brdf.hpp at one hit: SampledReflection's lobes.
    AshikhminShirleyBrdf brdf(const SurfaceTerms& t) const {
        return AshikhminShirleyBrdf(t.diffuse, t.specular, t.shape_u, t.shape_v);
    }

protected:
    void local_terms(const TextureLookup& q, SurfaceTerms& t) const override {
        t.diffuse = m_rd.eval(q);
        // rs > 1 would turn the diffuse term's (1 - rs) negative.
        const RGB rs = m_rs.eval(q);
        t.specular = {std::min(rs.r, 1.0f), std::min(rs.g, 1.0f), std::min(rs.b, 1.0f)};
        t.shape_u = m_nu.eval(q);
        t.shape_v = m_nv.eval(q);
    }

private:
    ColourChannel m_rd, m_rs;
    ScalarChannel m_nu, m_nv;
};

TypeSpec ashikhmin_shirley_spec() {
    TypeSpec s("anisotropic Phong of Ashikhmin and Shirley. Classic convention: times pi");
    s.add("rd", ParamKind::texture, "diffuse colour").defaults("0.5");
    s.add("rs", ParamKind::texture, "specular colour at normal incidence (<= 1)").defaults("0.05");
    s.add("nu", ParamKind::scalar, "exponent along the surface tangent").defaults("100").range(0, kMaxExponent);
    s.add("nv", ParamKind::scalar, "exponent along the bitangent (default: nu)").range(0, kMaxExponent);
    return with_material_params(std::move(s));
}
}  // namespace

void register_ashikhmin_shirley(MaterialRegistry& registry) {
    registry.add(
        "ashikhmin-shirley",
        [](const Params& p) -> std::shared_ptr<Material> {
            auto rd = colour_param(p, "rd", RGB(0.5f));
            auto rs = colour_param(p, "rs", RGB(0.05f));
            if (const RGB* c = rs->constant(); c && c->max_component() > 1.0f) fail_param(p, "rs", "must be <= 1");
            auto nu = scalar_param(p, "nu", 100.0f, 0.0f, kMaxExponent);
            auto nv = p.has("nv") ? scalar_param(p, "nv", 100.0f, 0.0f, kMaxExponent) : nu;
            return std::make_shared<AshikhminShirleyMaterial>(read_whitted(p, {}), std::move(rd), std::move(rs),
                                                              std::move(nu), std::move(nv));
        },
        ashikhmin_shirley_spec());
}

}  // namespace rtlab::shading_detail
