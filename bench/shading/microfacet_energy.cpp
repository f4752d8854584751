// The energy that single-scattering microfacet models lose, against roughness: the directional albedo of
//   conductor    cook-torrance's lobe with a white Fresnel term (F = 1: every microfacet reflects all it
//                receives), so that what is missing from 1 is what the Smith masking drops, the light that would
//                bounce between microfacets;
//   dielectric   the rough dielectric interface (Walter et al. 2007) of index 1.5 entered from outside, its
//                reflection plus its transmission in importance mode (the fraction of the arriving light that
//                leaves), 1 for the smooth interface;
// each with the GGX and the Beckmann distribution, for alpha from 0.01 to 1 (alpha itself: the materials'
// roughness parameter r gives alpha = r^2) and incident cosines 1, 0.7, 0.3 and 0.1. The albedo is the integral
// of f |cos(theta_i)| over the sphere by rtlab::shading_testing's adaptive quadrature (deterministic, refined
// around the mirror and refracted directions, 1e-7 absolute per starting cell): no Monte Carlo noise.
//   rtlab_shading_microfacet_energy [docs/data/microfacet_energy.csv]
#include <rtlab/shading/brdf.hpp>
#include <rtlab/shading/rough_dielectric.hpp>
#include <rtlab/shading_testing/sphere_quadrature.hpp>

#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

using namespace rtlab;
using shading_testing::SphereQuadrature;

namespace {

constexpr float kIor = 1.5f;

/// wo (above) refracted into the medium of index kIor.
Vec3 refracted(const Vec3& wo) {
    const float eta = 1.0f / kIor, cos2_t = 1.0f - eta * eta * (1.0f - wo.z * wo.z);
    return glm::normalize(Vec3(-eta * wo.x, -eta * wo.y, -std::sqrt(cos2_t)));
}

double albedo(const SphereQuadrature::Density& f_cos, const Vec3& wo) {
    return SphereQuadrature(f_cos, {Vec3(-wo.x, -wo.y, wo.z), refracted(wo)}).integrate_sphere(12, 12);
}

}  // namespace

int main(int argc, char** argv) {
    std::ofstream file;
    if (argc > 1) file.open(argv[1]);
    std::ostream& out = argc > 1 ? file : std::cout;
    if (!out) {
        std::cerr << "microfacet_energy: cannot write " << argv[1] << "\n";
        return 1;
    }
    out << "distribution,surface,cos_o,alpha,albedo,energy_lost\n";
    const auto start = std::chrono::steady_clock::now();
    constexpr int kAlphas = 21;  // 10 a decade
    for (MicrofacetModel model : {MicrofacetModel::ggx, MicrofacetModel::beckmann}) {
        const char* name = model == MicrofacetModel::ggx ? "ggx" : "beckmann";
        for (float cos_o : {1.0f, 0.7f, 0.3f, 0.1f}) {
            // Off the axes in azimuth, as the materials' tests look.
            const float sin_o = std::sqrt(1.0f - cos_o * cos_o);
            const Vec3 wo(sin_o * std::cos(0.3f), sin_o * std::sin(0.3f), cos_o);
            for (int i = 0; i < kAlphas; ++i) {
                const float alpha = std::pow(10.0f, -2.0f + 2.0f * i / (kAlphas - 1));
                const MicrofacetDistribution d(model, alpha);
                const CookTorranceBrdf conductor(RGB(0.0f), RGB(1.0f), d, Fresnel::one());
                const RoughDielectricBsdf dielectric(d, kIor);
                const double a_conductor = albedo(
                    [&](const Vec3& wi) { return wi.z > 0.0f ? double(conductor.eval(wo, wi).g) * wi.z : 0.0; }, wo);
                const double a_dielectric = albedo(
                    [&](const Vec3& wi) {
                        return double(dielectric.eval(wo, wi, TransportMode::importance)) * std::abs(wi.z);
                    },
                    wo);
                for (const auto& [surface, a] :
                     {std::pair("conductor", a_conductor), std::pair("dielectric", a_dielectric)})
                    out << name << ',' << surface << ',' << cos_o << ',' << alpha << ',' << a << ',' << 1.0 - a << '\n';
                std::cerr << name << " cos_o " << cos_o << " alpha " << alpha << ": conductor " << a_conductor
                          << ", dielectric " << a_dielectric << "\n";
            }
        }
    }
    std::cerr << "microfacet_energy: "
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s\n";
    return 0;
}
