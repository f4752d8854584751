// Speed against accuracy of the fast shading terms: time per evaluation against the error in reflected
// energy.
//   Fresnel: fresnel_dielectric (exact) and fresnel_schlick, at eta = n_i / n_t of 1/1.33, 1/1.5, 1/2.4 (into
//   water, glass, diamond) and 1.5 (out of glass). Error: |R_schlick - R_exact| of the hemispherical
//   reflectance R = integral of F(cos) 2 cos dcos (the fraction of uniform incident light reflected), and the
//   largest |F_schlick - F_exact| over angles.
//   Phong: the energy-normalised PhongBrdf times cos(theta_i) against the course's classic term ks (r.v)^e
//   (what the "phong" material computes with the classic convention), ks = 0.5, kd = 0, exponents 1 to 1000.
//   Error: the relative difference between the energy reflected from light at normal incidence (the
//   directional albedo, by quadrature in double) and ks, the fraction the user asked for.
// Time: each evaluation runs over 4096 precomputed inputs, 200 passes; the figure is the median over `runs`
// (default 9) of ns per evaluation, on one thread.
//   rtlab_shading_optics_tradeoff docs/data/optics_tradeoff.csv [--runs N]
#include <rtlab/core/rng.hpp>
#include <rtlab/shading/brdf.hpp>
#include <rtlab/shading/optics.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

using namespace rtlab;

namespace {

constexpr int kBatch = 4096;
constexpr int kPasses = 200;

/// Median ns per call of f(i) for i over the batch.
double time_per_eval(int runs, const std::function<float(int)>& f) {
    std::vector<double> ns;
    volatile float sink = 0.0f;
    for (int r = 0; r < runs; ++r) {
        float acc = 0.0f;
        const auto start = std::chrono::steady_clock::now();
        for (int p = 0; p < kPasses; ++p)
            for (int i = 0; i < kBatch; ++i) acc += f(i);
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        sink = sink + acc;
        ns.push_back(1e9 * s / (static_cast<double>(kBatch) * kPasses));
    }
    std::sort(ns.begin(), ns.end());
    return ns[ns.size() / 2];
}

/// The course's classic specular term, ks (r.v)^e with r the light direction mirrored about the normal
/// (per unit light, no cosine): the "phong" material's classic convention.
float classic_phong(float ks, float e, const Vec3& wo, const Vec3& wi) {
    if (!(wo.z > 0.0f && wi.z > 0.0f)) return 0.0f;
    const Vec3 r(-wi.x, -wi.y, wi.z);
    return ks * std::pow(std::max(0.0f, glm::dot(r, wo)), e);
}

/// Energy reflected from light arriving along the normal: integral over the hemisphere of the shaded value
/// per unit irradiance times cos(theta_o) (radiance to exitance), by the midpoint rule in cos(theta_o); the
/// lobe is symmetric about the normal here, so phi integrates to 2 pi.
double albedo_at_normal(const std::function<float(const Vec3&, const Vec3&)>& shade) {
    constexpr int n = 200000;
    const Vec3 wi(0.0f, 0.0f, 1.0f);
    double sum = 0.0;
    for (int k = 0; k < n; ++k) {
        const double c = (k + 0.5) / n, s = std::sqrt(std::max(0.0, 1.0 - c * c));
        const Vec3 wo(static_cast<float>(s), 0.0f, static_cast<float>(c));
        sum += static_cast<double>(shade(wo, wi)) * c;
    }
    return 2.0 * kPi * sum / n;
}

}  // namespace

int main(int argc, char** argv) {
    std::string out_path;
    int runs = 9;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--runs") && i + 1 < argc)
            runs = std::atoi(argv[++i]);
        else
            out_path = argv[i];
    }
    std::ofstream file;
    if (!out_path.empty()) file.open(out_path);
    std::ostream& out = out_path.empty() ? std::cout : file;
    out << "family,method,parameter,ns_per_eval,energy_error,max_abs_error,runs\n";

    Rng rng(42);
    std::vector<float> cosines(kBatch);
    for (float& c : cosines) c = rng.uniform();
    for (float eta : {1.0f / 1.33f, 1.0f / 1.5f, 1.0f / 2.4f, 1.5f}) {
        double r_exact = 0.0, r_schlick = 0.0, worst = 0.0;
        constexpr int n = 200000;
        for (int k = 0; k < n; ++k) {
            const double c = (k + 0.5) / n;
            const double fe = fresnel_dielectric(static_cast<float>(c), eta);
            const double fs = fresnel_schlick(static_cast<float>(c), eta);
            r_exact += fe * 2.0 * c / n;
            r_schlick += fs * 2.0 * c / n;
            worst = std::max(worst, std::abs(fs - fe));
        }
        const double t_exact = time_per_eval(runs, [&](int i) { return fresnel_dielectric(cosines[i], eta); });
        const double t_schlick = time_per_eval(runs, [&](int i) { return fresnel_schlick(cosines[i], eta); });
        char param[32];
        std::snprintf(param, sizeof param, "eta %.3f", static_cast<double>(eta));
        out << "fresnel,exact," << param << ',' << t_exact << ",0,0," << runs << '\n';
        out << "fresnel,schlick," << param << ',' << t_schlick << ',' << std::abs(r_schlick - r_exact) << ',' << worst
            << ',' << runs << '\n';
    }

    struct Pair {
        Vec3 wo, wi;
    };
    std::vector<Pair> pairs(kBatch);
    auto hemisphere = [&] {
        const float z = rng.uniform(), phi = 2.0f * kPi * rng.uniform(), r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        return Vec3(r * std::cos(phi), r * std::sin(phi), z);
    };
    for (Pair& p : pairs) p = {hemisphere(), hemisphere()};
    constexpr float ks = 0.5f;
    for (float e : {1.0f, 10.0f, 100.0f, 1000.0f}) {
        const PhongBrdf normalised(RGB(0.0f), RGB(ks), e);
        const Brdf* f = &normalised;  // through the interface, as the shading code calls it
        auto physical = [&](const Vec3& wo, const Vec3& wi) { return f->eval(wo, wi).r * wi.z; };
        auto classic = [&](const Vec3& wo, const Vec3& wi) { return classic_phong(ks, e, wo, wi); };
        const double t_norm = time_per_eval(runs, [&](int i) { return physical(pairs[i].wo, pairs[i].wi); });
        const double t_classic = time_per_eval(runs, [&](int i) { return classic(pairs[i].wo, pairs[i].wi); });
        const double a_norm = albedo_at_normal(physical), a_classic = albedo_at_normal(classic);
        char param[32];
        std::snprintf(param, sizeof param, "exponent %g", static_cast<double>(e));
        out << "phong,normalised," << param << ',' << t_norm << ',' << std::abs(a_norm - ks) / ks << ",0," << runs
            << '\n';
        out << "phong,classic," << param << ',' << t_classic << ',' << std::abs(a_classic - ks) / ks << ",0," << runs
            << '\n';
    }
    return 0;
}
