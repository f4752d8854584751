#pragma once
/// \brief Reflectance models evaluated in the local shading frame (normal = +z).
#include <rtlab/core/color.hpp>
#include <rtlab/core/math.hpp>

namespace rtlab {

/// \brief A BRDF f(wo, wi); both directions point away from the surface, in the local frame (n = +z).
/// Directions below the surface give black.
class Brdf {
public:
    virtual ~Brdf() = default;
    virtual RGB eval(const Vec3& wo, const Vec3& wi) const = 0;
};

/// \brief Ideal diffuse: albedo / pi.
class LambertBrdf final : public Brdf {
public:
    explicit LambertBrdf(const RGB& albedo) : m_albedo(albedo) {}
    RGB eval(const Vec3& wo, const Vec3& wi) const override;

private:
    RGB m_albedo;
};

/// \brief Energy-normalised Phong (Lafortune and Willems 1994): kd / pi + ks (e + 2) / (2 pi) cos^e(alpha),
/// alpha the angle between wi and the mirror direction of wo. Reciprocal, and conserves energy when
/// kd + ks <= 1 (the classic unnormalised Phong does neither).
class PhongBrdf final : public Brdf {
public:
    PhongBrdf(const RGB& kd, const RGB& ks, float exponent);
    RGB eval(const Vec3& wo, const Vec3& wi) const override;

private:
    RGB m_kd, m_ks;
    float m_exponent;
};

/// \brief Energy-normalised Blinn-Phong: kd / pi + ks c(e) cos^e(theta_h), theta_h the angle between the
/// normal and the half vector, c(e) = (e + 2)(e + 4) / (8 pi (e + 2^(-e/2))): the lobe then reflects exactly
/// ks at normal incidence, its largest albedo, and conserves energy when kd + ks <= 1. (The common
/// (e + 8) / (8 pi) of Real-Time Rendering approximates c(e) and reflects up to 7.5% more than it
/// receives, at e ~ 9.)
class BlinnPhongBrdf final : public Brdf {
public:
    BlinnPhongBrdf(const RGB& kd, const RGB& ks, float exponent);
    RGB eval(const Vec3& wo, const Vec3& wi) const override;

private:
    RGB m_kd, m_ks;
    float m_exponent;
    float m_norm;  // c(e)
};

}  // namespace rtlab
