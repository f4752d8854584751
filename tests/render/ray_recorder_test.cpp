// Recording the queries one object answers (rtlab/render/ray_recorder.hpp): the rays are those its mesh receives,
// in the mesh's own space, with the answers it gave; a render that records gives the same bytes; the cap keeps the
// first rays; bad names are errors.
#include "image_bytes.hpp"
#include "scene_fixtures.hpp"

#include <rtlab/accel/hit_agreement.hpp>
#include <rtlab/accel/mesh_shape.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/geometry/instance.hpp>
#include <rtlab/render/ray_recorder.hpp>
#include <rtlab/render/render_job.hpp>

#include <catch2/catch.hpp>
#include <test_meshes.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cstring>
#include <random>

using namespace rtlab;
using namespace rtlab::test;

namespace {

bool same_ray(const Ray& a, const Ray& b) { return std::memcmp(&a, &b, sizeof(Ray)) == 0; }

// The ball of these tests: an icosphere of 320 triangles off the origin, placed as the scene loader places a fitted,
// transformed mesh: an Instance (the fit) inside an Instance (the transform).
struct Ball {
    std::shared_ptr<const TriangleMesh> mesh =
        std::make_shared<const TriangleMesh>(icosphere(2, 1.0f, {0.3f, 0.2f, -0.1f}));
    std::shared_ptr<const MeshShape> shape = std::make_shared<const MeshShape>(mesh);
    Mat4 fit = glm::scale(glm::translate(Mat4(1.0f), Vec3(0.1f, 0.6f, 0.0f)), Vec3(0.6f));
    Mat4 place = glm::rotate(glm::translate(Mat4(1.0f), Vec3(0.2f, 0.0f, -0.3f)), glm::radians(30.0f), Vec3(0, 1, 0));
    std::shared_ptr<const Shape> placed = std::make_shared<Instance>(std::make_shared<Instance>(shape, fit), place);

    // The world ray as the mesh receives it: through each Instance's inverse, outer first.
    Ray to_mesh(const Ray& r) const {
        Ray out = r;
        for (const Mat4& m : {glm::inverse(place), glm::inverse(fit)}) {
            out.origin = Point3(m * Vec4(out.origin, 1.0f));
            out.direction = Vec3(m * Vec4(out.direction, 0.0f));
        }
        return out;
    }
};

std::shared_ptr<const Material> emitting(float radiance) {
    Params p;
    p.set("albedo", 0.0).set("emission", radiance);
    return material("lambert", p);
}

// A floor, the ball, two small meshes (which share the scene's flat tree) and a ceiling lamp; path traced, 16 x 16,
// 4 samples per pixel, on one thread.
RenderJob ball_job(const Ball& ball) {
    RenderJob job;
    job.camera = std::make_shared<PinholeCamera>(
        CameraSpec{.eye = {0, 1.2f, 2.5f}, .look_at = {0, 0.5f, -0.3f}, .width = 16, .height = 16});
    auto pebble =
        std::make_shared<const MeshShape>(std::make_shared<const TriangleMesh>(icosphere(1, 0.2f, {-0.8f, 0.2f, 0})));
    auto stone = std::make_shared<const MeshShape>(
        std::make_shared<const TriangleMesh>(icosphere(1, 0.25f, {0.9f, 0.25f, 0.2f})));
    job.scene = std::make_shared<Scene>(std::vector<SceneObject>{
        {std::make_shared<Quad>(Point3(-3, 0, 3), Vec3(6, 0, 0), Vec3(0, 0, -6)), lambert(RGB(0.6f)), {}, "floor"},
        {ball.placed, lambert(RGB(0.7f, 0.5f, 0.3f)), {}, "ball"},
        {pebble, lambert(RGB(0.3f, 0.6f, 0.3f)), {}, "pebble"},
        {stone, lambert(RGB(0.5f)), {}, "stone"},
        {std::make_shared<Quad>(Point3(-0.5f, 2.5f, -0.5f), Vec3(1, 0, 0), Vec3(0, 0, 1)),
         emitting(6.0f),
         {},
         "lamp"}});
    job.integrator = IntegratorKind::path;
    job.path.max_depth = 4;
    job.settings.pattern = PixelPattern::sobol;
    job.settings.spp = 4;
    job.settings.seed = 3;
    job.settings.threads = 1;
    return job;
}

// The job with the object `name` recording (at most `max` rays of each kind).
std::shared_ptr<RayRecorder> record(RenderJob& job, const std::string& name, std::size_t max = 1000000) {
    std::vector<SceneObject> objects = job.scene->objects();
    auto recorder = record_object_rays(objects, name, max);
    job.scene = std::make_shared<Scene>(std::move(objects));
    return recorder;
}

}  // namespace

TEST_CASE("a recorded object's queries are the rays its mesh receives in its own space with its answers",
          "[ray_recorder]") {
    const Ball ball;
    std::vector<SceneObject> objects{{ball.placed, lambert(RGB(0.5f)), {}, "ball"}};
    const auto recorder = record_object_rays(objects, "ball", 100000);
    const Scene scene(objects);
    CHECK(recorder->bounds().lo == ball.mesh->bounds().lo);
    CHECK(recorder->bounds().hi == ball.mesh->bounds().hi);

    // Rays from around the ball towards points near it, half of them segments ending before it or inside it.
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<Ray> expected_closest, expected_shadow;
    std::vector<float> world_t;
    std::vector<std::uint8_t> world_blocked;
    const int n = 2000;
    for (int i = 0; i < n; ++i) {
        const Point3 o(3.0f * u(rng), 0.8f + 3.0f * u(rng), 3.0f * u(rng));
        const Point3 target(0.8f * u(rng), 0.8f + 0.8f * u(rng), -0.3f + 0.8f * u(rng));
        Ray r{o, 1.7f * (target - o), 0.0f, kInfinity};
        if (i % 2 == 1) r.tmax = 0.5f + 0.5f * (u(rng) + 1.0f);
        if (i % 7 == 3) r.tmin = 0.4f;
        SurfaceHit hit;
        const bool found = scene.intersect(r, hit);
        const bool blocked = scene.occluded(r);
        const Ray local = ball.to_mesh(r);
        if (!ball.mesh->bounds().intersect(local)) continue;
        expected_closest.push_back(local);
        world_t.push_back(found ? hit.t : kInfinity);
        expected_shadow.push_back(local);
        world_blocked.push_back(blocked ? 1 : 0);
    }
    // The instance passes on only the rays near its world box (Instance::misses_bounds()): every overlapping one,
    // not necessarily the others.
    REQUIRE(recorder->closest_counts().answered <= n);
    REQUIRE(recorder->shadow_counts().answered <= n);
    REQUIRE(recorder->closest_counts().answered >= recorder->closest_counts().overlapping);
    REQUIRE(recorder->shadow_counts().answered >= recorder->shadow_counts().overlapping);
    REQUIRE(recorder->closest_rays().size() == expected_closest.size());
    REQUIRE(recorder->shadow_rays().size() == expected_shadow.size());
    CHECK(expected_closest.size() > 500);
    CHECK(expected_closest.size() < 1900);  // some rays pass beside the mesh's box, and are not kept

    const auto brute = make_accelerator("brute", *ball.mesh);
    std::size_t hits = 0, blockers = 0, disagreements = 0;
    for (std::size_t i = 0; i < expected_closest.size(); ++i) {
        INFO("ray " << i);
        const Ray& r = recorder->closest_rays()[i];
        CHECK(same_ray(r, expected_closest[i]));
        CHECK(same_ray(recorder->shadow_rays()[i], expected_shadow[i]));
        const RayRecorder::Answer a = recorder->closest_answers()[i];
        CHECK(a.t == world_t[i]);  // an Instance keeps t: the direction is transformed, not normalised
        CHECK(recorder->shadow_blocked()[i] == world_blocked[i]);
        // Replayed against another structure over the mesh's own triangles: the same hits.
        MeshHit b;
        const bool found = brute->intersect(r, b);
        disagreements += !same_hit(a.t < kInfinity, MeshHit{a.t, a.primitive, 0, 0}, found, b);
        disagreements += brute->occluded(recorder->shadow_rays()[i]) != (recorder->shadow_blocked()[i] != 0);
        hits += a.t < kInfinity;
        blockers += recorder->shadow_blocked()[i];
    }
    CHECK(disagreements == 0);
    CHECK(hits > 100);
    CHECK(hits < expected_closest.size());
    CHECK(blockers > 100);
    CHECK(blockers < expected_shadow.size());
}

TEST_CASE("a path-traced render that records gives the same bytes and rays that replay to its answers",
          "[ray_recorder]") {
    const Ball ball;
    RenderJob job = ball_job(ball);
    const RenderResult plain = render_job(job);
    const auto recorder = record(job, "ball");
    const RenderResult recorded = render_job(job);
    CHECK(same_bytes(plain.image, recorded.image));
    CHECK(plain.stats.rays == recorded.stats.rays);

    const std::vector<Ray>& closest = recorder->closest_rays();
    const std::vector<Ray>& shadow = recorder->shadow_rays();
    INFO(closest.size() << " closest-hit and " << shadow.size() << " shadow rays");
    CHECK(closest.size() > 200);
    CHECK(shadow.size() > 200);
    CHECK(recorder->closest_counts().overlapping == closest.size());
    CHECK(recorder->closest_counts().answered >= closest.size());
    // The mesh's own structure answers the recorded rays as it did in the render, bit for bit.
    const TriangleAccelerator& own = ball.shape->accelerator();
    std::size_t outside = 0, differ = 0, hits = 0, blockers = 0;
    for (std::size_t i = 0; i < closest.size(); ++i) {
        outside += !ball.mesh->bounds().intersect(closest[i]);
        MeshHit h;
        const bool found = own.intersect(closest[i], h);
        const RayRecorder::Answer a = recorder->closest_answers()[i];
        differ += found != (a.t < kInfinity) || (found && (h.t != a.t || h.primitive != a.primitive));
        hits += found;
    }
    for (std::size_t i = 0; i < shadow.size(); ++i) {
        outside += !ball.mesh->bounds().intersect(shadow[i]);
        const bool blocked = own.occluded(shadow[i]);
        differ += blocked != (recorder->shadow_blocked()[i] != 0);
        blockers += blocked;
    }
    CHECK(outside == 0);
    CHECK(differ == 0);
    CHECK(hits > 50);
    CHECK(blockers > 10);

    // One thread: the same rays in the same order every time.
    RenderJob again = ball_job(ball);
    const auto second = record(again, "ball");
    CHECK(same_bytes(render_job(again).image, plain.image));
    REQUIRE(second->closest_rays().size() == closest.size());
    REQUIRE(second->shadow_rays().size() == shadow.size());
    CHECK(std::memcmp(second->closest_rays().data(), closest.data(), closest.size() * sizeof(Ray)) == 0);
    CHECK(std::memcmp(second->shadow_rays().data(), shadow.data(), shadow.size() * sizeof(Ray)) == 0);

    SECTION("the cap keeps the first rays and counts the rest") {
        RenderJob capped = ball_job(ball);
        const auto few = record(capped, "ball", 50);
        CHECK(same_bytes(render_job(capped).image, plain.image));
        REQUIRE(few->closest_rays().size() == 50);
        REQUIRE(few->shadow_rays().size() == 50);
        CHECK(few->closest_counts().overlapping == closest.size());
        CHECK(few->shadow_counts().overlapping == shadow.size());
        CHECK(std::memcmp(few->closest_rays().data(), closest.data(), 50 * sizeof(Ray)) == 0);
        CHECK(std::memcmp(few->shadow_rays().data(), shadow.data(), 50 * sizeof(Ray)) == 0);
    }
    SECTION("a small mesh recorded leaves the flat tree and renders the same bytes") {
        RenderJob pebble = ball_job(ball);
        REQUIRE(pebble.scene->flat_meshes() == 2);
        const auto rec = record(pebble, "pebble");
        CHECK(pebble.scene->flat_meshes() == 0);
        CHECK(same_bytes(render_job(pebble).image, plain.image));
        CHECK(rec->closest_rays().size() > 20);
        CHECK(rec->shadow_rays().size() > 20);
    }
}

TEST_CASE("recording an unknown object or one that emits light is an error naming it", "[ray_recorder]") {
    const Ball ball;
    RenderJob job = ball_job(ball);
    std::vector<SceneObject> objects = job.scene->objects();
    CHECK_THROWS_MATCHES(record_object_rays(objects, "bal", 10), Error,
                         Catch::Matchers::Message("no object named 'bal'; did you mean 'ball'? (objects: floor, ball, "
                                                  "pebble, stone, lamp)"));
    CHECK_THROWS_WITH(record_object_rays(objects, "lamp", 10), Catch::Contains("object 'lamp' emits light"));
    CHECK(objects[1].shape == ball.placed);  // nothing replaced
}
