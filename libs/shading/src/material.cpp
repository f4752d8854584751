#include <rtlab/core/error.hpp>
#include <rtlab/shading/material.hpp>

#include <rtlab/textures/texture_param.hpp>

#include <algorithm>

namespace rtlab {

namespace {
// Textures may give anything; a term outside [0, limit] (or NaN) would make energy or NaNs downstream.
RGB clamp_rgb(const RGB& c, float limit) {
    auto f = [limit](float x) { return std::min(limit, std::max(0.0f, x)); };
    return {f(c.r), f(c.g), f(c.b)};
}
}  // namespace

Material::Term Material::make_term(const std::shared_ptr<const Texture>& texture, const RGB& fallback) {
    if (!texture) return {nullptr, fallback};
    if (const RGB* c = texture->constant()) return {nullptr, *c};
    return {texture.get(), RGB{}};
}

RGB Material::term_value(const Term& term, const TextureLookup& lookup) {
    return term.texture ? term.texture->eval(lookup) : term.value;
}

Material::Material(Whitted whitted) : m_whitted(std::move(whitted)) {
    if (!(m_whitted.ior_inside > 0.0f) || !(m_whitted.ior_outside > 0.0f))
        throw Error("material: indices of refraction must be > 0");
    m_kr = make_term(m_whitted.kr, RGB(0.0f));
    m_kt = make_term(m_whitted.kt, RGB(0.0f));
    m_emission = make_term(m_whitted.emission, RGB(0.0f));
    m_opacity = make_term(m_whitted.opacity, RGB(1.0f));
    const bool kt_zero = !m_kt.texture && m_kt.value.is_black();
    const bool opaque = !m_opacity.texture && scalar(m_opacity.value) >= 1.0f;
    m_transmits = !(kt_zero && opaque);
    if (!m_kt.texture && !m_opacity.texture) {
        m_shadow = looked_up_shadow_transmittance(TextureLookup{});
        m_constant_shadow = true;
    }
}

void Material::local_terms_are_constant() {
    if (m_kr.texture || m_kt.texture || m_emission.texture || m_opacity.texture) return;
    // The same code as every lookup runs, once: constants give the same record bit for bit.
    m_constant_terms = looked_up_terms(TextureLookup{});
    m_constant = true;
}

float Material::opacity(const TextureLookup& lookup) const {
    // The textures library's rule: the alpha of a texture that has one (an RGBA image: Saturn's rings), else
    // the mean of its channels (a grey mask, a constant).
    const float a = m_opacity.texture ? rtlab::opacity(*m_opacity.texture, lookup) : scalar(m_opacity.value);
    return a == a ? std::clamp(a, 0.0f, 1.0f) : 1.0f;  // a NaN alpha counts as opaque
}

SurfaceTerms Material::looked_up_terms(const TextureLookup& lookup) const {
    SurfaceTerms t;
    local_terms(lookup, t);
    t.kr = term_value(m_kr, lookup);
    t.kt = term_value(m_kt, lookup);
    if (m_kr.texture || m_kt.texture) {
        t.kr = clamp_rgb(t.kr, 1.0f);
        t.kt = clamp_rgb(t.kt, 1.0f);
        if (!m_whitted.fresnel) {
            const float sum = (t.kr + t.kt).max_component();
            if (sum > 1.0f) {
                t.kr /= sum;
                t.kt /= sum;
            }
        }
    }
    t.emission = term_value(m_emission, lookup);
    t.opacity = opacity(lookup);
    return t;
}

RGB Material::looked_up_shadow_transmittance(const TextureLookup& lookup) const {
    if (!m_transmits) return RGB(0.0f);
    const float a = opacity(lookup);
    RGB kt = term_value(m_kt, lookup);
    if (m_kt.texture) kt = clamp_rgb(kt, 1.0f);
    return RGB(1.0f - a) + a * kt;
}

}  // namespace rtlab
