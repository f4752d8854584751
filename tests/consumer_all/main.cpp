// Uses every rtlab component from an installed rtlab, built with the consumer's own flags (the test builds
// it with -march=native where the compiler has it):
//  1. the leak check: rays aimed exactly at the shared vertices and edges of a closed tessellated sphere
//     must hit one of its triangles, by the watertight test inlined here from rtlab/geometry's header and
//     by a BVH (accel). With FMA contraction (g++ -march=native without -ffp-contract=off, which the
//     rtlab targets pass on as a usage requirement) the inline test leaks;
//  2. a small render of that sphere (a MeshShape) with a textured material, a light, a camera and a tone
//     operator: core, geometry, accel, textures, shading, render and tonemap together.
#include <rtlab/accel/accelerator.hpp>
#include <rtlab/accel/mesh_shape.hpp>
#include <rtlab/core/image.hpp>
#include <rtlab/core/params.hpp>
#include <rtlab/geometry/triangle_intersect.hpp>
#include <rtlab/geometry/triangle_mesh.hpp>
#include <rtlab/render/render_job.hpp>
#include <rtlab/shading/light.hpp>
#include <rtlab/shading/material.hpp>
#include <rtlab/textures/texture.hpp>
#include <rtlab/tonemap/tone_operator.hpp>

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <random>
#include <utility>

namespace {

// A closed unit icosphere, 20 * 4^levels triangles with shared vertices, outward winding.
rtlab::TriangleMesh icosphere(int levels) {
    const float g = (1.0f + std::sqrt(5.0f)) / 2.0f;
    rtlab::TriangleMesh m;
    for (const rtlab::Vec3& v :
         {rtlab::Vec3(-1, g, 0), rtlab::Vec3(1, g, 0), rtlab::Vec3(-1, -g, 0), rtlab::Vec3(1, -g, 0),
          rtlab::Vec3(0, -1, g), rtlab::Vec3(0, 1, g), rtlab::Vec3(0, -1, -g), rtlab::Vec3(0, 1, -g),
          rtlab::Vec3(g, 0, -1), rtlab::Vec3(g, 0, 1), rtlab::Vec3(-g, 0, -1), rtlab::Vec3(-g, 0, 1)})
        m.positions.push_back(glm::normalize(v));
    m.triangles = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                   {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                   {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> middle;
        auto mid = [&](std::uint32_t a, std::uint32_t b) {
            auto [it, added] = middle.try_emplace(std::minmax(a, b), static_cast<std::uint32_t>(m.positions.size()));
            if (added) m.positions.push_back(glm::normalize(m.positions[a] + m.positions[b]));
            return it->second;
        };
        std::vector<std::array<std::uint32_t, 3>> next;
        for (const auto& [a, b, c] : m.triangles) {
            const std::uint32_t ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
            next.insert(next.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
        }
        m.triangles = std::move(next);
    }
    return m;
}

struct LeakCount {
    int rays = 0, inline_leaks = 0, bvh_leaks = 0, kd_leaks = 0;
};

// Rays from outside the sphere aimed exactly at every vertex and at three points of every edge, entering
// the solid there and ending just past it (an unbounded ray that slipped through would be caught by the far
// side). A ray that no triangle stops has slipped through a crack. Built with -march=native (FMA), this
// check measured 62 leaks of the inline test without -ffp-contract=off and 0 with it (35,856 rays).
LeakCount count_leaks(const rtlab::TriangleMesh& mesh, const rtlab::TriangleAccelerator& bvh,
                      const rtlab::TriangleAccelerator& kd) {
    std::mt19937 rng(12);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    LeakCount n;
    auto aim = [&](const rtlab::Point3& target) {
        const rtlab::Vec3 outward = glm::normalize(target);
        for (int k = 0; k < 8; ++k) {
            rtlab::Vec3 d;
            do d = rtlab::Vec3(u(rng), u(rng), u(rng));
            while (glm::length(d) > 1.0f || glm::length(d) < 0.1f || glm::dot(glm::normalize(d), outward) < 0.5f);
            const rtlab::Point3 origin = target + 3.0f * glm::normalize(d);
            const rtlab::Ray ray{origin, target - origin, 0.0f, 1.001f};  // ends just past the target
            const rtlab::WatertightRay sheared(ray);
            bool hit = false;
            for (std::size_t i = 0; i < mesh.triangle_count() && !hit; ++i)
                hit = rtlab::intersect_watertight(sheared, ray.tmin, ray.tmax, mesh.corner(i, 0), mesh.corner(i, 1),
                                                  mesh.corner(i, 2))
                          .has_value();
            rtlab::MeshHit tree_hit;
            ++n.rays;
            if (!hit) ++n.inline_leaks;
            if (!bvh.intersect(ray, tree_hit)) ++n.bvh_leaks;
            if (!kd.intersect(ray, tree_hit)) ++n.kd_leaks;
        }
    };
    for (const auto& p : mesh.positions) aim(p);
    for (const auto& [a, b, c] : mesh.triangles)
        for (float s : {0.5f, 0.25f, 1.0f / 3.0f}) aim(mesh.positions[a] + s * (mesh.positions[b] - mesh.positions[a]));
    return n;
}

rtlab::Params::List rgb(float r, float g, float b) { return {r, g, b}; }

}  // namespace

int main() {
    int failures = 0;
    const auto mesh = std::make_shared<rtlab::TriangleMesh>(icosphere(3));
#ifdef __FMA__
    std::puts("consumer_all: compiled for a target with FMA");
#else
    std::puts("consumer_all: compiled for a target without FMA (the leak check cannot see contraction here)");
#endif
    const LeakCount leaks =
        count_leaks(*mesh, *rtlab::make_accelerator("bvh", *mesh), *rtlab::make_accelerator("kd-sah", *mesh));
    std::printf(
        "consumer_all: %d rays at shared vertices and edges of %zu triangles: %d leaks (inline watertight "
        "test), %d (bvh), %d (kd-sah)\n",
        leaks.rays, mesh->triangle_count(), leaks.inline_leaks, leaks.bvh_leaks, leaks.kd_leaks);
    // kd-sah's count is printed, not required: its leaks where a split plane meets the tessellation's edges
    // (1 here) are issue 12's first item, fixed apart; require 0 once that lands.
    if (leaks.rays < 30000 || leaks.inline_leaks != 0 || leaks.bvh_leaks != 0) ++failures;

    // The sphere as a kd-tree shape, with a checker texture as its albedo, lit by a point light at the eye.
    const rtlab::TextureRegistry textures = rtlab::make_texture_registry();
    rtlab::Params checker;
    checker.set("color1", rgb(0.9f, 0.1f, 0.1f)).set("color2", rgb(0.1f, 0.1f, 0.9f));
    rtlab::Params lambert;
    lambert.set_object<rtlab::Texture>("albedo", textures.create("checker", checker));
    const auto material = rtlab::make_material_registry().create("lambert", lambert);
    rtlab::Params light;
    light.set("position", rgb(0, 0, 5)).set("intensity", 25.0f);
    rtlab::RenderJob job;
    job.scene = std::make_shared<rtlab::Scene>(
        std::vector<rtlab::SceneObject>{{std::make_shared<rtlab::MeshShape>(mesh), material, {}, "sphere"}});
    job.camera = std::make_shared<rtlab::PinholeCamera>(rtlab::CameraSpec{
        .eye = {0, 0, 5}, .look_at = {0, 0, 0}, .vertical_fov_degrees = 30.0f, .width = 32, .height = 32});
    job.lights = {rtlab::make_light_registry().create("point", light)};
    job.whitted.background = rtlab::RGB(0.0f, 1.0f, 0.0f);
    const rtlab::RenderResult result = rtlab::render_job(job);
    const rtlab::Image display = rtlab::make_tone_registry().create("reinhard", {})->apply(result.image);
    // The centre pixel sees the sphere (lit, not the green background); a corner sees the background.
    const rtlab::RGB centre = display.at(16, 16), corner = display.at(0, 0);
    std::printf("consumer_all: rendered %dx%d, %llu camera rays; centre %.3f %.3f %.3f, corner %.3f %.3f %.3f\n",
                display.width(), display.height(), static_cast<unsigned long long>(result.stats.rays.camera), centre.r,
                centre.g, centre.b, corner.r, corner.g, corner.b);
    if (!(centre.g < 0.5f && centre.r + centre.b > 0.1f) || !(corner.g > 0.5f && corner.r == 0.0f)) ++failures;

    std::puts(failures == 0 ? "consumer_all: ok" : "consumer_all: FAILED");
    return failures == 0 ? 0 : 1;
}
