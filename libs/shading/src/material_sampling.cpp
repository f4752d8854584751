// Material's sampled interface: the mixture of the model's own lobes with the Whitted terms as delta lobes
// (the weights are documented in material.hpp).
#include <rtlab/shading/material.hpp>
#include <rtlab/shading/optics.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace rtlab {

namespace {

RGB clamp_below_at_zero(const RGB& c) { return {std::max(0.0f, c.r), std::max(0.0f, c.g), std::max(0.0f, c.b)}; }

/// The mixture's weights for one wo, and where its delta lobes go.
struct Mixture {
    enum Lobe { own, reflect, transmit, pass, count };
    std::array<RGB, count> weight;      // each already times a (or 1 - a for pass)
    std::array<float, count> chance{};  // probabilities of choosing each lobe in sample(); sum 1 (or all 0)
    Vec3 refracted;                     // where T goes (valid when weight[transmit] is not black)
    float radiance_scale = 1.0f;        // (n_wo / n_wi)^2 for T in radiance mode
};

/// Whether the mixture is the model's own lobes alone, with weight 1 and chance 1 (no mirror, no refraction, no
/// cut-out): the common case, whose eval, pdf and sample skip the mixture. mixture() gives exactly 1 there too:
/// 1 * max(0, 1 - 0 - 0) = 1, and the chance is channel_mean(1) = 1 over a sum of 1 (3 * fl(1/3) rounds to 1).
bool own_lobes_only(const SurfaceTerms& t) { return t.opacity == 1.0f && t.kr.is_black() && t.kt.is_black(); }

Mixture mixture(const Material& material, const SurfaceTerms& t, const Vec3& wo, bool has_lobes) {
    Mixture m;
    const float a = t.opacity;
    RGB r = t.kr, tr = t.kt;
    if (!(r.is_black() && tr.is_black())) {
        const bool outside = wo.z > 0.0f;
        const float eta = outside ? material.ior_outside() / material.ior_inside()
                                  : material.ior_inside() / material.ior_outside();  // n_incident / n_transmitted
        const float cos_i = std::min(std::abs(wo.z), 1.0f);
        const float cos2_t = transmitted_cos2(cos_i, eta);
        if (material.fresnel()) {
            const float f = fresnel_dielectric_given(cos_i, cos2_t, eta);
            r *= f;
            tr *= 1.0f - f;
        }
        if (cos2_t <= 0.0f) {  // total internal reflection, as the Whitted recursion has it
            r += tr;
            tr = RGB{};
        } else {
            const float cos_t = std::sqrt(cos2_t);
            const Vec3 n(0.0f, 0.0f, outside ? 1.0f : -1.0f);
            m.refracted = glm::normalize(eta * -wo + (eta * cos_i - cos_t) * n);
            m.radiance_scale = eta * eta;
        }
    }
    m.weight[Mixture::reflect] = a * r;
    m.weight[Mixture::transmit] = a * tr;
    m.weight[Mixture::own] = has_lobes ? a * clamp_below_at_zero(RGB(1.0f) - r - tr) : RGB{};
    m.weight[Mixture::pass] = RGB(1.0f - a);
    float sum = 0.0f;
    for (int i = 0; i < Mixture::count; ++i) sum += m.chance[i] = channel_mean(m.weight[i]);
    if (sum > 0.0f)
        for (float& c : m.chance) c /= sum;
    return m;
}

Vec3 mirrored(const Vec3& v) { return {v.x, v.y, -v.z}; }

}  // namespace

RGB Material::own_eval(const SurfaceTerms& t, Vec3 wo, Vec3 wi, TransportMode mode) const {
    if (!lobes_transmit()) {
        if (wo.z < 0.0f) {
            wo = mirrored(wo);
            wi = mirrored(wi);
        }
        if (!(wo.z > 0.0f && wi.z > 0.0f)) return {};
    }
    return lobe_eval(t, wo, wi, mode);
}

float Material::own_pdf(const SurfaceTerms& t, Vec3 wo, Vec3 wi, TransportMode mode) const {
    if (!lobes_transmit()) {
        if (wo.z < 0.0f) {
            wo = mirrored(wo);
            wi = mirrored(wi);
        }
        if (!(wo.z > 0.0f && wi.z > 0.0f)) return 0.0f;
    }
    return lobe_pdf(t, wo, wi, mode);
}

std::optional<LobeDraw> Material::own_sample(const SurfaceTerms& t, Vec3 wo, float uc, const Vec2& u,
                                             TransportMode mode) const {
    if (lobes_transmit()) return lobe_sample(t, wo, uc, u, mode);
    const bool below = wo.z < 0.0f;
    if (below) wo = mirrored(wo);
    if (!(wo.z > 0.0f)) return std::nullopt;
    std::optional<LobeDraw> draw = lobe_sample(t, wo, uc, u, mode);
    if (draw && below) draw->wi = mirrored(draw->wi);
    return draw;
}

RGB Material::eval(const SurfaceTerms& t, const Vec3& wo, const Vec3& wi, TransportMode mode) const {
    if (!has_lobes()) return {};
    if (own_lobes_only(t)) return own_eval(t, wo, wi, mode);  // the weight is 1: the same bits
    const RGB w = mixture(*this, t, wo, true).weight[Mixture::own];
    if (w.is_black()) return {};
    return w * own_eval(t, wo, wi, mode);
}

float Material::pdf(const SurfaceTerms& t, const Vec3& wo, const Vec3& wi, TransportMode mode) const {
    if (!has_lobes()) return 0.0f;
    if (own_lobes_only(t)) return own_pdf(t, wo, wi, mode);  // the chance is 1: the same bits
    const float chance = mixture(*this, t, wo, true).chance[Mixture::own];
    if (!(chance > 0.0f)) return 0.0f;
    return chance * own_pdf(t, wo, wi, mode);
}

bool Material::sample_uses_choice(const SurfaceTerms& t) const {
    return !(has_lobes() && own_lobes_only(t)) || lobes_use_choice();
}

float Material::non_delta_chance(const SurfaceTerms& t, const Vec3& wo) const {
    if (!has_lobes()) return 0.0f;
    return mixture(*this, t, wo, true).chance[Mixture::own];
}

std::optional<BsdfSample> Material::sample(const SurfaceTerms& t, const Vec3& wo, float uc, const Vec2& u,
                                           TransportMode mode) const {
    const bool lobes = has_lobes();
    if (lobes && own_lobes_only(t)) {
        // What the general case below does for a mixture of the own lobe alone at chance 1 and weight 1 (uc < 1
        // is its own rescaled uc), without the multiplications by 1.
        const std::optional<LobeDraw> draw = own_sample(t, wo, std::min(uc, 0x1.fffffep-1f), u, mode);
        if (!draw) return std::nullopt;
        BsdfSample s;
        s.wi = draw->wi;
        s.flags = draw->flags;
        s.pdf = own_pdf(t, wo, s.wi, mode);
        if (!(s.pdf > 0.0f)) return std::nullopt;
        s.value = own_eval(t, wo, s.wi, mode) * (std::abs(s.wi.z) / s.pdf);
        return s;
    }
    const Mixture m = mixture(*this, t, wo, lobes);
    // Choose a lobe by uc and stretch the rest of uc over [0, 1) for the model's own choice.
    int lobe = -1;
    float below = 0.0f;
    for (int i = 0; i < Mixture::count; ++i) {
        if (!(m.chance[i] > 0.0f)) continue;
        lobe = i;
        if (uc < below + m.chance[i]) break;
        below += m.chance[i];
    }
    if (lobe < 0) return std::nullopt;
    const float chance = m.chance[lobe];
    BsdfSample s;
    switch (lobe) {
        case Mixture::own: {
            const float uc_own = std::min((uc - below) / chance, 0x1.fffffep-1f);
            const std::optional<LobeDraw> draw = own_sample(t, wo, uc_own, u, mode);
            if (!draw) return std::nullopt;
            s.wi = draw->wi;
            s.flags = draw->flags;
            s.pdf = chance * own_pdf(t, wo, s.wi, mode);
            if (!(s.pdf > 0.0f)) return std::nullopt;
            s.value = m.weight[Mixture::own] * own_eval(t, wo, s.wi, mode) * (std::abs(s.wi.z) / s.pdf);
            return s;
        }
        case Mixture::reflect:
            s.wi = Vec3(-wo.x, -wo.y, wo.z);
            s.flags = kLobeSpecular | kLobeReflection;
            break;
        case Mixture::transmit:
            s.wi = m.refracted;
            s.flags = kLobeSpecular | kLobeTransmission;
            break;
        default:
            s.wi = -wo;
            s.flags = kLobeSpecular | kLobeTransmission;
            break;
    }
    s.pdf = chance;
    s.value = m.weight[lobe] / chance;
    if (lobe == Mixture::transmit && mode == TransportMode::radiance) s.value *= m.radiance_scale;
    return s;
}

}  // namespace rtlab
