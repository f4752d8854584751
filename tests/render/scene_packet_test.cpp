// The scene's packet queries (intersect_surface_packet, occluded_packet) against its single-ray queries, bit for bit,
// and renders with and without packets byte for byte. The hard inputs: objects that overlap exactly (two instances
// of one mesh under one transform, a quad in the plane of a mesh's faces: ties between objects, which the single
// query gives to the object tested first), rays through vertices and edges, rays that start on a surface, grazing
// and axis-parallel rays with +0 and -0 components, degenerate and bounded intervals; groups of sizes from 1 to 16
// and beyond, camera tiles and rays of mixed octants; lists, kd-trees, and the flat tree of small meshes.
#include "camera_tiles.hpp"
#include "image_bytes.hpp"
#include "scene_fixtures.hpp"
#include "test_meshes.hpp"

#include <rtlab/accel/accelerator.hpp>
#include <rtlab/accel/mesh_shape.hpp>
#include <rtlab/core/rng.hpp>
#include <rtlab/geometry/instance.hpp>
#include <rtlab/geometry/smooth_normals.hpp>
#include <rtlab/render/render_job.hpp>

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

using namespace rtlab;
using namespace rtlab::test;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

bool same_bits(float a, float b) { return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b); }
bool same_bits(const Vec3& a, const Vec3& b) {
    return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z);
}

bool same_hit(const SurfaceHit& a, const SurfaceHit& b) {
    return same_bits(a.t, b.t) && same_bits(a.point, b.point) && same_bits(a.point_error, b.point_error) &&
           same_bits(a.object_point, b.object_point) && same_bits(a.geometric_normal, b.geometric_normal) &&
           same_bits(a.shading_normal, b.shading_normal) && same_bits(a.uv.x, b.uv.x) && same_bits(a.uv.y, b.uv.y) &&
           same_bits(a.tangent, b.tangent) && a.primitive == b.primitive && a.front_face == b.front_face &&
           a.shape == b.shape;
}

struct Differences {
    std::size_t rays = 0, hits = 0, blocked = 0, closest = 0, any = 0;
};

// The rays in consecutive groups of `size` through the packet queries, each answer against the single query's.
Differences compare(const Scene& scene, std::span<const Ray> rays, std::size_t size) {
    std::vector<SurfaceHit> hits(rays.size());
    std::vector<SurfaceInfo> infos(rays.size());
    std::vector<std::uint8_t> found(rays.size(), 2), blocked(rays.size(), 2);
    for (std::size_t i = 0; i < rays.size(); i += size) {
        const std::size_t n = std::min(size, rays.size() - i);
        scene.intersect_surface_packet(rays.subspan(i, n), std::span<SurfaceHit>(hits).subspan(i, n),
                                       std::span<SurfaceInfo>(infos).subspan(i, n),
                                       std::span<std::uint8_t>(found).subspan(i, n));
        scene.occluded_packet(rays.subspan(i, n), std::span<std::uint8_t>(blocked).subspan(i, n));
    }
    Differences d;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        SurfaceHit hit;
        SurfaceInfo info;
        const bool single = scene.intersect_surface(rays[i], hit, info);
        const bool occluded = scene.occluded(rays[i]);
        ++d.rays;
        d.hits += single;
        d.blocked += occluded;
        d.closest +=
            found[i] != (single ? 1 : 0) || (single && (!same_hit(hit, hits[i]) || info.material != infos[i].material ||
                                                        info.flags.casts_shadows != infos[i].flags.casts_shadows ||
                                                        info.flags.reversed != infos[i].flags.reversed));
        d.any += blocked[i] != (occluded ? 1 : 0);
    }
    return d;
}

// Objects that tie: the icosphere mesh as a MeshShape, an Instance of it under the identity and two Instances under
// one transform (the same t on the same triangles), a coplanar grid with a quad in its plane, small meshes that
// join the flat tree (two copies of a stacked-quads mesh at the same place), spheres, one of them around a mesh.
std::vector<SceneObject> tied_objects(const std::string& method) {
    auto sphere_mesh = std::make_shared<const TriangleMesh>(with_smooth_normals(test::icosphere(3)));
    const auto mesh = std::make_shared<MeshShape>(sphere_mesh, method);
    const Mat4 moved = glm::translate(Mat4(1.0f), Vec3(2.5f, 0.25f, -0.5f)) *
                       glm::rotate(Mat4(1.0f), 0.7f, Vec3(0.3f, 1.0f, 0.2f)) * glm::scale(Mat4(1.0f), Vec3(0.8f));
    const auto grid =
        std::make_shared<MeshShape>(std::make_shared<const TriangleMesh>(test::coplanar_grid(8, -1.0f)), method);
    const auto small = std::make_shared<const TriangleMesh>(test::stacked_quads(6, -2.0f));
    std::vector<SceneObject> objects;
    objects.push_back({mesh, lambert(RGB(0.8f, 0.2f, 0.2f)), {}, "mesh"});
    objects.push_back({std::make_shared<Instance>(mesh, Mat4(1.0f)), lambert(RGB(0.2f, 0.8f, 0.2f)), {}, "same"});
    objects.push_back({std::make_shared<Sphere>(Point3(-2.0f, 0.5f, 0.0f), 0.75f), material("mirror"), {}, "ball"});
    objects.push_back({std::make_shared<Instance>(mesh, moved), material("glass"), {}, "moved"});
    objects.push_back({std::make_shared<Instance>(mesh, moved), lambert(RGB(0.5f)), {false, false}, "moved again"});
    objects.push_back({std::make_shared<Quad>(Point3(0.0f, 0.0f, -1.0f), Vec3(8.0f, 0, 0), Vec3(0, 8.0f, 0)),
                       lambert(RGB(0.3f, 0.3f, 0.9f)),
                       {},
                       "quad in the grid's plane"});
    objects.push_back({grid, lambert(RGB(0.9f, 0.9f, 0.3f)), {true, true}, "grid"});
    objects.push_back({std::make_shared<MeshShape>(small, method), lambert(RGB(0.6f)), {}, "small"});
    objects.push_back({std::make_shared<MeshShape>(small, method), lambert(RGB(0.4f)), {}, "small again"});
    objects.push_back({std::make_shared<Sphere>(Point3(2.5f, 0.25f, -0.5f), 0.9f), material("glass"), {}, "shell"});
    objects.push_back({std::make_shared<Quad>(Point3(-8, -1.5f, 8), Vec3(16, 0, 0), Vec3(0, 0, -16)),
                       lambert(RGB(0.7f)),
                       {},
                       "floor"});
    return objects;
}

// Rays that meet the tied objects at their hardest: camera tiles from several eyes (one looking straight down the
// z axis at the grid's vertices), rays from the hits on (tmin 0, starting on a surface) towards a point and in
// mirrored directions, axis-parallel rays with signed zeros through vertices, random rays of mixed octants, and
// degenerate rays and intervals.
std::vector<Ray> hard_rays(const Scene& scene) {
    std::vector<Ray> rays;
    for (const Point3& eye : {Point3(0.1f, 0.6f, 6.0f), Point3(-5.0f, 3.0f, 4.0f), Point3(4.0f, -0.5f, 3.0f)}) {
        const std::vector<Ray> tiles = test::camera_tiles(eye, Point3(0.0f), 7.0f, 24);
        rays.insert(rays.end(), tiles.begin(), tiles.end());
    }
    // Through the grid's vertices along -z (at whole coordinates in [0, 8]^2, z = -1), and along its diagonals.
    for (float zero : {0.0f, -0.0f})
        for (int i = 0; i <= 8; ++i)
            for (int j = 0; j <= 8; ++j) {
                rays.push_back(
                    Ray{Point3(static_cast<float>(i), static_cast<float>(j), 5.0f), Vec3(zero, zero, -1.0f)});
                rays.push_back(Ray{Point3(static_cast<float>(i) - 6.0f, static_cast<float>(j) - 6.0f, 5.0f),
                                   Vec3(1.0f, 1.0f, -1.0f)});
            }
    // From the hits found so far: shadow-like segments to a point and to the camera, and mirrored rays.
    const std::size_t primary = rays.size();
    for (std::size_t i = 0; i < primary; ++i) {
        SurfaceHit h;
        if (!scene.intersect(rays[i], h)) continue;
        const Point3 light(-3.0f, 6.0f, 4.0f);
        rays.push_back(Ray{h.point, light - h.point, 0.0f, 1.0f});
        rays.push_back(Ray{h.point, rays[i].direction, 0.0f, kInfinity});  // on the surface, onwards
        rays.push_back(Ray{h.point, -rays[i].direction, 0.0f, kInfinity});
    }
    Rng rng(17);
    for (int i = 0; i < 400; ++i) {
        const Point3 o(8.0f * rng.uniform() - 4.0f, 6.0f * rng.uniform() - 2.0f, 8.0f * rng.uniform() - 4.0f);
        rays.push_back(Ray{o, Vec3(rng.uniform() - 0.5f, rng.uniform() - 0.5f, rng.uniform() - 0.5f)});
    }
    const Point3 o(0.1f, 0.2f, 5.0f);
    const Vec3 d(0.0f, 0.0f, -1.0f);
    for (const Ray& special :
         {Ray{Point3(kNaN, 0.0f, 5.0f), d}, Ray{o, Vec3(0.0f, kNaN, -1.0f)}, Ray{o, Vec3(0.0f)}, Ray{o, d, 5.0f, 1.0f},
          Ray{o, d, 4.0f, 4.0f}, Ray{o, d, kNaN, 10.0f}, Ray{o, d, 0.0f, kNaN}, Ray{o, d * 1e-30f}, Ray{o, d * 1e30f}})
        for (int lane = 0; lane < 5; ++lane) {
            rays.push_back(special);
            rays.push_back(Ray{o, Vec3(0.01f * static_cast<float>(lane), 0.02f, -1.0f)});
        }
    return rays;
}

std::string label(const SceneOptions& options) {
    return std::string(options.tree_threshold == 0 ? "kd-tree" : "list") +
           (options.flat_mesh_triangles == 0 ? " without" : " with") + " the flat tree";
}

}  // namespace

TEST_CASE("scene packet queries answer as single queries with ties between objects and rays on surfaces", "[scene]") {
    std::vector<std::string> methods = {"kd-sah", "kd-median", "bvh"};
    const std::vector<std::string> known = accelerator_methods();
    if (std::find(known.begin(), known.end(), "embree") != known.end()) methods.push_back("embree");
    for (const std::string& method : methods)
        for (std::size_t threshold : {kAlwaysList, std::size_t{0}})
            for (std::size_t flat : {kSceneFlatMeshTriangles, std::size_t{0}}) {
                SceneOptions options;
                options.tree_threshold = threshold;
                options.flat_mesh_triangles = flat;
                const Scene scene(tied_objects(method), options);
                const std::vector<Ray> rays = hard_rays(scene);
                for (std::size_t size : {1, 2, 3, 5, 8, 11, 16, 17}) {
                    // Sizes below, at and past a packet of 8 and a chunk of 16 on kd-sah; 8 and 17 on the others.
                    if (method != "kd-sah" && size != 8 && size != 17) continue;
                    const Differences d = compare(scene, rays, size);
                    INFO(method << ", " << label(options) << ", groups of " << size << ": " << d.closest
                                << " closest-hit and " << d.any << " any-hit differences of " << d.rays << " rays ("
                                << d.hits << " hits, " << d.blocked << " blocked)");
                    CHECK(d.closest == 0);
                    CHECK(d.any == 0);
                    CHECK(d.hits > d.rays / 4);
                    CHECK(d.blocked > d.rays / 4);
                }
            }
}

TEST_CASE("scene packet queries of a scene without meshes and of an empty scene answer as single queries", "[scene]") {
    const Scene spheres(random_objects(30, 10, 4));
    std::mt19937 rng(8);
    std::vector<Ray> rays;
    for (int i = 0; i < 300; ++i) rays.push_back(random_ray(rng));
    for (std::size_t size : {1, 7, 16, 40}) {
        const Differences d = compare(spheres, rays, size);
        CHECK(d.closest == 0);
        CHECK(d.any == 0);
        CHECK(d.hits > 0);
    }
    const Scene empty(std::vector<SceneObject>{});
    const Differences d = compare(empty, rays, 16);
    CHECK(d.closest == 0);
    CHECK(d.any == 0);
    CHECK(d.hits == 0);
}

namespace {

// A bunny-like render: a smooth icosphere mesh through an Instance on a floor beside spheres, a mirror and glass,
// lit by a point light and, for Whitted, an ambient light (as rtlab-bunny's).
RenderJob tied_job(const std::string& method, IntegratorKind integrator) {
    RenderJob job;
    job.scene = std::make_shared<Scene>(tied_objects(method));
    job.camera = std::make_shared<PinholeCamera>(CameraSpec{
        .eye = {0.5f, 2.0f, 7.0f}, .look_at = {0, 0, 0}, .vertical_fov_degrees = 50.0f, .width = 52, .height = 38});
    Params ambient;
    ambient.set("intensity", 0.15);
    job.lights = {point_light(Point3(-3.0f, 6.0f, 4.0f), 60.0f)};
    if (integrator == IntegratorKind::whitted) job.lights.push_back(light("ambient", ambient));  // not physical
    job.whitted.background = RGB(0.55f, 0.65f, 0.8f);
    job.integrator = integrator;
    job.path.max_depth = 3;
    return job;
}

}  // namespace

TEST_CASE("renders with and without packets are byte-identical for every pattern", "[render_job]") {
    std::vector<std::string> methods = {"kd-sah"};
    const std::vector<std::string> known = accelerator_methods();
    if (std::find(known.begin(), known.end(), "embree") != known.end()) methods.push_back("embree");
    struct Setting {
        PixelPattern pattern;
        int spp;
        IntegratorKind integrator;
    };
    const std::vector<Setting> settings = {
        {PixelPattern::none, 1, IntegratorKind::whitted},  {PixelPattern::jittered, 2, IntegratorKind::whitted},
        {PixelPattern::sobol, 2, IntegratorKind::whitted}, {PixelPattern::adaptive, 1, IntegratorKind::whitted},
        {PixelPattern::none, 1, IntegratorKind::path},     {PixelPattern::sobol, 2, IntegratorKind::direct}};
    for (const std::string& method : methods)
        for (const Setting& s : settings)
            for (int tile : {0, 5}) {
                RenderJob job = tied_job(method, s.integrator);
                job.settings.pattern = s.pattern;
                job.settings.spp = s.spp;
                job.settings.tile_size = tile;  // 5: groups of 5 and 10 samples, odd tiles at the edges
                job.settings.threads = 2;
                const RenderResult with = render_job(job);
                job.settings.packets = false;
                const RenderResult without = render_job(job);
                INFO(method << ", " << pixel_pattern_name(s.pattern) << ", integrator "
                            << static_cast<int>(s.integrator) << ", tile " << tile);
                CHECK(same_bytes(with.image, without.image));
                CHECK(with.stats.rays == without.stats.rays);
                CHECK(with.samples == without.samples);
            }
}

TEST_CASE("Whitted radiance of a group equals each ray's radiance on the hard rays", "[render_job]") {
    // Two point lights (the second inside the moved mesh's glass shell: its shadow segments cross transmissive
    // surfaces), a directional one and the ambient light, over the tied objects; rays that start on surfaces,
    // NaN and zero directions among them.
    const Scene scene(tied_objects("kd-sah"));
    Params sun;
    sun.set("direction", Params::List{-0.3, -1.0, -0.4}).set("intensity", 1.5);
    Params ambient;
    ambient.set("intensity", 0.1);
    const WhittedIntegrator whitted(
        scene,
        {point_light(Point3(-3.0f, 6.0f, 4.0f), 60.0f), point_light(Point3(2.5f, 0.25f, -0.5f), 5.0f),
         light("directional", sun), light("ambient", ambient)},
        WhittedOptions{});
    const std::vector<Ray> rays = hard_rays(scene);
    std::vector<SampleKey> keys;
    for (std::size_t i = 0; i < rays.size(); ++i)
        keys.push_back(SampleKey{3, static_cast<std::uint32_t>(i % 64), static_cast<std::uint32_t>(i / 64), 0, 0});
    for (std::size_t size : {1, 8, 16, 37}) {
        std::vector<RGB> packet(rays.size());
        RayStats packet_stats, single_stats;
        for (std::size_t i = 0; i < rays.size(); i += size) {
            const std::size_t n = std::min(size, rays.size() - i);
            whitted.radiance_packet(std::span<const Ray>(rays).subspan(i, n),
                                    std::span<const SampleKey>(keys).subspan(i, n),
                                    std::span<RGB>(packet).subspan(i, n), packet_stats);
        }
        std::size_t differences = 0, lit = 0;
        for (std::size_t i = 0; i < rays.size(); ++i) {
            const RGB single = whitted.radiance(rays[i], keys[i], single_stats);
            differences += !(same_bits(single.r, packet[i].r) && same_bits(single.g, packet[i].g) &&
                             same_bits(single.b, packet[i].b));
            lit += single.r > 0.0f;
        }
        INFO("groups of " << size << ": " << differences << " differences of " << rays.size() << " rays");
        CHECK(differences == 0);
        CHECK(lit > rays.size() / 4);
        CHECK(packet_stats.shadow == single_stats.shadow);
        CHECK(packet_stats.reflected == single_stats.reflected);
        CHECK(packet_stats.refracted == single_stats.refracted);
        CHECK(single_stats.shadow > rays.size());
    }
}
