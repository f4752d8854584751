#pragma once
// The material configurations the sampled-material tests run over: every built-in model at three roughness
// values (exponents, alphas) and incident angles from normal to grazing (cos theta <= 0.05), on both sides.
#include <rtlab/core/params.hpp>
#include <rtlab/shading/material.hpp>
#include <rtlab/shading_testing/bsdf_check.hpp>

#include "sample_scale.hpp"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace rtlab::test {

/// One material to test: a registry type and its parameters, and whether light goes through it.
struct MaterialCase {
    std::string label;
    std::shared_ptr<const Material> material;
    bool transmits = false;
};

inline std::shared_ptr<const Material> make_material(const std::string& type, Params p) {
    static const MaterialRegistry registry = make_material_registry();
    return registry.create(type, std::move(p));
}

/// Incident cosines: normal, oblique, grazing (<= 0.05) above, and from below (opaque models are two-sided,
/// dielectrics are entered from inside, beyond the critical angle too).
inline std::vector<float> opaque_cosines() { return shading_testing::BsdfCheckOptions{}.cosines; }
inline std::vector<float> dielectric_cosines() { return {1.0f, 0.7f, 0.3f, 0.05f, -0.9f, -0.6f, -0.05f}; }

/// The glossy models at three shape values each, from wide to a lobe narrower than a degree.
inline std::vector<MaterialCase> glossy_cases() {
    std::vector<MaterialCase> cases;
    auto add = [&](std::string label, const std::string& type, Params p, bool transmits = false) {
        cases.push_back({std::move(label), make_material(type, std::move(p)), transmits});
    };
    add("lambert", "lambert", Params().set("albedo", 0.7));
    for (double e : {5.0, 200.0, 5000.0}) {
        add("phong e " + std::to_string(e), "phong", Params().set("kd", 0.4).set("ks", 0.5).set("exponent", e));
        add("blinn-phong e " + std::to_string(e), "blinn-phong",
            Params().set("kd", 0.4).set("ks", 0.5).set("exponent", e));
    }
    for (double r : {0.01, 0.3, 0.9}) {
        add("cook-torrance ggx r " + std::to_string(r), "cook-torrance",
            Params().set("kd", 0.3).set("roughness", r).set("distribution", std::string("ggx")));
        add("cook-torrance beckmann gold r " + std::to_string(r), "cook-torrance",
            Params()
                .set("roughness", r)
                .set("distribution", std::string("beckmann"))
                .set("metal", std::string("gold")));
        add("rough-dielectric ggx r " + std::to_string(r), "rough-dielectric", Params().set("roughness", r), true);
    }
    add("rough-dielectric beckmann r 0.3", "rough-dielectric",
        Params().set("roughness", 0.3).set("distribution", std::string("beckmann")), true);
    for (auto [nu, nv] : {std::pair(5.0, 20.0), std::pair(100.0, 1000.0), std::pair(5000.0, 5000.0)})
        add("ashikhmin-shirley nu " + std::to_string(nu) + " nv " + std::to_string(nv), "ashikhmin-shirley",
            Params().set("rd", 0.4).set("rs", 0.3).set("nu", nu).set("nv", nv));
    // The Whitted terms as delta lobes and a cut-out around a sampled model: the density covers only the
    // model's share.
    add("lambert with kr kt and opacity", "lambert",
        Params().set("albedo", 0.6).set("kr", 0.2).set("kt", 0.3).set("ior", 1.5).set("opacity", 0.7));
    return cases;
}

/// The incident direction for cosine c, at an azimuth off the axes (Ashikhmin-Shirley is anisotropic).
inline Vec3 incident(float c) { return shading_testing::incident_direction(c); }

}  // namespace rtlab::test
