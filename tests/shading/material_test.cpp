#include <rtlab/core/error.hpp>
#include <rtlab/shading/brdf.hpp>
#include <rtlab/shading/material.hpp>
#include <rtlab/textures/image_texture.hpp>
#include <rtlab/textures/texture_param.hpp>

#include <catch2/catch.hpp>

#include "shared_data.hpp"
#include "skip.hpp"

#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

using namespace rtlab;

namespace {
std::shared_ptr<Material> make(const std::string& name, Params p = {}) {
    static const MaterialRegistry registry = make_material_registry();
    return registry.create(name, std::move(p));
}

// A texture that returns a fixed, possibly absurd, value: what a badly made image could give.
class FixedTexture final : public Texture {
public:
    explicit FixedTexture(const RGB& c) : m_c(c) {}
    RGB eval(const TextureLookup&) const override { return m_c; }

private:
    RGB m_c;
};

// A texture that says where it was looked up, to check what a material passes on.
class UvTexture final : public Texture {
public:
    RGB eval(const TextureLookup& q) const override { return {q.uv.x, q.uv.y, q.point.z}; }
};

// A texture with an alpha channel whose colour and alpha disagree, as an RGBA image's may.
class AlphaTexture final : public Texture {
public:
    AlphaTexture(const RGB& c, float a) : m_c(c), m_a(a) {}
    RGB eval(const TextureLookup&) const override { return m_c; }
    bool has_alpha() const override { return true; }
    float alpha(const TextureLookup&) const override { return m_a; }

private:
    RGB m_c;
    float m_a;
};

std::string error_of(const std::string& name, Params p) {
    try {
        make(name, std::move(p));
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

const Vec3 kUp(0.0f, 0.0f, 1.0f);
Vec3 at_angle(float degrees, float azimuth_degrees = 0.0f) {
    const float t = degrees * kPi / 180.0f, p = azimuth_degrees * kPi / 180.0f;
    return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}
}  // namespace

TEST_CASE("every built-in material is registered with its parameters documented", "[material]") {
    const MaterialRegistry r = make_material_registry();
    CHECK(r.category() == "material");
    CHECK(r.names() == std::vector<std::string>{"ashikhmin-shirley", "blinn-phong", "cook-torrance", "glass", "lambert",
                                                "mirror", "phong", "rough-dielectric"});
    for (const auto& name : r.names()) {
        INFO(name);
        // The shared keys are declared by every material, as one group, once each.
        for (const ParamSpec& shared : material_shared_params()) {
            const ParamSpec* p = r.spec(name).find(shared.name);
            REQUIRE(p != nullptr);
            CHECK(p->group == "material");
        }
        CHECK(r.doc(name).find("opacity") == std::string::npos);
        CHECK(make(name) != nullptr);
    }
}

TEST_CASE("unknown and misspelt material parameters are rejected naming the material", "[material]") {
    Params p;
    p.set("albdo", 0.5);
    const std::string e = error_of("lambert", p);
    CHECK(e.find("material 'lambert'") != std::string::npos);
    CHECK(e.find("albdo") != std::string::npos);
    Params q;
    q.set("kd", 0.5);  // Phong's name, not Lambert's
    CHECK(error_of("lambert", q).find("'kd'") != std::string::npos);
    Params g;
    g.set("exponent", 10.0);  // glass has no exponent
    CHECK(error_of("glass", g).find("material 'glass'") != std::string::npos);
}

TEST_CASE("bad material values are rejected naming the parameter", "[material]") {
    auto one = [](const char* key, Params::Value v) {
        Params p;
        p.set(key, std::move(v));
        return p;
    };
    CHECK(error_of("glass", one("ior", -1.5)).find("'ior'") != std::string::npos);
    CHECK(error_of("glass", one("ior", 0.0)).find("'ior'") != std::string::npos);
    CHECK(error_of("phong", one("exponent", -1.0)).find("'exponent'") != std::string::npos);
    CHECK(error_of("lambert", one("kr", -0.5)).find("'kr'") != std::string::npos);
    CHECK(error_of("lambert", one("opacity", 1.5)).find("'opacity'") != std::string::npos);
    CHECK(error_of("lambert", one("absorption", -1.0)).find("'absorption'") != std::string::npos);
    CHECK(error_of("lambert", one("fresnel", 1.0)).find("'fresnel'") != std::string::npos);
    CHECK(error_of("lambert", one("albedo", std::string("red"))).find("'albedo'") != std::string::npos);
}

TEST_CASE("constant kr plus kt above 1 is rejected unless Fresnel weights them", "[material]") {
    Params p;
    p.set("kr", 0.7).set("kt", Params::List{0.1, 0.4, 0.2});
    const std::string e = error_of("lambert", p);
    CHECK(e.find("kt exceeds 1") != std::string::npos);
    CHECK(e.find("material 'lambert'") != std::string::npos);
    Params ok;
    ok.set("kr", 0.7).set("kt", 0.3);
    CHECK_NOTHROW(make("lambert", ok));
    Params f;
    f.set("kr", 0.7).set("kt", 0.6).set("fresnel", true);
    CHECK_NOTHROW(make("lambert", f));
    Params g;
    g.set("fresnel", false);  // glass's kr = kt = 1 then add up to 2
    CHECK(error_of("glass", g).find("kt exceeds 1") != std::string::npos);
    Params big;
    big.set("kt", 1.5).set("fresnel", true);
    CHECK(error_of("glass", big).find("'kt' must be <= 1") != std::string::npos);
}

TEST_CASE("textured kr and kt above 1 are scaled down per hit and never give NaN", "[material]") {
    const float nan = std::nanf("");
    for (const RGB& kr : {RGB(5.0f), RGB(0.9f, 0.2f, 0.0f), RGB(-3.0f), RGB(nan), RGB(kInfinity)}) {
        Params p;
        p.set_object<Texture>("kr", std::make_shared<FixedTexture>(kr));
        p.set_object<Texture>("kt", std::make_shared<FixedTexture>(RGB(0.6f)));
        p.set_object<Texture>("opacity", std::make_shared<FixedTexture>(RGB(nan)));
        const auto m = make("lambert", p);
        const SurfaceTerms t = m->terms({});
        INFO(kr.r);
        REQUIRE(t.kr.is_finite());
        REQUIRE(t.kt.is_finite());
        CHECK(t.kr.r >= 0.0f);
        CHECK((t.kr + t.kt).max_component() <= 1.0f + 1e-6f);
        CHECK(t.opacity == 1.0f);  // a NaN alpha counts as opaque
        CHECK(m->shadow_transmittance({}).is_finite());
    }
    // kr = 0.9, kt = 0.6 sum to 1.5 in g: both scaled by 1 / 1.5.
    Params p;
    p.set_object<Texture>("kr", std::make_shared<FixedTexture>(RGB(0.9f)));
    p.set("kt", 0.6);
    const SurfaceTerms t = make("lambert", p)->terms({});
    CHECK(t.kr.g == Approx(0.6f));
    CHECK(t.kt.g == Approx(0.4f));
}

TEST_CASE("every colour parameter takes a constant or a texture under one key", "[material]") {
    const auto uv = std::make_shared<UvTexture>();
    TextureLookup q;
    q.uv = {0.25f, 0.75f};
    q.point = {0.0f, 0.0f, 0.5f};
    for (const char* key : {"albedo", "kr", "emission", "opacity"}) {
        INFO(key);
        Params p;
        p.set_object<Texture>(key, uv);
        if (std::string(key) == "kr") p.set("kt", 0.0);
        const SurfaceTerms t = make("lambert", p)->terms(q);
        if (std::string(key) == "albedo") CHECK(t.diffuse == RGB(0.25f, 0.75f, 0.5f));
        if (std::string(key) == "kr") CHECK(t.kr == RGB(0.25f, 0.75f, 0.5f));
        if (std::string(key) == "emission") CHECK(t.emission == RGB(0.25f, 0.75f, 0.5f));
        if (std::string(key) == "opacity") CHECK(t.opacity == 0.5f);  // no alpha: the channel mean
    }
    for (const char* key : {"kd", "ks", "exponent"}) {
        INFO(key);
        Params p;
        p.set_object<Texture>(key, uv);
        const SurfaceTerms t = make("phong", p)->terms(q);
        if (std::string(key) == "kd") CHECK(t.diffuse == RGB(0.25f, 0.75f, 0.5f));
        if (std::string(key) == "ks") CHECK(t.specular == RGB(0.25f, 0.75f, 0.5f));
        if (std::string(key) == "exponent") CHECK(t.shape_u == 0.5f);  // a scalar is the channel mean
    }
}

TEST_CASE("shadow transmittance is 1 - opacity + opacity kt and flags the materials that have it", "[material]") {
    CHECK_FALSE(make("lambert")->transmits_shadows());
    CHECK_FALSE(make("mirror")->transmits_shadows());
    CHECK(make("glass")->transmits_shadows());
    Params p;
    p.set("kt", 0.5).set("opacity", 0.5);
    const auto m = make("lambert", p);
    CHECK(m->transmits_shadows());
    CHECK(m->shadow_transmittance({}).g == Approx(0.75f));
    Params cut;
    cut.set_object<Texture>("opacity", std::make_shared<FixedTexture>(RGB(1.0f)));
    CHECK(make("lambert", cut)->transmits_shadows());  // a texture may cut holes anywhere
    CHECK(make("lambert", cut)->shadow_transmittance({}).is_black());
}

TEST_CASE("opacity is a texture's alpha when it has one, else its channel mean", "[material]") {
    // Colour 0.9, alpha 0.2: a rule that read the colour would give 0.9 (mean) or 0.9 (any channel).
    Params p;
    p.set_object<Texture>("opacity", std::make_shared<AlphaTexture>(RGB(0.9f), 0.2f));
    const auto m = make("lambert", p);
    CHECK(m->terms({}).opacity == 0.2f);
    CHECK(m->shadow_transmittance({}).g == Approx(0.8f));
    // Without alpha, the mean of the channels: 0.1, 0.2, 0.6 give 0.3, not the green 0.2.
    Params q;
    q.set_object<Texture>("opacity", std::make_shared<FixedTexture>(RGB(0.1f, 0.2f, 0.6f)));
    CHECK(make("lambert", q)->terms({}).opacity == Approx(0.3f));
    // A constant list is read by the same rule, and checked in [0, 1] by it.
    Params c;
    c.set("opacity", Params::List{0.1, 0.2, 0.6});
    CHECK(make("lambert", c)->terms({}).opacity == Approx(0.3f));
    CHECK(make("lambert", c)->transmits_shadows());
    Params bad;
    bad.set("opacity", Params::List{1.0, 1.0, 1.6});
    CHECK(error_of("lambert", bad).find("'opacity'") != std::string::npos);
}

TEST_CASE("an RGBA PNG is both the colour and the cut-out of Saturn's rings", "[material]") {
    const auto shared = test::shared_dir();
    if (!shared) return test::skip(test::needs_shared("saturn_ring.png"));
    // saturn_ring.png: a radial strip, alpha 0 for the innermost ~5% (x < 108 of 2048), ~0.9 across the B ring.
    const auto ring = ImageTexture::load(*shared / "textures" / "saturn_ring.png", {.wrap = WrapMode::clamp});
    REQUIRE(ring->has_alpha());
    Params p;
    p.set_object<Texture>("albedo", ring).set_object<Texture>("opacity", ring);
    const auto m = make("lambert", p);
    CHECK(m->transmits_shadows());
    int holes = 0, solid = 0, wrong = 0;
    for (int x = 0; x < 2048; ++x) {
        TextureLookup q;
        q.uv = {(static_cast<float>(x) + 0.5f) / 2048.0f, 0.5f};
        const SurfaceTerms t = m->terms(q);
        const float a = ring->alpha(q);
        if (t.opacity != a || t.diffuse != ring->eval(q)) ++wrong;
        if (m->shadow_transmittance(q).g != Approx(1.0f - a).margin(1e-6)) ++wrong;
        if (x < 100 && t.opacity == 0.0f && m->shadow_transmittance(q) == RGB(1.0f)) ++holes;
        if (a > 0.8f) ++solid;
    }
    CHECK(wrong == 0);
    CHECK(holes == 100);  // the gap inside the rings lets everything through
    CHECK(solid > 200);   // and the B ring very little
}

TEST_CASE("classic and physical conventions differ exactly as defined", "[material]") {
    // Hand values with light 60 degrees off the normal and the viewer in the mirror direction.
    const Vec3 wi = at_angle(60.0f), wo = at_angle(60.0f, 180.0f);
    Params lp;
    lp.set("albedo", 0.5);
    const auto lambert = make("lambert", lp);
    const SurfaceTerms lt = lambert->terms({});
    CHECK(lambert->direct(lt, wo, wi, Convention::physical).g == Approx(0.5f * 0.5f / kPi));
    CHECK(lambert->direct(lt, wo, wi, Convention::classic).g == Approx(0.25f));

    Params pp;
    pp.set("kd", 0.5).set("ks", 0.5).set("exponent", 10.0);
    for (const char* name : {"phong", "blinn-phong"}) {
        INFO(name);
        const auto m = make(name, pp);
        const SurfaceTerms t = m->terms({});
        // Classic at the mirror direction: kd cos + ks 1^e = 0.25 + 0.5.
        CHECK(m->direct(t, wo, wi, Convention::classic).g == Approx(0.75f));
        // Physical: the normalised BRDF times cos. Phong by hand, (kd / pi + ks (e + 2) / 2pi) cos; Blinn-Phong's
        // normalisation belongs to BlinnPhongBrdf (tested in brdf_test), the cosine and no-pi choice to us.
        const float physical = std::string(name) == "phong"
                                   ? (0.5f / kPi + 0.5f * 12.0f / (2.0f * kPi)) * 0.5f
                                   : BlinnPhongBrdf(RGB(0.5f), RGB(0.5f), 10.0f).eval(wo, wi).g * 0.5f;
        CHECK(m->direct(t, wo, wi, Convention::physical).g == Approx(physical));
        // Off the mirror direction by 20 degrees: Phong's (r.v)^e = cos(20)^10, Blinn's (n.h)^e = cos(10)^10.
        const Vec3 wo2 = at_angle(40.0f, 180.0f);
        const float spec = std::string(name) == "phong" ? std::pow(std::cos(20.0f * kPi / 180.0f), 10.0f)
                                                        : std::pow(std::cos(10.0f * kPi / 180.0f), 10.0f);
        CHECK(m->direct(t, wo2, wi, Convention::classic).g == Approx(0.25f + 0.5f * spec));
    }
    // Below the surface on either side: black in both conventions.
    for (Convention c : {Convention::physical, Convention::classic}) {
        CHECK(lambert->direct(lt, wo, -wi, c).is_black());
        CHECK(lambert->direct(lt, -wo, wi, c).is_black());
    }
    CHECK_FALSE(make("mirror")->reflects_direct_light());
    CHECK_FALSE(make("glass")->reflects_direct_light());
    CHECK(make("phong")->direct(make("phong")->terms({}), kUp, kUp, Convention::classic).g == Approx(1.0f));
}

TEST_CASE("cook-torrance is the CookTorranceBrdf times cos with each Fresnel convention checked by hand",
          "[material]") {
    // Light 60 degrees off the normal, viewer in the mirror direction: h = n and cos_d = cos 60 = 0.5.
    const Vec3 wi = at_angle(60.0f), wo = at_angle(60.0f, 180.0f);
    const auto ggx = MicrofacetDistribution::from_roughness(MicrofacetModel::ggx, 0.4f);
    const RGB lobe = CookTorranceBrdf(RGB(0.0f), RGB(1.0f), ggx, Fresnel::one()).eval(wo, wi) * wi.z;
    REQUIRE(lobe.g > 0.0f);
    auto direct = [&](Params p, Convention c = Convention::physical) {
        p.set("roughness", 0.4).set("kd", 0.0);
        const auto m = make("cook-torrance", p);
        return m->direct(m->terms({}), wo, wi, c);
    };
    // A dielectric lobe: ior over ior_outside in Fresnel::dielectric's convention. By hand with
    // fresnel_dielectric's n_incident / n_transmitted: light from the outside, 1 / 1.5. The reversed
    // convention would put 60 degrees beyond the critical angle and give F = 1.
    const float f_glass = fresnel_dielectric(0.5f, 1.0f / 1.5f);
    REQUIRE(f_glass < 0.1f);
    CHECK(direct({}).g == Approx(lobe.g * f_glass).epsilon(1e-5));  // ior defaults to 1.5
    Params water;
    water.set("ior", 1.5).set("ior_outside", 1.33);
    CHECK(direct(water).g == Approx(lobe.g * fresnel_dielectric(0.5f, 1.33f / 1.5f)).epsilon(1e-5));
    // Conductors: the measured presets and an explicit eta and k, per channel, against fresnel_conductor.
    Params gold;
    gold.set("metal", std::string("gold"));
    const RGB fg = fresnel_conductor(0.5f, kGold);
    const RGB g = direct(gold);
    CHECK(g.r == Approx(lobe.r * fg.r).epsilon(1e-5));
    CHECK(g.b == Approx(lobe.b * fg.b).epsilon(1e-5));
    CHECK(g.r > 2.0f * g.b);  // gold is yellow
    Params explicit_ior;
    explicit_ior.set("eta", Params::List{0.14, 0.43, 1.38}).set("k", Params::List{3.697, 2.455, 1.914});
    CHECK(direct(explicit_ior).g == Approx(g.g).epsilon(1e-6));
    // In water the metal's tabulated index is divided by the outside's.
    Params gold_in_water = gold;
    gold_in_water.set("ior_outside", 1.33);
    const ComplexIor in_water{kGold.eta / 1.33f, kGold.k / 1.33f};
    CHECK(direct(gold_in_water).g == Approx(lobe.g * fresnel_conductor(0.5f, in_water).g).epsilon(1e-5));
    // Classic: the same times pi (kd (n.l) for the diffuse part).
    CHECK(direct(gold, Convention::classic).g == Approx(kPi * g.g).epsilon(1e-6));
    // Beckmann is another lobe; kd adds kd / pi cos.
    Params beckmann;
    beckmann.set("distribution", std::string("beckmann"));
    const auto bk = MicrofacetDistribution::from_roughness(MicrofacetModel::beckmann, 0.4f);
    CHECK(direct(beckmann).g ==
          Approx(CookTorranceBrdf(RGB(0.0f), RGB(1.0f), bk, Fresnel::dielectric(1.5f)).eval(wo, wi).g * wi.z)
              .epsilon(1e-5));
    CHECK(direct(beckmann).g != Approx(direct({}).g).epsilon(1e-2));
}

TEST_CASE("cook-torrance and ashikhmin-shirley reject bad parameters and survive absurd textures", "[material]") {
    auto one = [](const char* key, Params::Value v) {
        Params p;
        p.set(key, std::move(v));
        return p;
    };
    CHECK(error_of("cook-torrance", one("roughness", 1.5)).find("'roughness'") != std::string::npos);
    CHECK(error_of("cook-torrance", one("distribution", std::string("phong"))).find("'distribution'") !=
          std::string::npos);
    CHECK(error_of("cook-torrance", one("metal", std::string("brass"))).find("'metal'") != std::string::npos);
    CHECK(error_of("cook-torrance", one("eta", 0.5)).find("'k'") != std::string::npos);
    CHECK(error_of("cook-torrance", one("kd", -0.1)).find("'kd'") != std::string::npos);
    Params both;
    both.set("metal", std::string("gold")).set("eta", 0.5).set("k", 2.0);
    CHECK(error_of("cook-torrance", both).find("'metal'") != std::string::npos);
    Params neg_eta;
    neg_eta.set("eta", Params::List{1.0, -1.0, 1.0}).set("k", 1.0);
    CHECK(error_of("cook-torrance", neg_eta).find("'eta'") != std::string::npos);
    CHECK(error_of("ashikhmin-shirley", one("nu", -1.0)).find("'nu'") != std::string::npos);
    CHECK(error_of("ashikhmin-shirley", one("nv", 1e20)).find("'nv'") != std::string::npos);
    CHECK(error_of("ashikhmin-shirley", one("rs", -0.5)).find("'rs'") != std::string::npos);

    // Textures giving NaN, infinities or negatives reach neither an exception nor a NaN.
    const float nan = std::nanf("");
    const Vec3 wi = at_angle(30.0f), wo = at_angle(50.0f, 150.0f);
    for (const RGB& bad : {RGB(nan), RGB(kInfinity), RGB(-2.0f), RGB(1e30f)}) {
        INFO(bad.r);
        auto tex = std::make_shared<FixedTexture>(bad);
        Params ct;
        ct.set_object<Texture>("kd", tex).set_object<Texture>("ks", tex).set_object<Texture>("roughness", tex);
        Params as;
        as.set_object<Texture>("rd", tex).set_object<Texture>("rs", tex);
        as.set_object<Texture>("nu", tex).set_object<Texture>("nv", tex);
        for (const auto& [name, p] : {std::pair{"cook-torrance", ct}, std::pair{"ashikhmin-shirley", as}}) {
            INFO(name);
            const auto m = make(name, p);
            RGB f;
            REQUIRE_NOTHROW(f = m->direct(m->terms({}), wo, wi, Convention::physical));
            CHECK_FALSE(std::isnan(f.r + f.g + f.b));
            CHECK(f.r >= 0.0f);
        }
    }
}

TEST_CASE("ashikhmin-shirley is the AshikhminShirleyBrdf times cos, nu along local x, nv default nu", "[material]") {
    const Vec3 wi = at_angle(40.0f, 10.0f), wo = at_angle(35.0f, 200.0f);
    Params p;
    p.set("rd", 0.3).set("rs", 0.2).set("nu", 2000.0).set("nv", 20.0);
    const auto m = make("ashikhmin-shirley", p);
    const SurfaceTerms t = m->terms({});
    const RGB expected = AshikhminShirleyBrdf(RGB(0.3f), RGB(0.2f), 2000.0f, 20.0f).eval(wo, wi) * wi.z;
    CHECK(m->direct(t, wo, wi, Convention::physical).g == Approx(expected.g).epsilon(1e-6));
    CHECK(m->direct(t, wo, wi, Convention::classic).g == Approx(kPi * expected.g).epsilon(1e-6));
    // The lobe around the mirror direction is narrow where the half vector tilts along x (nu = 2000) and
    // wide along y (nv = 20): the viewer 8 degrees off the mirror direction each way, the half vector ~4.
    const Vec3 l = at_angle(30.0f);
    const float along_x = m->direct(t, at_angle(38.0f, 180.0f), l, Convention::physical).g;
    const float along_y =
        m->direct(t, glm::normalize(at_angle(30.0f, 180.0f) + Vec3(0, 0.14f, 0)), l, Convention::physical).g;
    CHECK(along_y > 20.0f * along_x);
    // nv defaults to nu: an isotropic lobe.
    Params iso;
    iso.set("nu", 200.0);
    const auto mi = make("ashikhmin-shirley", iso);
    CHECK(mi->terms({}).shape_v == 200.0f);
}

namespace {
// A model made outside the library (as a plugin's would be) that never says its terms are constant.
class PlainMaterial final : public Material {
public:
    PlainMaterial() : Material(Whitted{}) {}
    RGB direct(const SurfaceTerms&, const Vec3&, const Vec3&, Convention) const override { return {}; }

protected:
    void local_terms(const TextureLookup&, SurfaceTerms& t) const override { t.diffuse = RGB(0.25f); }
};
}  // namespace

TEST_CASE("constant materials give one record for every lookup and textured ones still read theirs", "[material]") {
    // Lookups that a texture would tell apart; a constant material must not.
    TextureLookup a, b;
    a.uv = {0.1f, 0.7f};
    a.point = {1.0f, 2.0f, 3.0f};
    b.uv = {0.9f, 0.2f};
    b.point = {-4.0f, 0.5f, 8.0f};
    auto same = [](const SurfaceTerms& x, const SurfaceTerms& y) {
        return x.diffuse == y.diffuse && x.specular == y.specular && x.shape_u == y.shape_u && x.shape_v == y.shape_v &&
               x.kr == y.kr && x.kt == y.kt && x.emission == y.emission && x.opacity == y.opacity;
    };
    Params phong;
    phong.set("kd", Params::List{0.3, 0.2, 0.1}).set("ks", 0.4).set("exponent", 30.0).set("kr", 0.25);
    for (const auto& [name, params] : std::vector<std::pair<std::string, Params>>{{"lambert", {}},
                                                                                  {"phong", phong},
                                                                                  {"blinn-phong", {}},
                                                                                  {"cook-torrance", {}},
                                                                                  {"ashikhmin-shirley", {}},
                                                                                  {"mirror", {}},
                                                                                  {"glass", {}}}) {
        INFO(name);
        const auto m = make(name, params);
        CHECK_FALSE(m->reads_lookup());
        CHECK(same(m->terms(a), m->terms(b)));
    }
    const SurfaceTerms p = make("phong", phong)->terms(a);
    CHECK(p.diffuse == RGB(0.3f, 0.2f, 0.1f));
    CHECK(p.specular == RGB(0.4f));
    CHECK(p.shape_u == 30.0f);
    CHECK(p.kr == RGB(0.25f));
    CHECK(p.opacity == 1.0f);
    // One texture anywhere, in the model's own terms or in the Whitted ones, and every hit is looked up.
    Params kd, kt, emission;
    kd.set_object<const Texture>("kd", std::make_shared<UvTexture>());
    kt.set_object<const Texture>("kt", std::make_shared<UvTexture>());
    emission.set_object<const Texture>("emission", std::make_shared<UvTexture>());
    for (Params* params : {&kd, &kt, &emission}) {
        const auto m = make("phong", *params);
        CHECK(m->reads_lookup());
        CHECK_FALSE(same(m->terms(a), m->terms(b)));
    }
    CHECK(make("phong", kd)->terms(b).diffuse == RGB(0.9f, 0.2f, 8.0f));
    // A model that does not declare its terms constant keeps its own local_terms on every hit.
    const PlainMaterial plain;
    CHECK(plain.reads_lookup());
    CHECK(plain.terms(a).diffuse == RGB(0.25f));
}
