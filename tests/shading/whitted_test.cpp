#include <rtlab/accel/mesh_shape.hpp>
#include <rtlab/core/frame.hpp>
#include <rtlab/geometry/instance.hpp>
#include <rtlab/geometry/quad.hpp>
#include <rtlab/geometry/spawn.hpp>
#include <rtlab/geometry/sphere.hpp>
#include <rtlab/shading/brdf.hpp>
#include <rtlab/shading/optics.hpp>
#include <rtlab/shading/whitted.hpp>
#include <rtlab/textures/cube_map.hpp>

#include <catch2/catch.hpp>
#include <test_meshes.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <array>
#include <cmath>
#include <map>
#include <string>

using namespace rtlab;

namespace {
std::shared_ptr<const Material> material(const std::string& name, Params p = {}) {
    static const MaterialRegistry registry = make_material_registry();
    return registry.create(name, std::move(p));
}
std::shared_ptr<const Light> light(const std::string& name, Params p = {}) {
    static const LightRegistry registry = make_light_registry();
    return registry.create(name, std::move(p));
}
Params::List list(const Vec3& v) { return {v.x, v.y, v.z}; }
std::shared_ptr<const Light> point_light(const Point3& at, float intensity) {
    Params p;
    p.set("position", list(at)).set("intensity", intensity);
    return light("point", p);
}
std::shared_ptr<const Material> lambert(float albedo, Params p = {}) {
    p.set("albedo", albedo);
    return material("lambert", p);
}
std::shared_ptr<const Shape> quad(const Point3& corner, const Vec3& u, const Vec3& v) {
    return std::make_shared<Quad>(corner, u, v);
}
std::shared_ptr<const Shape> sphere(const Point3& c, float r) { return std::make_shared<Sphere>(c, r); }

// Directions spread over the sphere (a Fibonacci spiral): deterministic and even.
Vec3 spiral(int i, int n) {
    const float z = 1.0f - (2.0f * static_cast<float>(i) + 1.0f) / static_cast<float>(n);
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = static_cast<float>(i) * 2.39996323f;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// Environment whose colour says which way the ray left: any bend or shift of an escaping ray shows.
class DirectionTexture final : public Texture {
public:
    RGB eval(const TextureLookup& q) const override {
        const Vec3 d = glm::normalize(q.direction);
        return {0.5f + 0.5f * d.x, 0.5f + 0.5f * d.y, 0.5f + 0.5f * d.z};
    }
};

RGB max_abs_diff(const RGB& a, const RGB& b) { return {std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)}; }
}  // namespace

TEST_CASE("a Lambert sphere around a point light of intensity pi r^2 is 0.5 everywhere", "[whitted]") {
    // Physically based, direct light only: rho / pi * I / r^2 * cos 0 = 0.5 at every point, seen from inside
    // (the back faces), for a sphere and a scaled Instance of one, small and large, at the origin and away
    // from it (as far as float positions resolve the sphere to the 2e-5 asked for).
    const std::pair<float, Point3> cases[] = {{1.0f, Point3(0.0f)},
                                              {1e-3f, Point3(0.0f)},
                                              {1e3f, Point3(0.0f)},
                                              {1.0f, Point3(1.0f, -2.0f, 0.5f)},
                                              {1e-3f, Point3(1e-3f, 0, 2e-3f)},
                                              {1e3f, Point3(1e3f, -2e3f, 5e2f)}};
    for (const auto& [r, c] : cases) {
        for (bool instance : {false, true}) {
            ShapeList scene;
            std::shared_ptr<const Shape> s = sphere(c, r);
            if (instance)
                s = std::make_shared<Instance>(sphere(Point3(0.0f), 1.0f),
                                               glm::scale(glm::translate(Mat4(1.0f), c), Vec3(r)));
            scene.add(s, lambert(0.5f));
            const WhittedIntegrator w(scene, {point_light(c, kPi * r * r)});
            RayStats stats;
            int off = 0;
            const int n = 500;
            for (int i = 0; i < n; ++i) {
                const RGB L = w.radiance(Ray{c, spiral(i, n)}, {}, stats);
                if (std::abs(L.g - 0.5f) > 2e-5f) ++off;
            }
            INFO("r " << r << " centre " << c.x << " instance " << instance);
            CHECK(off == 0);
            CHECK(stats.shadow == static_cast<std::uint64_t>(n));
        }
    }
}

TEST_CASE("a glass sphere of index 1 leaves what is behind it unchanged", "[whitted]") {
    Params g;
    g.set("ior", 1.0);
    WhittedOptions options;
    options.environment = std::make_shared<DirectionTexture>();
    // A lit Lambert floor behind the sphere; the light shines through the sphere (kt = 1) onto it.
    auto build = [&](bool with_glass, ShapeList& scene) {
        scene.add(quad(Point3(-20, -2, -20), Vec3(0, 0, 40), Vec3(40, 0, 0)), lambert(0.8f));
        if (with_glass) scene.add(sphere(Point3(0.0f), 1.0f), material("glass", g));
    };
    ShapeList glass, empty;
    build(true, glass);
    build(false, empty);
    const std::vector<std::shared_ptr<const Light>> lights{point_light(Point3(0.3f, 5.0f, 0.2f), 30.0f)};
    const WhittedIntegrator wg(glass, lights, options), we(empty, lights, options);
    int through = 0, worst_off = 0;
    float worst = 0.0f;
    for (int i = 0; i < 2000; ++i) {
        const Vec3 aim = 0.99f * spiral(i, 2000);
        const Point3 eye(0.1f, 0.7f, 6.0f);
        const Ray ray{eye, aim - eye};
        RayStats sg, se;
        const RGB a = wg.radiance(ray, {}, sg), b = we.radiance(ray, {}, se);
        if (sg.refracted > 0) ++through;
        const float diff = max_abs_diff(a, b).max_component();
        worst = std::max(worst, diff);
        if (diff > 1e-4f) ++worst_off;
    }
    INFO("largest difference " << worst);
    CHECK(through > 1000);
    CHECK(worst_off == 0);
}

TEST_CASE("a ray inside a glass sphere finds the exit with the Fresnel share", "[whitted]") {
    WhittedOptions options;
    options.background = RGB(1.0f);
    options.min_weight = 0.0f;
    Params no_reflection;
    no_reflection.set("kr", 0.0);
    ShapeList scene;
    scene.add(sphere(Point3(0.0f), 1.0f), material("glass", no_reflection));
    const WhittedIntegrator w(scene, {}, options);
    int tir = 0, exits = 0;
    for (int i = 0; i < 1000; ++i) {
        const Point3 o = 0.9f * spiral(i, 1000) * (static_cast<float>(i % 10) / 10.0f);
        const Vec3 d = spiral((i * 37) % 1000, 1000);
        // Where the ray leaves, and the Fresnel transmittance there (glass 1.5 to air).
        const float b = glm::dot(o, d), c = glm::dot(o, o) - 1.0f;
        const Point3 p = o + (-b + std::sqrt(b * b - c)) * d;
        const float cos_i = glm::dot(d, glm::normalize(p));
        const float f = fresnel_dielectric(cos_i, 1.5f);
        RayStats stats;
        const RGB L = w.radiance(Ray{o, d}, {}, stats);
        if (f == 1.0f) {
            ++tir;
            CHECK(L.g == 0.0f);
            CHECK(stats.refracted == 0);
        } else {
            ++exits;
            REQUIRE(L.g == Approx(1.0f - f).margin(1e-5));
            CHECK(stats.refracted == 1);
        }
    }
    CHECK(tir > 50);
    CHECK(exits > 500);

    // From the centre with reflection: 0.96 leaves at each pass, 0.04 goes round again, max_depth passes.
    ShapeList full;
    full.add(sphere(Point3(0.0f), 1.0f), material("glass"));
    for (int depth : {1, 2, 3}) {
        options.max_depth = depth;
        const WhittedIntegrator wf(full, {}, options);
        RayStats stats;
        const RGB L = wf.radiance(Ray{Point3(0.0f), Vec3(0.3f, -0.4f, 0.5f)}, {}, stats);
        CHECK(L.g == Approx(1.0f - std::pow(0.04f, static_cast<float>(depth))).epsilon(1e-5));
        CHECK(stats.reflected == static_cast<std::uint64_t>(depth));
        CHECK(stats.refracted == static_cast<std::uint64_t>(depth));
    }
    // A ray trapped by total internal reflection: every bounce meets the same angle, nothing gets out.
    options.max_depth = 7;
    const WhittedIntegrator wt(full, {}, options);
    RayStats stats;
    CHECK(wt.radiance(Ray{Point3(0.9f, 0.0f, 0.0f), Vec3(0, 0, 1)}, {}, stats).g == 0.0f);
    CHECK(stats.reflected == 7);
    CHECK(stats.refracted == 0);
}

TEST_CASE("transparent shadows multiply kt per crossing in order", "[whitted]") {
    Params pane_params;
    pane_params.set("kt", 0.5);
    const auto pane = lambert(0.0f, pane_params);
    const Point3 light_at(0.0f, 10.0f, 0.0f);
    const Ray down{Point3(0.0f, 1.0f, -3.0f), Vec3(0.0f, -1.0f, 3.0f)};  // sees the floor at the origin
    auto floor_value = [&](ShapeList& scene, RayStats& stats) {
        scene.add(quad(Point3(-5, 0, -5), Vec3(0, 0, 10), Vec3(10, 0, 0)), lambert(1.0f));
        const WhittedIntegrator w(scene, {point_light(light_at, 100.0f)});
        return w.radiance(down, {}, stats).g;
    };
    RayStats s0;
    ShapeList open;
    const float unshadowed = floor_value(open, s0);
    CHECK(unshadowed == Approx(1.0f / kPi * 100.0f / 100.0f));
    CHECK(s0.shadow == 1);

    SECTION("two panes of kt 0.5 give 0.25") {
        ShapeList scene;
        scene.add(quad(Point3(-1, 4, -1), Vec3(0, 0, 2), Vec3(2, 0, 0)), pane);
        scene.add(quad(Point3(-1, 6, -1), Vec3(2, 0, 0), Vec3(0, 0, 2)), pane);  // facing the other way
        RayStats s;
        CHECK(floor_value(scene, s) == Approx(0.25f * unshadowed).epsilon(1e-6));
        CHECK(s.shadow == 3);
    }
    SECTION("a hollow sphere is four crossings") {
        ShapeList scene;
        scene.add(sphere(Point3(0, 5, 0), 1.0f), pane);
        scene.add(sphere(Point3(0, 5, 0), 0.9f), pane, {true, true});
        RayStats s;
        CHECK(floor_value(scene, s) == Approx(0.0625f * unshadowed).epsilon(1e-6));
        CHECK(s.shadow == 5);
    }
    SECTION("Beer-Lambert over the chord inside an absorbing sphere") {
        Params clear;
        clear.set("kt", 1.0).set("absorption", 0.5).set("albedo", 0.0);
        ShapeList scene;
        scene.add(sphere(Point3(0, 5, 0), 1.0f), material("lambert", clear));
        RayStats s;
        CHECK(floor_value(scene, s) == Approx(std::exp(-0.5f * 2.0f) * unshadowed).epsilon(1e-5));
    }
    SECTION("an opaque occluder blocks whatever transmissive surfaces there are") {
        ShapeList scene;
        scene.add(quad(Point3(-1, 4, -1), Vec3(0, 0, 2), Vec3(2, 0, 0)), pane);
        scene.add(quad(Point3(-1, 7, -1), Vec3(0, 0, 2), Vec3(2, 0, 0)), lambert(0.5f));
        RayStats s;
        CHECK(floor_value(scene, s) == 0.0f);
        CHECK(s.shadow == 1);
    }
    SECTION("a cut-out (opacity 0.25) lets 0.75 through, and a glowing Sun that casts no shadow none") {
        Params cut;
        cut.set("opacity", 0.25);
        Params sun;
        sun.set("emission", 5.0);
        ShapeList scene;
        scene.add(quad(Point3(-1, 4, -1), Vec3(0, 0, 2), Vec3(2, 0, 0)), lambert(0.5f, cut));
        scene.add(sphere(light_at, 0.5f), lambert(0.0f, sun), {false, false});
        RayStats s;
        CHECK(floor_value(scene, s) == Approx(0.75f * unshadowed).epsilon(1e-6));
    }
}

TEST_CASE("classic and physical conventions in a scene, with the ambient term", "[whitted]") {
    // Floor point at the origin, light 2 away at 60 degrees from the normal, intensity 2; viewer in the
    // mirror direction. Lambert 0.5: physical 0.5 / pi * cos 60 * 2 / 4, classic 0.5 * cos 60 * 2 (+ ambient).
    const Point3 light_at(2.0f * std::sin(kPi / 3.0f), 1.0f, 0.0f);
    const Ray view{Point3(-light_at.x, light_at.y, 0.0f), Vec3(light_at.x, -light_at.y, 0.0f)};
    Params amb;
    amb.set("intensity", 0.1);
    auto value = [&](std::shared_ptr<const Material> m, Convention c, bool ambient) {
        ShapeList scene;
        scene.add(quad(Point3(-5, 0, -5), Vec3(0, 0, 10), Vec3(10, 0, 0)), m);
        std::vector<std::shared_ptr<const Light>> lights{point_light(light_at, 2.0f)};
        if (ambient) lights.push_back(light("ambient", amb));
        WhittedOptions o;
        o.convention = c;
        RayStats s;
        return WhittedIntegrator(scene, lights, o).radiance(view, {}, s).g;
    };
    CHECK(value(lambert(0.5f), Convention::physical, false) == Approx(0.125f / kPi));
    CHECK(value(lambert(0.5f), Convention::classic, false) == Approx(0.5f));
    CHECK(value(lambert(0.5f), Convention::classic, true) == Approx(0.55f));
    CHECK(value(lambert(0.5f), Convention::physical, true) == Approx(0.125f / kPi + 0.05f));
    Params pp;
    pp.set("kd", 0.5).set("ks", 0.5).set("exponent", 10.0);
    CHECK(value(material("phong", pp), Convention::classic, false) == Approx(1.5f));
    CHECK(value(material("phong", pp), Convention::physical, false) == Approx(0.875f / kPi));
    CHECK(value(material("blinn-phong", pp), Convention::classic, false) == Approx(1.5f));
    // Blinn-Phong at the mirror direction: n.h = 1, so f = kd / pi + ks c(e) with BlinnPhongBrdf's c(e).
    const float blinn = BlinnPhongBrdf(RGB(0.5f), RGB(0.5f), 10.0f).eval(Vec3(0, 0, 1), Vec3(0, 0, 1)).g;
    CHECK(value(material("blinn-phong", pp), Convention::physical, false) == Approx(blinn * 0.25f));
}

TEST_CASE("no shadow acne on a lit sphere and plane from 1e-4 to 1e6", "[whitted]") {
    // Each object alone in its scene, lit by a point light and a grazing directional light: any pixel
    // darker than the same object casting no shadows is the object shadowing itself.
    Params dir;
    dir.set("direction", Params::List{-1.0, -0.05, 0.3});
    std::map<std::string, int> zero_offset_acne;
    for (float scale : {1e-4f, 1.0f, 1e5f, 1e6f}) {
        const Point3 centre = scale * Point3(1.0f, 0.5f, -1.0f);
        Params pt;
        pt.set("position", list(centre + scale * Vec3(1.5f, 2.0f, 1.0f))).set("intensity", scale * scale * 10.0f);
        const std::vector<std::shared_ptr<const Light>> lights{light("point", pt), light("directional", dir)};
        const auto grid = std::make_shared<TriangleMesh>(test::coplanar_grid(4));
        std::vector<std::pair<std::string, std::shared_ptr<const Shape>>> objects{
            {"sphere", sphere(centre, 0.5f * scale)},
            {"quad", quad(centre - scale * Vec3(1, 0, 1), scale * Vec3(0, 0, 2), scale * Vec3(2, 0, 0))},
            {"mesh plane", std::make_shared<Instance>(
                               std::make_shared<MeshShape>(grid),
                               glm::rotate(glm::scale(glm::translate(Mat4(1.0f), centre - scale * Vec3(1, 0, -1)),
                                                      Vec3(0.5f * scale)),
                                           -kPi / 2.0f, Vec3(1, 0, 0)))},
            {"sphere instance",
             std::make_shared<Instance>(sphere(Point3(0.0f), 1.0f),
                                        glm::scale(glm::translate(Mat4(1.0f), centre), Vec3(0.5f * scale)))}};
        for (const auto& [name, shape] : objects) {
            ShapeList shadowed, free;
            shadowed.add(shape, lambert(0.7f));
            free.add(shape, lambert(0.7f), {false, false});
            const WhittedIntegrator ws(shadowed, lights), wf(free, lights);
            const Point3 eye = centre + scale * Vec3(0.3f, 3.0f, 2.5f);
            int lit = 0, darker = 0, towards_light = 0, spawned_blocked = 0, unoffset_blocked = 0;
            for (int y = 0; y < 64; ++y)
                for (int x = 0; x < 64; ++x) {
                    const Point3 aim = centre + scale * Vec3((x - 31.5f) / 40.0f, 0.0f, (y - 31.5f) / 40.0f);
                    const Ray ray{eye, aim - eye};
                    RayStats s;
                    const RGB a = ws.radiance(ray, {}, s), b = wf.radiance(ray, {}, s);
                    if (b.g > 0.0f) ++lit;
                    if (a.g < b.g) ++darker;
                    // The control: shadow rays to the point light from the hit itself, spawned by
                    // geometry's routine and not offset at all (what the darker count would see without it).
                    SurfaceHit h;
                    if (!shadowed.intersect(ray, h)) continue;
                    const Normal3 ng =
                        glm::dot(h.geometric_normal, ray.direction) < 0.0f ? h.geometric_normal : -h.geometric_normal;
                    const Point3 target = centre + scale * Vec3(1.5f, 2.0f, 1.0f);
                    if (!(glm::dot(target - h.point, ng) > 0.0f)) continue;
                    ++towards_light;
                    spawned_blocked += shadowed.occluded(spawn_ray_to(h, target));
                    unoffset_blocked += shadowed.occluded(Ray{h.point, target - h.point, 0.0f, 1.0f - kShadowEpsilon});
                }
            INFO(name << " at scale " << scale << ": " << towards_light << " hits facing the light, "
                      << unoffset_blocked << " shadowed by themselves without an offset");
            CHECK(lit > 1000);
            CHECK(darker == 0);
            CHECK(spawned_blocked == 0);
            // Without the offset the spheres shadow themselves at every scale (262 to 645 of 1,520 hits).
            if (name.find("sphere") != std::string::npos) CHECK(unoffset_blocked > 100);
            zero_offset_acne[name] += unoffset_blocked;
        }
    }
    // The mesh plane at two of the four scales (260 at 1, 2,464 at 1e5); the quad's own hit test happens
    // never to find itself again from its hit points.
    CHECK(zero_offset_acne["mesh plane"] > 100);
}

TEST_CASE("no NaN or infinity for grazing rays, reversed normals, zero vectors and black lights", "[whitted]") {
    // A smooth-normal icosphere whose normals point inwards (against the winding), a sphere, a plane, every
    // material, black and ordinary lights, grazing and degenerate rays.
    auto mesh = std::make_shared<TriangleMesh>(test::icosphere(2, 1.0f, Point3(3.0f, 0.0f, 0.0f)));
    mesh->normals.resize(mesh->positions.size());
    for (std::size_t i = 0; i < mesh->positions.size(); ++i)
        mesh->normals[i] = -glm::normalize(mesh->positions[i] - Point3(3, 0, 0));
    Params black;
    black.set("intensity", 0.0);
    Params area;
    area.set("corner", Params::List{-1, 5, -1}).set("edge_u", Params::List{2, 0, 0});
    area.set("edge_v", Params::List{0, 0, 2}).set("samples", 2.0);
    const std::vector<std::shared_ptr<const Light>> lights{
        point_light(Point3(0, 3, 0), 5.0f),
        light("point", black),
        light("directional", black),
        light("area", area),
        light("spot", black),
        point_light(Point3(0, 0, 0), 1.0f)};  // a light exactly on a surface point
    for (const std::string& name : make_material_registry().names()) {
        ShapeList scene;
        const auto m = material(name);
        scene.add(sphere(Point3(0.0f), 1.0f), m);
        scene.add(std::make_shared<MeshShape>(mesh), m);
        scene.add(quad(Point3(-10, -1, -10), Vec3(0, 0, 20), Vec3(20, 0, 0)), m, {true, true});
        for (Convention c : {Convention::physical, Convention::classic}) {
            WhittedOptions o;
            o.convention = c;
            o.background = RGB(0.2f);
            const WhittedIntegrator w(scene, lights, o);
            int bad = 0;
            auto check = [&](const Ray& r) {
                RayStats s;
                const RGB L = w.radiance(r, {}, s);
                if (!L.is_finite() || L.r < 0.0f || L.g < 0.0f || L.b < 0.0f) ++bad;
            };
            for (int i = 0; i < 400; ++i) {
                const float e = std::ldexp(1.0f, -(i % 24));
                check(Ray{Point3(-5.0f, 1.0f - e, 0.0f), Vec3(1, 0, 0)});              // grazing the sphere's top
                check(Ray{Point3(-5.0f, -1.0f + e, 0.1f), Vec3(1, -e, 0)});            // grazing the plane
                check(Ray{Point3(3.0f, 1.0f + e, -5.0f), Vec3(0, 0, 1)});              // grazing the mesh
                check(Ray{Point3(0, 0, 5), spiral(i, 400) - Point3(0, 0, 5) / 5.0f});  // all over
            }
            check(Ray{Point3(0, 0, 5), Vec3(0.0f)});  // zero direction
            check(Ray{Point3(0, 0, 5), Vec3(std::nanf(""), 0, 0)});
            check(Ray{Point3(0.0f), Vec3(0, 1, 0)});  // from the sphere's centre, the light's point
            INFO(name);
            CHECK(bad == 0);
        }
    }
}

TEST_CASE("a solid texture on an instanced translated sphere shows the pattern of the untranslated one", "[whitted]") {
    // checker3d with cells of 1/4 glowing on a sphere at the origin, seen straight and through an Instance
    // moved by T = (8.125, -4, 16): 8.125 is half a cell off the grid, so a lookup at the world point would
    // shift the pattern in x. T and the ray origins are dyadic, so o + T - T is exact and both scenes
    // intersect the very same object-space rays: every pixel must match bit for bit.
    const TextureRegistry textures = make_texture_registry();
    Params cp;
    cp.set("tiles", 4.0);
    const std::shared_ptr<Texture> checker = textures.create("checker3d", cp);
    Params glow;
    glow.set_object<Texture>("emission", checker);
    const auto m = lambert(0.0f, glow);
    const Vec3 T(8.125f, -4.0f, 16.0f);
    ShapeList plain, moved;
    plain.add(sphere(Point3(0.0f), 1.0f), m);
    moved.add(std::make_shared<Instance>(sphere(Point3(0.0f), 1.0f), glm::translate(Mat4(1.0f), T)), m);
    const WhittedIntegrator wp(plain, {}), wm(moved, {});
    int hits = 0, differ = 0, world_differ = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const Point3 o((x - 32) / 32.0f, (y - 32) / 32.0f, -4.0f);
            const Vec3 d(0.125f * (x % 3 - 1), 0.0625f * (y % 5 - 2), 1.0f);
            RayStats s;
            const RGB a = wp.radiance(Ray{o, d}, {}, s), b = wm.radiance(Ray{o + T, d}, {}, s);
            SurfaceHit h;
            if (!moved.intersect(Ray{o + T, d}, h)) continue;
            ++hits;
            if (a != b) ++differ;
            // The control: what a lookup at the world point would have shown.
            TextureLookup q;
            q.point = h.point;
            if (checker->eval(q) != a) ++world_differ;
        }
    CHECK(hits > 2000);
    CHECK(differ == 0);
    CHECK(world_differ > hits / 4);
}

TEST_CASE("smooth normals never send reflected or refracted rays to the wrong side of the true surface", "[whitted]") {
    // A coarse icosphere with vertex normals: the shading normal differs from the facet's by up to ~20
    // degrees. A mirror in an environment that is black below y = 0: a reflected ray that started inside
    // the mesh would escape from the far side instead; counted through the reflected direction's sign.
    auto mesh = std::make_shared<TriangleMesh>(test::icosphere(0));
    mesh->normals = mesh->positions;
    ShapeList scene;
    scene.add(std::make_shared<MeshShape>(mesh), material("mirror"));
    WhittedOptions o;
    o.environment = std::make_shared<DirectionTexture>();
    o.max_depth = 1;
    const WhittedIntegrator w(scene, {}, o);
    int hits = 0, wrong = 0;
    for (int i = 0; i < 4000; ++i) {
        const Point3 eye = 4.0f * spiral(i, 4000);
        const Vec3 d = glm::normalize(spiral((i * 61) % 4000, 4000) * 0.8f - eye);
        SurfaceHit h;
        if (!scene.intersect(Ray{eye, d}, h)) continue;
        ++hits;
        RayStats stats;
        const RGB L = w.radiance(Ray{eye, d}, {}, stats);
        // The colour is the reflected direction; it must point out of the facet that was hit.
        const Vec3 r(2.0f * L.r - 1.0f, 2.0f * L.g - 1.0f, 2.0f * L.b - 1.0f);
        if (L.is_black() || glm::dot(r, h.geometric_normal) <= 0.0f) ++wrong;
    }
    CHECK(hits > 1000);
    CHECK(wrong == 0);
}

TEST_CASE("smooth normals never refract into or out of a mesh on the wrong side of the true surface", "[whitted]") {
    // The coarse smooth icosphere in clear glass (kt 1, no kr, no Fresnel), one refraction deep, in the
    // direction environment; its vertex normals lean up to 37 degrees off the facets'.
    // Entering: the ray must go into the mesh, meet the far wall at the depth limit and be black; one left
    // outside would escape and show the environment. (With n_s . n_g > 0 an entering refraction cannot
    // rise above the facet: it is d eta + k n_s with k < 0; the leaks are on the way out.)
    // Leaving, at index 1.05 (critical angle 72 degrees), from eyes inside: where the shading normal lets
    // the ray out, it must leave above the facet it hits and show the environment in a direction outside
    // it; total internal reflection stays inside and is black. The test counts the rays whose uncorrected
    // direction, refract(d, n_s, 1.05), points back into the mesh, so it is known to exercise the correction.
    auto mesh = std::make_shared<TriangleMesh>(test::icosphere(0));
    mesh->normals = mesh->positions;
    WhittedOptions o;
    o.environment = std::make_shared<DirectionTexture>();
    o.max_depth = 1;
    auto glass = [&](double ior, ShapeList& scene) {
        Params clear;
        clear.set("kr", 0.0).set("kt", 1.0).set("fresnel", false).set("ior", ior);
        scene.add(std::make_shared<MeshShape>(mesh), material("glass", clear));
    };

    ShapeList dense;
    glass(1.5, dense);
    const WhittedIntegrator wd(dense, {}, o);
    int entering = 0, entering_wrong = 0;
    for (int i = 0; i < 4000; ++i) {
        const Point3 eye = 4.0f * spiral(i, 4000);
        const Vec3 d = glm::normalize(spiral((i * 61) % 4000, 4000) * 0.8f - eye);
        SurfaceHit h;
        if (!dense.intersect(Ray{eye, d}, h)) continue;
        ++entering;
        RayStats stats;
        if (!wd.radiance(Ray{eye, d}, {}, stats).is_black()) ++entering_wrong;
    }
    CHECK(entering > 1000);
    CHECK(entering_wrong == 0);

    ShapeList thin;
    glass(1.05, thin);
    const WhittedIntegrator wt(thin, {}, o);
    int leaving = 0, leaving_wrong = 0, would_leak = 0, tir = 0;
    for (int i = 0; i < 4000; ++i) {
        const Point3 eye = 0.78f * spiral((i * 17) % 4000, 4000);
        const Vec3 d = glm::normalize(spiral(i, 4000));
        SurfaceHit h;
        REQUIRE(thin.intersect(Ray{eye, d}, h));
        ++leaving;
        // The integrator turns the normals towards the viewer (inwards here) and refracts with 1.05 / 1.
        Normal3 ns = -h.shading_normal;
        if (!(glm::dot(ns, -d) > 0.0f)) ns = -h.geometric_normal;
        const auto t = refract(d, ns, 1.05f);
        RayStats stats;
        const RGB L = wt.radiance(Ray{eye, d}, {}, stats);
        if (!t) {
            ++tir;
            if (!L.is_black()) ++leaving_wrong;  // reflected inside: meets the wall at the depth limit
            continue;
        }
        if (glm::dot(*t, h.geometric_normal) <= 0.0f) ++would_leak;
        const Vec3 r(2.0f * L.r - 1.0f, 2.0f * L.g - 1.0f, 2.0f * L.b - 1.0f);
        if (L.is_black() || glm::dot(r, h.geometric_normal) <= 0.0f) ++leaving_wrong;
    }
    INFO("entering " << entering << ", leaving " << leaving << " (uncorrected back inside " << would_leak
                     << ", total internal reflection " << tir << ")");
    CHECK(would_leak > 20);
    CHECK(tir > 20);
    CHECK(leaving_wrong == 0);
}

TEST_CASE("area light samples are a pure function of the sample key", "[whitted]") {
    Params area;
    area.set("corner", Params::List{-1, 3, -1}).set("edge_u", Params::List{2, 0, 0});
    area.set("edge_v", Params::List{0, 0, 2}).set("samples", 3.0);
    ShapeList scene;
    scene.add(quad(Point3(-5, 0, -5), Vec3(0, 0, 10), Vec3(10, 0, 0)), lambert(0.5f));
    scene.add(sphere(Point3(0.3f, 1.5f, 0.2f), 0.6f), lambert(0.5f));  // a penumbra on the floor
    const WhittedIntegrator w(scene, {light("area", area)});
    const Ray ray{Point3(0.0f, 2.0f, -4.0f), Vec3(-0.4f, -2.0f, 3.6f)};
    RayStats s;
    const SampleKey k{7, 10, 20, 0, 0};
    const RGB a = w.radiance(ray, k, s), b = w.radiance(ray, k, s);
    CHECK(a == b);
    CHECK(s.shadow == 18);
    int differ = 0;
    for (std::uint32_t i = 1; i < 20; ++i) differ += w.radiance(ray, SampleKey{7, 10, 20, i, 0}, s) != a;
    CHECK(differ >= 15);
}

TEST_CASE("escaping rays see the cube map in their direction, through a mirror too", "[whitted]") {
    // Six one-colour faces (px nx py ny pz nz): a ray leaving along an axis sees that face's colour.
    std::array<Image, 6> faces;
    for (int f = 0; f < 6; ++f) faces[f] = Image(4, 4, RGB(0.1f * static_cast<float>(f + 1)));
    WhittedOptions o;
    o.environment = std::make_shared<CubeMapTexture>(std::move(faces));
    ShapeList scene;
    scene.add(quad(Point3(-1, -1, -5), Vec3(2, 0, 0), Vec3(0, 2, 0)), material("mirror"));  // faces +z
    const WhittedIntegrator w(scene, {}, o);
    RayStats s;
    CHECK(w.radiance(Ray{Point3(0.0f), Vec3(1, 0, 0)}, {}, s).g == Approx(0.1f));
    CHECK(w.radiance(Ray{Point3(0.0f), Vec3(0, -3, 0)}, {}, s).g == Approx(0.4f));
    CHECK(w.radiance(Ray{Point3(0.0f), Vec3(0, 0, 1)}, {}, s).g == Approx(0.5f));
    // Straight into the mirror: back along +z.
    CHECK(w.radiance(Ray{Point3(0.0f), Vec3(0, 0, -1)}, {}, s).g == Approx(0.5f));
    CHECK(s.reflected == 1);
}

TEST_CASE("a cook-torrance floor under a hand-placed light gives the BRDF times cos times I over r^2", "[whitted]") {
    // Floor y = 0 seen at the origin from (0, 1, -3); a point light of intensity 7 at (1.2, 2, 0.5). Physical:
    // f(wo, wi) cos(theta_i) 7 / r^2 in any local frame with n = +y (the lobe is isotropic).
    const Point3 light_at(1.2f, 2.0f, 0.5f), eye(0.0f, 1.0f, -3.0f);
    for (const char* metal : {"gold", "none"}) {
        Params p;
        p.set("kd", 0.2).set("roughness", 0.5);
        if (std::string(metal) != "none") p.set("metal", std::string(metal));
        ShapeList scene;
        scene.add(quad(Point3(-5, 0, -5), Vec3(0, 0, 10), Vec3(10, 0, 0)), material("cook-torrance", p));
        for (Convention c : {Convention::physical, Convention::classic}) {
            WhittedOptions o;
            o.convention = c;
            const WhittedIntegrator w(scene, {point_light(light_at, 7.0f)}, o);
            RayStats s;
            const RGB L = w.radiance(Ray{eye, Point3(0.0f) - eye}, {}, s);
            const Frame f = Frame::from_normal(Normal3(0, 1, 0));
            const Vec3 wo = f.to_local(glm::normalize(eye)), wi = f.to_local(glm::normalize(light_at));
            const Fresnel fresnel =
                std::string(metal) == "gold" ? Fresnel::conductor(kGold) : Fresnel::dielectric(1.5f);
            const CookTorranceBrdf brdf(RGB(0.2f), RGB(1.0f),
                                        MicrofacetDistribution::from_roughness(MicrofacetModel::ggx, 0.5f), fresnel);
            const float r2 = glm::dot(light_at, light_at);
            const RGB expected = c == Convention::physical ? brdf.eval(wo, wi) * wi.z * (7.0f / r2)
                                                           : brdf.eval(wo, wi) * wi.z * kPi * 7.0f;
            INFO(metal << (c == Convention::physical ? " physical" : " classic"));
            CHECK(L.r == Approx(expected.r).epsilon(1e-5));
            CHECK(L.g == Approx(expected.g).epsilon(1e-5));
            CHECK(L.b == Approx(expected.b).epsilon(1e-5));
            CHECK(s.shadow == 1);
        }
    }
}

TEST_CASE("an ashikhmin-shirley highlight is elongated along the surface tangent and turns with it", "[whitted]") {
    // A floor seen from above with the light at the eye: at a floor point offset by x the half vector
    // tilts towards x. nu = 10 along the tangent, nv = 2000 across: the highlight stretches along the
    // tangent. Two floors, tangent (edge_u) along x and along z: the long axis follows.
    Params p;
    p.set("rd", 0.0).set("rs", 0.5).set("nu", 10.0).set("nv", 2000.0);
    const auto m = material("ashikhmin-shirley", p);
    const Point3 eye(0.0f, 2.0f, 0.0f);
    auto extent = [&](const Point3& corner, const Vec3& edge_u, const Vec3& edge_v, const Vec3& along) {
        ShapeList scene;
        scene.add(quad(corner, edge_u, edge_v), m);
        const WhittedIntegrator w(scene, {point_light(eye, 4.0f)});
        RayStats s;
        const float peak = w.radiance(Ray{eye, Vec3(0, -1, 0)}, {}, s).g;
        int above_half = 0;
        for (int i = -200; i <= 200; ++i) {
            const Point3 target = (static_cast<float>(i) / 100.0f) * along;
            above_half += w.radiance(Ray{eye, target - eye}, {}, s).g > 0.5f * peak;
        }
        return above_half;
    };
    // edge_u x edge_v faces up (+y) in both: x cross -z and z cross x.
    const Vec3 x(10, 0, 0), z(0, 0, 10), ax(1, 0, 0), az(0, 0, 1);
    const int tx_along_x = extent(Point3(-5, 0, 5), x, -z, ax), tx_along_z = extent(Point3(-5, 0, 5), x, -z, az);
    const int tz_along_x = extent(Point3(-5, 0, -5), z, x, ax), tz_along_z = extent(Point3(-5, 0, -5), z, x, az);
    INFO("tangent x: " << tx_along_x << " along x, " << tx_along_z << " along z; tangent z: " << tz_along_x
                       << " along x, " << tz_along_z << " along z");
    CHECK(tx_along_z >= 1);
    CHECK(tx_along_x > 5 * tx_along_z);
    CHECK(tz_along_z > 5 * tz_along_x);
    CHECK(std::abs(tx_along_x - tz_along_z) <= 2);
}
