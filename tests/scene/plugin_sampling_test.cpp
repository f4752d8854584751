// Sampled plugin materials through the checks a plugin author runs on their own material
// (rtlab/shading_testing/bsdf_check.hpp, docs/sampled-materials.md): chi-square of sample() against pdf(), the
// pdf's normalisation, sample() against eval() and pdf(), albedo <= 1 and reciprocity, as the built-in
// materials pass them, over modules loaded as a program loads them: the toon example and the page's own
// example, gloss (tests/scene/plugins/gloss.cpp).
#include <rtlab/scene/plugin.hpp>
#include <rtlab/shading_testing/bsdf_check.hpp>

#include <catch2/catch.hpp>

#include "sample_scale.hpp"

#include <string>
#include <vector>

using namespace rtlab;

namespace {

/// The built-in materials, textures and lights and one plugin module from `folder`.
struct Module {
    MaterialRegistry materials = make_material_registry();
    TextureRegistry textures = make_texture_registry();
    LightRegistry lights = make_light_registry();
    PluginHost plugins;
    Module(const std::string& folder, const std::string& name)
        : plugins(materials, textures, lights, SearchPath({folder})) {
        plugins.load_by_name(name);
    }
};

Params::List grey(double v) { return {v, v, v}; }

/// The checks' defaults, lighter under the sanitizers: fewer draws, and normal, oblique, grazing and
/// from-below incidence only.
shading_testing::BsdfCheckOptions light_options() {
    shading_testing::BsdfCheckOptions options;
    options.chi_square_samples /= test::kSampleScale;
    options.consistency_samples /= test::kSampleScale;
    if (test::kSampleScale > 1) options.cosines = {1.0f, 0.5f, 0.04f, -0.6f};
    return options;
}

}  // namespace

TEST_CASE("the toon example's sampled lobes pass the checks of the built-in materials", "[plugins][sampling]") {
    Module toon(RTLAB_TEST_EXAMPLE_DIR, "toon");
    struct Case {
        std::string label;
        Params params;
    };
    const std::vector<Case> cases{
        // Both lobes and every Whitted term around them.
        {"with kr kt and opacity", Params()
                                       .set("color", Params::List{0.6, 0.3, 0.2})
                                       .set("highlight", grey(0.3))
                                       .set("kr", 0.2)
                                       .set("kt", 0.1)
                                       .set("ior", 1.5)
                                       .set("opacity", 0.8)},
        // A cone 78 degrees about its axis: at grazing incidence most of it lies below the horizon (lost draws).
        {"wide highlight", Params().set("color", grey(0.5)).set("highlight", grey(0.5)).set("highlight_size", 0.2)},
        // A cone half a degree about its axis, found only by the quadrature's refinement around the mirror
        // direction; color + highlight > 1, so the sampled diffuse part is lowered to 1 - highlight.
        {"narrow highlight brighter than 1", Params()
                                                 .set("color", Params::List{0.9, 0.25, 0.2})
                                                 .set("highlight", grey(0.8))
                                                 .set("highlight_size", 0.99996)},
    };
    shading_testing::BsdfCheckOptions options = light_options();
    // One family for every case, so that the union of the tests keeps the 1% significance.
    options.family_size = static_cast<int>(cases.size() * options.cosines.size());
    for (const Case& c : cases) {
        const auto material = toon.materials.create("toon", c.params);
        const shading_testing::BsdfCheckReport report =
            shading_testing::check_material(*material, material->terms(TextureLookup{}), options);
        INFO(c.label << ": " << report.message);
        CHECK(report.passed);
    }
}

TEST_CASE("the toon highlight reflects highlight (2 + highlight_size) / 3 of light at normal incidence",
          "[plugins][sampling]") {
    // The cone about the normal, cos a = c: the integral of highlight (c - s) / (pi (1 - s)^2) c over it,
    // 2 pi highlight / (pi (1 - s)^2) (1 - s)^2 (2 + s) / 6; the diffuse part adds color.
    Module toon(RTLAB_TEST_EXAMPLE_DIR, "toon");
    for (double s : {0.2, 0.97, 0.99996}) {
        const auto m = toon.materials.create(
            "toon", Params().set("color", grey(0.25)).set("highlight", grey(0.5)).set("highlight_size", s));
        const double albedo = shading_testing::directional_albedo(*m, m->terms(TextureLookup{}), Vec3(0, 0, 1),
                                                                  TransportMode::importance);
        INFO("highlight_size " << s);
        CHECK(albedo == Approx(0.25 + 0.5 * (2.0 + s) / 3.0).margin(1e-4));
    }
}

TEST_CASE("the sampled-materials page's gloss example passes the checks", "[plugins][sampling]") {
    // As docs/sampled-materials.md runs it: every check at its defaults, a lobe whose albedo is color at normal
    // incidence less what falls below the horizon.
    Module gloss(RTLAB_TEST_MODULE_DIR, "rtlab_test_gloss");
    const auto material = gloss.materials.create("gloss", Params().set("color", grey(0.9)).set("exponent", 20.0));
    const shading_testing::BsdfCheckReport report =
        shading_testing::check_material(*material, material->terms(TextureLookup{}), light_options());
    INFO(report.message);
    CHECK(report.passed);
    CHECK(report.largest_albedo <= 0.9);
}
