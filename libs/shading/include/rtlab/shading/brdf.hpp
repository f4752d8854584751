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

/// \brief Energy-normalised Blinn-Phong: kd / pi + ks (e + 8) / (8 pi) cos^e(theta_h), theta_h the angle
/// between the normal and the half vector (Akenine-Moller et al., Real-Time Rendering).
class BlinnPhongBrdf final : public Brdf {
public:
    BlinnPhongBrdf(const RGB& kd, const RGB& ks, float exponent);
    RGB eval(const Vec3& wo, const Vec3& wi) const override;

private:
    RGB m_kd, m_ks;
    float m_exponent;
};

}  // namespace rtlab
