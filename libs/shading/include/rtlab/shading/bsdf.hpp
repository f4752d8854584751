#pragma once
/// \brief What a sampled material answers: transport modes, lobe flags, a sampled direction, and the warps
/// the built-in lobes draw with.
///
/// Directions: every direction is a unit vector in the hit's local shading frame (rtlab/core/frame.hpp:
/// tangent +x, bitangent +y, shading normal +z), both pointing away from the surface. +z is the surface's
/// outward normal as the shape gives it (after a reversed flag), NOT turned towards the viewer: wo.z < 0
/// means the viewer is inside (or behind). Opaque materials are two-sided and answer for the side wo is on;
/// dielectrics use the sign to tell the index of refraction on each side (ior_outside above, ior below).
#include <rtlab/core/color.hpp>
#include <rtlab/core/math.hpp>

#include <cstdint>

namespace rtlab {

/// \brief What a path carries: radiance (traced from the camera) or importance (traced from the lights,
/// the adjoint). Only transmission between different media differs: in radiance mode it is scaled by
/// (eta_wo / eta_wi)^2, the squeeze of the solid angle, which importance does not undergo.
enum class TransportMode { radiance, importance };

/// Lobe flags: a combination of one type (diffuse, glossy, specular) and one direction class.
using LobeFlags = std::uint32_t;
inline constexpr LobeFlags kLobeNone = 0;
inline constexpr LobeFlags kLobeReflection = 1u << 0;
inline constexpr LobeFlags kLobeTransmission = 1u << 1;
inline constexpr LobeFlags kLobeDiffuse = 1u << 2;
inline constexpr LobeFlags kLobeGlossy = 1u << 3;
/// A delta lobe: eval() and pdf() are 0 for every direction; only sample() reaches it.
inline constexpr LobeFlags kLobeSpecular = 1u << 4;

/// \brief A direction drawn by Material::sample().
///
/// value = f(wo, wi) |cos(theta_i)| / pdf for the whole mixture, what multiplies the path throughput. For
/// a delta lobe (flags has kLobeSpecular) pdf is the discrete probability of having chosen that lobe and
/// value its weight over that probability; eval() and pdf() know nothing of it.
struct BsdfSample {
    Vec3 wi;
    RGB value;
    float pdf = 0.0f;
    LobeFlags flags = kLobeNone;
};

/// \brief A direction drawn by one model's own lobes (before the material's mixture weights), with the
/// flags of the part that drew it.
struct LobeDraw {
    Vec3 wi;
    LobeFlags flags = kLobeNone;
};

/// Cosine-weighted direction on the upper hemisphere from u in [0, 1)^2 (Malley's method on a concentric
/// disk, Shirley and Chiu 1997): pdf cos(theta) / pi.
Vec3 sample_cosine_hemisphere(const Vec2& u);

/// A direction at angle alpha from the unit `axis` with cos(alpha) distributed as (e + 1) cos^e over the
/// solid angle, i.e. pdf (e + 1) / (2 pi) cos^e(alpha): Phong's lobe and Blinn's half vectors. 1 - cos is
/// worked out as -expm1(log(1 - u.x) / (e + 1)), so that exponents of 1e6 keep their angles.
Vec3 sample_power_cosine(const Vec3& axis, float exponent, const Vec2& u);

/// The mean of the three channels: the scalar a mixture weighs its lobes by.
inline float channel_mean(const RGB& c) { return (c.r + c.g + c.b) * (1.0f / 3.0f); }

}  // namespace rtlab
