// The small meshes a Scene gathers into one flat triangle tree against the same scene with every mesh on its
// own tree: the same answers to every query, records bit for bit.
#include "image_bytes.hpp"
#include "scene_fixtures.hpp"

#include <rtlab/accel/mesh_shape.hpp>
#include <rtlab/geometry/instance.hpp>
#include <rtlab/render/render_job.hpp>

#include <catch2/catch.hpp>
#include <test_meshes.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cstring>
#include <limits>
#include <set>

using namespace rtlab;
using namespace rtlab::test;

namespace {

// A soup of `count` triangles of size up to `size`, moved from [0, 10]^3 into the box at `corner`, scaled by s.
std::shared_ptr<const MeshShape> soup(int count, std::uint32_t seed, float s, Point3 corner) {
    TriangleMesh m = random_soup(count, seed, 1.5f);
    for (Point3& p : m.positions) p = corner + s * p;
    return std::make_shared<const MeshShape>(std::make_shared<const TriangleMesh>(std::move(m)));
}

std::shared_ptr<const MeshShape> ball(int subdivisions, float radius, Point3 centre) {
    return std::make_shared<const MeshShape>(
        std::make_shared<const TriangleMesh>(icosphere(subdivisions, radius, centre)));
}

// Random spheres and quads, and beside them: twelve small icospheres (glass every fourth, one not casting
// shadows), three triangle soups (one glass), one small mesh on a BVH and one with the Moller-Trumbore test
// (neither may join: their hits are not the kd-tree's), two instances of a small mesh, and an icosphere of
// 1,280 triangles, above the flat limit.
struct MeshScene {
    std::vector<SceneObject> objects;
    std::set<const Shape*> joinable;  // the objects that must join the flat trees
    std::set<const Shape*> left;      // the meshes that must not
};

MeshScene mesh_scene() {
    MeshScene s;
    s.objects = random_objects(20, 10, 13);
    const auto glass = material("glass");
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int i = 0; i < 12; ++i) {
        const Point3 c(-5.0f + 10.0f * u(rng), 0.5f + 4.0f * u(rng), -15.0f + 10.0f * u(rng));
        auto shape = ball(1, 0.3f + 0.5f * u(rng), c);
        SceneObject o{shape, i % 4 == 1 ? glass : lambert(RGB(0.3f + 0.6f * u(rng), 0.5f, 0.4f)), {}, "ball"};
        if (i == 6) o.flags.casts_shadows = false;
        s.joinable.insert(shape.get());
        s.objects.push_back(std::move(o));
    }
    for (int i = 0; i < 3; ++i) {
        auto shape = soup(40, 100 + static_cast<std::uint32_t>(i), 0.35f, Point3(-5.0f + 3.5f * i, 0.5f, -14.0f));
        s.joinable.insert(shape.get());
        s.objects.push_back({shape, i == 2 ? glass : lambert(RGB(0.8f, 0.8f, 0.2f)), {}, "soup"});
    }
    auto mesh = std::make_shared<const TriangleMesh>(icosphere(1, 0.6f, Point3(2, 1, -7)));
    BuildOptions moller;
    moller.triangle_test = TriangleTest::moller;
    auto bvh = std::make_shared<const MeshShape>(mesh, "bvh");
    auto other_test = std::make_shared<const MeshShape>(
        std::make_shared<const TriangleMesh>(icosphere(1, 0.6f, Point3(-2, 1, -7))), "kd-sah", moller);
    auto shared = ball(2, 0.7f, Point3(0.0f));
    auto left = std::make_shared<Instance>(shared, glm::translate(Mat4(1.0f), Vec3(-3, 2, -9)));
    auto right = std::make_shared<Instance>(shared, glm::translate(Mat4(1.0f), Vec3(3, 2, -9)));
    auto large = ball(3, 1.2f, Point3(0, 3.5f, -12));
    for (const std::shared_ptr<const Shape>& shape :
         std::initializer_list<std::shared_ptr<const Shape>>{bvh, other_test, left, right, large}) {
        s.left.insert(shape.get());
        s.objects.push_back({shape, shape == right ? glass : lambert(RGB(0.2f, 0.7f, 0.9f)), {}, "left alone"});
    }
    return s;
}

bool same_record(const SurfaceHit& a, const SurfaceHit& b) {
    return a.t == b.t && a.point == b.point && a.point_error == b.point_error && a.object_point == b.object_point &&
           a.geometric_normal == b.geometric_normal && a.shading_normal == b.shading_normal && a.uv == b.uv &&
           a.tangent == b.tangent && a.primitive == b.primitive && a.front_face == b.front_face && a.shape == b.shape;
}

// The shading queries may leave out a sphere's uv where its material reads no lookup and its tangent where it
// reflects no direct light, and lists do so where kd-trees over objects do not; a mesh's record is whole.
bool same_shading_record(const SurfaceHit& a, const SurfaceHit& b, const Material& m) {
    SurfaceHit x = a;
    if (!dynamic_cast<const MeshShape*>(a.shape)) {
        if (!m.reads_lookup()) x.uv = b.uv;
        if (!m.reflects_direct_light()) x.tangent = b.tangent;
    }
    return same_record(x, b);
}

}  // namespace

TEST_CASE("small meshes join one flat tree and answer every query as their own trees do", "[scene]") {
    const MeshScene s = mesh_scene();
    // Lists and kd-trees over the other objects, with and without the flat trees; the reference is the list
    // of objects each on its own tree.
    const Scene reference(s.objects, {kAlwaysList, 0});
    const Scene tree_alone(s.objects, {1, 0});
    const Scene flat_list(s.objects, {kAlwaysList});
    const Scene flat_tree(s.objects, {1});
    REQUIRE(reference.flat_meshes() == 0);
    REQUIRE(flat_list.flat_meshes() == s.joinable.size());
    REQUIRE(flat_tree.flat_meshes() == s.joinable.size());
    REQUIRE(flat_list.structure() == "list");
    REQUIRE(flat_tree.structure() == "kd-tree");
    std::mt19937 rng(23);
    int mismatches = 0, joined_hits = 0, left_hits = 0, occluded = 0, joined_crossings = 0, clear = 0;
    for (int i = 0; i < 20000; ++i) {
        const Ray r = random_ray(rng);
        SurfaceHit want, want_shading;
        SurfaceInfo want_info;
        const bool hit = reference.intersect(r, want);
        if (reference.intersect_surface(r, want_shading, want_info) != hit) ++mismatches;
        const bool blocked = reference.occluded(r);
        SurfaceHit want_t;
        const bool crossing = reference.intersect_transmissive(r, want_t);
        if (hit) {
            joined_hits += s.joinable.contains(want.shape);
            left_hits += s.left.contains(want.shape);
        }
        occluded += blocked;
        if (crossing) joined_crossings += s.joinable.contains(want_t.shape);
        for (const Scene* scene : {&tree_alone, &flat_list, &flat_tree}) {
            SurfaceHit got, got_surface, got_t;
            SurfaceInfo info;
            if (scene->intersect(r, got) != hit || (hit && !same_record(want, got))) ++mismatches;
            if (scene->intersect_surface(r, got_surface, info) != hit ||
                (hit && (!same_shading_record(want, got_surface, *want_info.material) ||
                         info.material != want_info.material || scene->surface(got).material != want_info.material)))
                ++mismatches;
            if (scene->occluded(r) != blocked) ++mismatches;
            if (scene->intersect_transmissive(r, got_t) != crossing || (crossing && !same_record(want_t, got_t)))
                ++mismatches;
            for (const bool check_opaque : {true, false}) {
                SurfaceHit want_s, got_s;
                SurfaceInfo want_si, got_si;
                const ShadowHit a = reference.shadow(r, check_opaque, want_s, want_si);
                const ShadowHit b = scene->shadow(r, check_opaque, got_s, got_si);
                if (a != b ||
                    (a == ShadowHit::transmissive &&
                     (!same_shading_record(want_s, got_s, *want_si.material) || want_si.material != got_si.material)))
                    ++mismatches;
                clear += a == ShadowHit::clear;
            }
        }
    }
    CHECK(mismatches == 0);
    INFO("joined " << joined_hits << " left " << left_hits << " occluded " << occluded << " crossings "
                   << joined_crossings << " clear " << clear);
    // Every kind of answer must be reached, or the comparison proves nothing.
    CHECK(joined_hits > 400);       // 746 measured
    CHECK(left_hits > 300);         // 635
    CHECK(occluded > 5000);         // 9,370
    CHECK(joined_crossings > 130);  // 273
    CHECK(clear > 30000);           // 89,955 over six answers a ray
}

TEST_CASE("a single small mesh or meshes over the limit keep their own trees", "[scene]") {
    auto objects = random_objects(5, 0, 3);
    objects.push_back({ball(1, 0.5f, Point3(0, 1, -8)), lambert(RGB(0.5f)), {}, "one"});
    CHECK(Scene(objects).flat_meshes() == 0);
    objects.push_back({ball(1, 0.5f, Point3(2, 1, -8)), lambert(RGB(0.5f)), {}, "two"});
    CHECK(Scene(objects).flat_meshes() == 2);
    CHECK(Scene(objects, {kSceneTreeThreshold, 79}).flat_meshes() == 0);  // 80 triangles each
    CHECK(Scene(objects, {kSceneTreeThreshold, 80}).flat_meshes() == 2);
}

TEST_CASE("a scene with flat meshes renders the image of its meshes on their own trees", "[scene]") {
    const MeshScene s = mesh_scene();
    RenderJob job;
    job.camera = std::make_shared<PinholeCamera>(CameraSpec{
        .eye = {0, 3, 2}, .look_at = {0, 1.5f, -10}, .vertical_fov_degrees = 50.0f, .width = 64, .height = 48});
    job.lights = {point_light(Point3(-3, 8, 0), 300.0f), point_light(Point3(4, 6, -4), 100.0f)};
    job.whitted.background = RGB(0.2f, 0.3f, 0.5f);
    job.whitted.max_depth = 6;
    job.scene = std::make_shared<Scene>(s.objects, SceneOptions{kSceneTreeThreshold, 0});
    const RenderResult alone = render_job(job);
    job.scene = std::make_shared<Scene>(s.objects);
    const RenderResult flat = render_job(job);
    CHECK(same_bytes(alone.image, flat.image));
    CHECK(alone.stats.rays == flat.stats.rays);
    CHECK(alone.stats.rays.refracted > 300);
    CHECK(alone.stats.rays.shadow > 3000);
}

TEST_CASE("a list walks meshes inside instances itself and answers as their shapes do", "[scene]") {
    // A mesh inside two Instances (a scene file's mesh with "fit" and a "transform"), one inside an Instance on a
    // BVH (no packets) and one placed directly: the list traces their accelerators itself, no virtual calls through
    // the shapes, and must give each shape's own records, bit for bit, and its own occlusion answers.
    auto objects = random_objects(12, 6, 29);
    auto inner = std::make_shared<const Instance>(
        ball(3, 1.0f, Point3(0.0f)), glm::scale(glm::rotate(Mat4(1.0f), 0.7f, Vec3(0.3f, 1.0f, 0.2f)), Vec3(0.6f)));
    auto nested = std::make_shared<const Instance>(
        inner, glm::translate(glm::rotate(Mat4(1.0f), 3.49f, Vec3(0, 1, 0)), Vec3(-1.5f, 1.0f, -8.0f)));
    auto on_bvh = std::make_shared<const Instance>(
        std::make_shared<const MeshShape>(std::make_shared<const TriangleMesh>(icosphere(2, 0.8f, Point3(0.0f))),
                                          "bvh"),
        glm::translate(Mat4(1.0f), Vec3(1.5f, 1.2f, -9.0f)));
    auto direct = ball(3, 0.9f, Point3(0.0f, 2.5f, -11.0f));
    for (const std::shared_ptr<const Shape>& shape :
         std::initializer_list<std::shared_ptr<const Shape>>{nested, on_bvh, direct})
        objects.push_back({shape, lambert(RGB(0.6f)), {}, "mesh"});
    const Scene scene(objects, {kAlwaysList, 0});
    REQUIRE(scene.structure() == "list");
    std::mt19937 rng(31);
    int mismatches = 0, mesh_hits = 0, blocked = 0;
    for (int i = 0; i < 20000; ++i) {
        const Ray r = random_ray(rng);
        // The list's order and ties: each object asked up to the nearest hit so far.
        Ray walk = r;
        SurfaceHit want;
        bool hit = false, occluded = false;
        for (const SceneObject& o : objects) {
            SurfaceHit h;
            if (o.shape->intersect(walk, h)) {
                walk.tmax = h.t;
                want = h;
                want.shape = o.shape.get();
                hit = true;
            }
            // Glass and the like let shadow rays through (intersect_transmissive's set).
            if (o.flags.casts_shadows && !o.material->transmits_shadows()) occluded = occluded || o.shape->occluded(r);
        }
        SurfaceHit got;
        if (scene.intersect(r, got) != hit || (hit && !same_record(want, got))) ++mismatches;
        if (scene.occluded(r) != occluded) ++mismatches;
        mesh_hits += hit && (want.shape == nested.get() || want.shape == on_bvh.get() || want.shape == direct.get());
        blocked += occluded;
    }
    CHECK(mismatches == 0);
    INFO("mesh hits " << mesh_hits << " blocked " << blocked);
    CHECK(mesh_hits > 200);  // 321 measured
    CHECK(blocked > 5000);   // 8,914
}
