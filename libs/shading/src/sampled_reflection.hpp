#pragma once
// The sampled-lobe overrides every reflection model shares whose physical BRDF samples itself (brdf.hpp:
// eval, pdf, sample), private to the shading library.
#include <rtlab/shading/material.hpp>

#include <optional>

namespace rtlab::shading_detail {

/// \brief A Material whose own lobes are those of the BRDF Derived::brdf(terms) returns: opaque, two-sided
/// (Material hands it the pair mirrored to the upper side when the viewer is below), the same in radiance
/// and importance mode (reflection only).
template <class Derived>
class SampledReflection : public Material {
public:
    using Material::Material;

protected:
    bool has_lobes() const override { return true; }
    RGB lobe_eval(const SurfaceTerms& t, const Vec3& wo, const Vec3& wi, TransportMode) const override {
        return self().brdf(t).eval(wo, wi);
    }
    float lobe_pdf(const SurfaceTerms& t, const Vec3& wo, const Vec3& wi, TransportMode) const override {
        return self().brdf(t).pdf(wo, wi);
    }
    std::optional<LobeDraw> lobe_sample(const SurfaceTerms& t, const Vec3& wo, float uc, const Vec2& u,
                                        TransportMode) const override {
        return self().brdf(t).sample(wo, uc, u);
    }

private:
    const Derived& self() const { return static_cast<const Derived&>(*this); }
};

}  // namespace rtlab::shading_detail
