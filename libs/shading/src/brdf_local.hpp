#pragma once
// Checks and frame helpers shared by the BRDF sources (private to the shading library).
#include <rtlab/core/color.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/core/math.hpp>
#include <rtlab/shading/bsdf.hpp>

#include <cmath>
#include <optional>
#include <string>

namespace rtlab::detail {

/// Both directions strictly above the surface: every BRDF is black otherwise.
inline bool both_above(const Vec3& wo, const Vec3& wi) { return wo.z > 0.0f && wi.z > 0.0f; }

/// The half vector of two directions above the surface. Their sum has |sum| >= cos_o + cos_i > 0, but for
/// opposite directions within 1e-19 of the horizon its square underflows; the limit there is n.
inline Vec3 half_vector(const Vec3& wo, const Vec3& wi) {
    const Vec3 sum = wo + wi;
    const float len2 = glm::dot(sum, sum);
    return len2 > 0.0f ? sum / std::sqrt(len2) : Vec3(0.0f, 0.0f, 1.0f);
}

/// (1 - x)^e for x in [0, 1], from x rather than from 1 - x: the cosines of narrow lobes round to multiples of
/// 6e-8 near 1, which an exponent of 1e4 turns into percent-level errors, while x = 1 - cos, taken from
/// the sines, keeps full precision. 0^0 = 1, as std::pow has it.
inline float pow_one_minus(float x, float e) {
    if (!(x < 1.0f)) return e == 0.0f ? 1.0f : 0.0f;
    return std::exp(e * std::log1p(-std::max(0.0f, x)));
}

/// wo mirrored about the unit vector h (both pointing away from the surface).
inline Vec3 reflect_about(const Vec3& wo, const Vec3& h) { return 2.0f * glm::dot(wo, h) * h - wo; }

/// The probability with which a two-part model draws its specular part: the specular weight's share of the
/// sum, or -1 when both weights are 0 (the model is black and draws nothing).
inline float specular_probability(float diffuse_weight, float specular_weight) {
    const float sum = diffuse_weight + specular_weight;
    return sum > 0.0f ? specular_weight / sum : -1.0f;
}

/// The density of a two-part model's draws: cosine sampling with probability 1 - p_lobe, its specular lobe's
/// density lobe_pdf otherwise.
inline float two_part_pdf(float p_lobe, float cos_i, float lobe_pdf) {
    return (1.0f - p_lobe) * cos_i * kInvPi + p_lobe * lobe_pdf;
}

/// A two-part model's draw: lobe() (a direction, or nullopt when the draw is lost) with probability p_lobe,
/// else a cosine-weighted direction; nullopt below the surface.
template <class Lobe>
std::optional<LobeDraw> draw_two_part(float p_lobe, float uc, const Vec2& u, Lobe&& lobe) {
    LobeDraw draw;
    if (uc < p_lobe) {
        const std::optional<Vec3> wi = lobe();
        if (!wi) return std::nullopt;
        draw = {*wi, kLobeGlossy | kLobeReflection};
    } else {
        draw = {sample_cosine_hemisphere(u), kLobeDiffuse | kLobeReflection};
    }
    if (!(draw.wi.z > 0.0f)) return std::nullopt;
    return draw;
}

/// wo mirrored about a sampled half vector h, or nullopt when h faces away from wo.
inline std::optional<Vec3> mirror_about(const Vec3& wo, const Vec3& h) {
    if (!(glm::dot(wo, h) > 0.0f)) return std::nullopt;
    return reflect_about(wo, h);
}

// The checks build their messages only on failure: materials construct BRDFs per light sample, where
// formatting the values up front cost ~1 us per Cook-Torrance and ~2 us per Ashikhmin-Shirley.
inline void check_parameter(bool ok, const char* model, const char* what, float got) {
    if (!ok) throw Error(std::string(model) + ": " + what + ", got " + std::to_string(got));
}

inline void check_colour(const RGB& c, const char* model, const char* name) {
    if (c.is_finite() && c.r >= 0.0f && c.g >= 0.0f && c.b >= 0.0f) return;
    throw Error(std::string(model) + ": " + name + " must be finite and >= 0, got " + std::to_string(c.r) + " " +
                std::to_string(c.g) + " " + std::to_string(c.b));
}

}  // namespace rtlab::detail
