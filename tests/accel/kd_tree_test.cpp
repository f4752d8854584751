#include <rtlab/accel/kd_tree.hpp>
#include <rtlab/accel/mesh_shape.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/geometry/instance.hpp>

#include <catch2/catch.hpp>

#include "test_meshes.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>

using namespace rtlab;

namespace {

// Two kinds of shape for the mixed-kind tree: spheres and axis-aligned boxes, each reporting its id.
struct TestSphere final : Shape {
    Point3 c;
    float r;
    std::uint32_t id;
    TestSphere(Point3 c_, float r_, std::uint32_t id_) : c(c_), r(r_), id(id_) {}
    AABB bounds() const override { return {c - Vec3(r), c + Vec3(r)}; }
    bool intersect(const Ray& ray, SurfaceHit& hit) const override {
        const Vec3 oc = ray.origin - c;
        const float a = glm::dot(ray.direction, ray.direction), b = glm::dot(oc, ray.direction);
        const float disc = b * b - a * (glm::dot(oc, oc) - r * r);
        if (disc < 0.0f) return false;
        for (float t : {(-b - std::sqrt(disc)) / a, (-b + std::sqrt(disc)) / a})
            if (t > ray.tmin && t < ray.tmax) {
                hit.t = t;
                hit.primitive = id;
                return true;
            }
        return false;
    }
    bool occluded(const Ray& ray) const override {
        SurfaceHit h;
        return intersect(ray, h);
    }
};
struct TestBox final : Shape {
    AABB box;
    std::uint32_t id;
    TestBox(AABB b, std::uint32_t id_) : box(b), id(id_) {}
    AABB bounds() const override { return box; }
    bool intersect(const Ray& ray, SurfaceHit& hit) const override {
        const auto range = box.intersect(ray);
        if (!range) return false;
        const float t = range->min > ray.tmin ? range->min : range->max;
        if (!(t > ray.tmin && t < ray.tmax)) return false;
        hit.t = t;
        hit.primitive = id;
        return true;
    }
    bool occluded(const Ray& ray) const override {
        SurfaceHit h;
        return intersect(ray, h);
    }
};

}  // namespace

TEST_CASE("kd nodes are 8 bytes and pack axis and counts", "[kd]") {
    STATIC_REQUIRE(sizeof(KdNode) == 8);
    const KdNode interior = KdNode::interior(2, 1.5f, 12345);
    CHECK_FALSE(interior.is_leaf());
    CHECK(interior.axis() == 2);
    CHECK(interior.split() == 1.5f);
    CHECK(interior.children() == 12345);
    CHECK(interior.empty_children() == 0);
    const KdNode flagged = KdNode::interior(1, -2.0f, KdNode::kMaxIndex, true, false);
    CHECK(flagged.axis() == 1);
    CHECK(flagged.children() == KdNode::kMaxIndex);
    CHECK(flagged.empty_children() == 1);
    CHECK(KdNode::interior(0, 0.0f, 7, false, true).empty_children() == 2);
    const KdNode leaf = KdNode::leaf(7, 99);
    CHECK(leaf.is_leaf());
    CHECK(leaf.primitive_count() == 7);
    CHECK(leaf.primitive_offset() == 99);
}

TEST_CASE("interior nodes flag exactly their empty children and keep siblings in one cache line", "[kd]") {
    const TriangleMesh sphere = test::icosphere(4);  // hollow: the SAH cuts off empty space inside and out
    KdBuildInput input;
    for (std::size_t i = 0; i < sphere.triangle_count(); ++i) input.bounds.push_back(sphere.triangle_bounds(i));
    for (KdStrategy s : {KdStrategy::sah, KdStrategy::sah_binned, KdStrategy::median, KdStrategy::midpoint}) {
        const KdTreeData tree = build_kd_tree(input, s);
        auto empty_leaf = [&](std::uint32_t i) {
            return tree.nodes[i].is_leaf() && tree.nodes[i].primitive_count() == 0;
        };
        int flagged = 0, wrong = 0, odd = 0;
        std::vector<int> parents(tree.nodes.size(), 0);
        for (std::uint32_t i = 0; i < tree.nodes.size(); ++i) {
            const KdNode& n = tree.nodes[i];
            if (n.is_leaf()) continue;
            const std::uint32_t below = n.children();
            REQUIRE(below + 1 < tree.nodes.size());
            if (below % 2 != 0) ++odd;
            ++parents[below];
            ++parents[below + 1];
            const std::uint32_t expected = (empty_leaf(below) ? 1u : 0u) | (empty_leaf(below + 1) ? 2u : 0u);
            if (n.empty_children() != expected) ++wrong;
            if (expected != 0) ++flagged;
        }
        INFO(kd_strategy_name(s) << ": " << flagged << " interior nodes with an empty child, "
                                 << tree.stats.empty_leaves << " empty leaves");
        CHECK(wrong == 0);
        CHECK(odd == 0);  // pairs start at even indices: 16-byte aligned, never split across cache lines
        CHECK(flagged == tree.stats.empty_leaves);  // an empty leaf is never the root here
        // Every node but the root and its padding has exactly one parent, and the padding is an empty leaf.
        CHECK(parents[0] == 0);
        CHECK(parents[1] == 0);
        CHECK(empty_leaf(1));
        CHECK(std::count(parents.begin() + 2, parents.end(), 1) == static_cast<long>(tree.nodes.size()) - 2);
        CHECK(tree.stats.nodes == static_cast<std::int64_t>(tree.nodes.size()) - 1);
    }
}

TEST_CASE("a closest-hit walk in a split plane tests the far child after a hit in nodes pushed later", "[kd]") {
    // By hand: the root splits x at 0; its below child splits z at 2 (leaf A below; above it a node splitting
    // z at 6 into leaves B1 and B2); its above child is leaf C. A ray along +z in the plane x = 0 has a NaN
    // distance to the root's plane: it enters the near child (by the sign of its x component) and pushes the
    // other over its whole interval [0, 10], before the near child pushes intervals beginning at 2 and 6.
    // Below the plane, B1 is hit at t = 5; above it, C at t = 1. The node beginning at 6 lies past the hit
    // at 5, but the one under it, C, does not: the walk must go on to C and answer t = 1.
    KdTreeData tree;
    tree.nodes.resize(8, KdNode::leaf(0, 0));
    tree.nodes[0] = KdNode::interior(0, 0.0f, 2);
    tree.nodes[2] = KdNode::interior(2, 2.0f, 4);
    tree.nodes[3] = KdNode::leaf(1, 2);  // C
    tree.nodes[4] = KdNode::leaf(1, 0);  // A
    tree.nodes[5] = KdNode::interior(2, 6.0f, 6);
    tree.nodes[6] = KdNode::leaf(1, 1);  // B1
    tree.nodes[7] = KdNode::leaf(1, 3);  // B2
    tree.bounds = AABB(Point3(-1.0f, -1.0f, 0.0f), Point3(1.0f, 1.0f, 10.0f));
    tree.max_depth = 4;
    const float hit_t[4] = {kInfinity, 5.0f, 1.0f, 8.0f};  // A misses; B1, C, B2
    for (float x_direction : {0.0f, -0.0f}) {
        const Ray ray{Point3(0.0f, 0.5f, 0.0f), Vec3(x_direction, 0.0f, 1.0f)};  // t = z
        std::vector<std::uint32_t> visited;
        float closest = kInfinity;
        const bool hit = kd_traverse<false>(tree, ray, [&](const KdNode& leaf, float& limit) {
            visited.push_back(leaf.primitive_offset());
            if (!(hit_t[leaf.primitive_offset()] < limit)) return false;
            limit = hit_t[leaf.primitive_offset()];
            closest = limit;
            return true;
        });
        INFO("x component " << (std::signbit(x_direction) ? "-0" : "+0") << ", " << visited.size() << " leaves tested");
        CHECK(hit);
        CHECK(closest == 1.0f);
        CHECK(std::find(visited.begin(), visited.end(), 2u) != visited.end());
        // any-hit stops at the first leaf that hits
        CHECK(kd_traverse<true>(
            tree, ray, [&](const KdNode& leaf, float&) { return hit_t[leaf.primitive_offset()] < kInfinity; }));
    }
}

TEST_CASE("the cost model validates its constants", "[kd]") {
    CHECK_THROWS_AS(KdCostModel(0.0f, 1.0f, 0.2f), Error);
    CHECK_THROWS_AS(KdCostModel(1.0f, -1.0f, 0.2f), Error);
    CHECK_THROWS_AS(KdCostModel(1.0f, 1.0f, 1.0f), Error);
    const KdCostModel m(1.0f, 2.0f, 0.5f);
    CHECK(m.leaf_cost(4) == 8.0f);
    CHECK(m.split_cost(0.5f, 0.5f, 2, 2) == Approx(1.0f + 2.0f * 2.0f));
    CHECK(m.split_cost(0.5f, 0.5f, 0, 4) == Approx(1.0f + 0.5f * 2.0f * 2.0f));  // empty-space bonus
}

TEST_CASE("SAH trees stop by cost and are identical with 1 and 2 threads", "[kd]") {
    const TriangleMesh sphere = test::icosphere(5);  // 20,480 triangles
    KdBuildInput input;
    for (std::size_t i = 0; i < sphere.triangle_count(); ++i) input.bounds.push_back(sphere.triangle_bounds(i));
    for (KdStrategy s : {KdStrategy::sah, KdStrategy::sah_binned, KdStrategy::median, KdStrategy::midpoint}) {
        const KdTreeData one = build_kd_tree(input, s, {}, 1);
        const KdTreeData two = build_kd_tree(input, s, {}, 2);
        INFO(kd_strategy_name(s) << ": nodes " << one.stats.nodes << ", depth " << one.stats.max_depth << ", mean leaf "
                                 << one.stats.mean_leaf_primitives << ", SAH " << one.stats.sah_cost);
        CHECK(one.stats.nodes == two.stats.nodes);
        CHECK(one.primitive_indices == two.primitive_indices);
        CHECK(one.stats.leaves == (one.stats.nodes + 1) / 2);
        CHECK(one.stats.max_depth < 40);
        CHECK(one.stats.mean_leaf_primitives > 0.5);
        CHECK(one.stats.mean_leaf_primitives < 20.0);
    }
    // The full SAH finds trees at least as cheap as its binned approximation (by its own cost model).
    const KdTreeData sah = build_kd_tree(input, KdStrategy::sah);
    const KdTreeData binned = build_kd_tree(input, KdStrategy::sah_binned);
    const KdTreeData median = build_kd_tree(input, KdStrategy::median);
    CHECK(sah.stats.sah_cost <= binned.stats.sah_cost * 1.02);
    CHECK(sah.stats.sah_cost < median.stats.sah_cost);
}

TEST_CASE("kd-sah finds the splits of the naive O(N^2) SAH on boxes enough for its radix-sorted events", "[kd]") {
    // 2,500 boxes give 5,000 events per axis: the root's events take the radix sort, the clipped ones
    // std::sort. A fifth of the coordinates sit at -0 or +0 (equal planes with different bits) and
    // some at shared grid values, so the sweep's grouping of equal positions is exercised. No box is
    // flat: there the naive SAH puts planar primitives always left and the trees may rightly differ.
    std::mt19937 rng(7);
    auto uniform = [&rng] { return static_cast<float>(rng() >> 8) * 0x1p-23f - 1.0f; };  // [-1, 1)
    auto coordinate = [&](float& c) {
        const std::uint32_t pick = rng() % 10;
        c = pick == 0 ? -0.0f : pick == 1 ? 0.0f : pick == 2 ? std::round(c * 8.0f) / 8.0f : c;
    };
    KdBuildInput input;
    while (input.bounds.size() < 2500) {
        Point3 a(uniform(), uniform(), uniform()), b(uniform(), uniform(), uniform());
        for (int k = 0; k < 3; ++k) {
            coordinate(a[k]);
            coordinate(b[k]);
        }
        AABB box{glm::min(a, b), glm::max(a, b)};
        if (box.lo.x < box.hi.x && box.lo.y < box.hi.y && box.lo.z < box.hi.z) input.bounds.push_back(box);
    }
    const KdTreeData sah = build_kd_tree(input, KdStrategy::sah, {}, 1);
    const KdTreeData naive = build_kd_tree(input, KdStrategy::sah_naive, {}, 1);
    INFO("kd-sah: nodes " << sah.stats.nodes << ", SAH " << sah.stats.sah_cost << "; naive: nodes " << naive.stats.nodes
                          << ", SAH " << naive.stats.sah_cost);
    CHECK(sah.stats.nodes == naive.stats.nodes);
    CHECK(sah.stats.max_depth == naive.stats.max_depth);
    CHECK(sah.stats.sah_cost == Approx(naive.stats.sah_cost).epsilon(1e-6));
    CHECK(sah.primitive_indices.size() == naive.primitive_indices.size());
    CHECK(sah.stats.nodes > 100);
}

TEST_CASE("a kd-tree over shapes of mixed kinds, itself a shape inside another tree", "[kd]") {
    std::vector<std::shared_ptr<const Shape>> shapes;
    std::uint32_t id = 0;
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) {
            const Point3 c(2.0f * i, 2.0f * j, 0.0f);
            if ((i + j) % 2)
                shapes.push_back(std::make_shared<TestSphere>(c, 0.7f, id++));
            else
                shapes.push_back(std::make_shared<TestBox>(AABB{c - Vec3(0.5f), c + Vec3(0.5f)}, id++));
        }
    const auto inner = std::make_shared<KdShapeTree>(shapes);
    // The tree of trees: the first tree is one primitive of the outer one, beside a far sphere.
    const KdShapeTree outer({inner, std::make_shared<TestSphere>(Point3(100, 0, 0), 1.0f, 999)});
    int checked = 0;
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) {
            const Ray down{{2.0f * i, 2.0f * j, 5.0f}, {0.0f, -0.0f, -1.0f}};
            SurfaceHit a, b;
            REQUIRE(inner->intersect(down, a));
            REQUIRE(outer.intersect(down, b));
            CHECK(a.primitive == static_cast<std::uint32_t>(i * 6 + j));
            CHECK(b.primitive == a.primitive);
            CHECK(a.t == Approx((i + j) % 2 ? 5.0f - 0.7f : 4.5f));
            CHECK(outer.occluded(down));
            ++checked;
        }
    CHECK(checked == 36);
    SurfaceHit far;
    REQUIRE(outer.intersect(Ray{{90, 0, 0}, {1, 0, 0}}, far));
    CHECK(far.primitive == 999);
    CHECK_FALSE(outer.occluded(Ray{{2, 1, 5}, {0, 0, -1}}));  // between the shapes
}

TEST_CASE("a scene of meshes as a tree of trees: mesh shapes and their instances in a kd-tree", "[kd]") {
    const auto sphere = std::make_shared<TriangleMesh>(test::icosphere(3));  // radius 1, 1280 triangles
    const auto mesh = std::make_shared<MeshShape>(sphere);
    std::vector<std::shared_ptr<const Shape>> objects;
    objects.push_back(mesh);  // at the origin
    for (int k = 1; k <= 4; ++k) {
        // The same mesh three units apart along x, scaled by 0.5.
        const Mat4 m = glm::scale(glm::translate(Mat4(1.0f), Vec3(3.0f * k, 0, 0)), Vec3(0.5f));
        objects.push_back(std::make_shared<Instance>(mesh, m));
    }
    const KdShapeTree scene(objects);
    CHECK(scene.bounds().hi.x == Approx(12.5f));
    for (int k = 0; k <= 4; ++k) {
        const float radius = k == 0 ? 1.0f : 0.5f;
        const Ray down{{3.0f * k, 0.01f, 5.0f}, {0.0f, 0.0f, -1.0f}};
        SurfaceHit h;
        REQUIRE(scene.intersect(down, h));
        INFO("object " << k);
        CHECK(h.t == Approx(5.0f - radius).epsilon(0.02));  // the icosphere lies within 1.5% of the sphere
        CHECK(h.point.x == Approx(3.0f * k).margin(0.02));
        CHECK(h.geometric_normal.z > 0.9f);
        CHECK(h.front_face);
        CHECK(scene.occluded(down));
    }
    SurfaceHit h;
    CHECK_FALSE(scene.intersect(Ray{{1.5f, 0.0f, 5.0f}, {0.0f, 0.0f, -1.0f}}, h));  // between the objects
    // Along the row: the first object hit is the big sphere at the origin, entered at x = -1.
    REQUIRE(scene.intersect(Ray{{-5.0f, 0.01f, 0.01f}, {1.0f, 0.0f, 0.0f}}, h));
    CHECK(h.t == Approx(4.0f).epsilon(0.01));
}

namespace {

// Clips a triangle to a box in float, plane by plane (Sutherland-Hodgman): not the library's conservative
// clip, but a deterministic one, so that a build with it depends on nothing but its input.
AABB test_clip(const TriangleMesh& mesh, std::uint32_t i, const AABB& box) {
    std::vector<Point3> poly = {mesh.corner(i, 0), mesh.corner(i, 1), mesh.corner(i, 2)}, next;
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            const float plane = side == 0 ? box.lo[axis] : box.hi[axis];
            auto inside = [&](const Point3& p) { return side == 0 ? p[axis] >= plane : p[axis] <= plane; };
            next.clear();
            for (std::size_t k = 0; k < poly.size(); ++k) {
                const Point3& p = poly[k];
                const Point3& q = poly[(k + 1) % poly.size()];
                if (inside(p)) next.push_back(p);
                if (inside(p) != inside(q)) {
                    Point3 x = p + (plane - p[axis]) / (q[axis] - p[axis]) * (q - p);
                    x[axis] = plane;
                    next.push_back(x);
                }
            }
            poly.swap(next);
        }
    AABB out;
    for (const Point3& p : poly) out.expand(p);
    return out;
}

bool same_nodes(const KdTreeData& a, const KdTreeData& b) {
    return a.nodes.size() == b.nodes.size() &&
           std::memcmp(a.nodes.data(), b.nodes.data(), a.nodes.size() * sizeof(KdNode)) == 0;
}

}  // namespace

TEST_CASE("kd-sah trees over clipped triangles are the same node for node on any thread count", "[kd]") {
    // A closed sphere and an overlapping soup (many straddling, clipped triangles), each large enough for
    // the build to fork and, at the root, to work on both threads.
    for (const TriangleMesh& mesh : {test::icosphere(5), test::random_soup(20000, 11, 0.6f)}) {
        KdBuildInput input;
        for (std::size_t i = 0; i < mesh.triangle_count(); ++i) input.bounds.push_back(mesh.triangle_bounds(i));
        input.clip = [&mesh](std::uint32_t i, const AABB& box) { return test_clip(mesh, i, box); };
        const KdTreeData one = build_kd_tree(input, KdStrategy::sah, kd_mesh_cost_model(), 1);
        INFO(mesh.triangle_count() << " triangles: nodes " << one.stats.nodes << ", depth " << one.stats.max_depth
                                   << ", SAH " << one.stats.sah_cost);
        CHECK(one.stats.nodes > 500);
        for (int threads : {2, 0}) {
            const KdTreeData other = build_kd_tree(input, KdStrategy::sah, kd_mesh_cost_model(), threads);
            CHECK(same_nodes(one, other));
            CHECK(one.primitive_indices == other.primitive_indices);
            CHECK(one.stats.sah_cost == other.stats.sah_cost);
        }
        // The mesh accelerator (the library's own clip and leaf layout): the same figures on 1 and 2 threads.
        BuildOptions options;
        options.threads = 1;
        const AccelStats a = make_kd_tree("kd-sah", mesh, options)->stats();
        options.threads = 2;
        const AccelStats b = make_kd_tree("kd-sah", mesh, options)->stats();
        CHECK(a.nodes == b.nodes);
        CHECK(a.max_depth == b.max_depth);
        CHECK(a.bytes == b.bytes);
        CHECK(a.sah_cost == b.sah_cost);
    }
}

TEST_CASE("a kd-tree that is one leaf answers single rays as its packets do", "[kd]") {
    // An open box of 10 triangles and a quad just under its top (the Cornell box's walls and light): kd-sah keeps
    // them in one leaf, which single rays test without the walk, and without the root clip for origins inside.
    TriangleMesh m;
    const float lo = 0.0f, hi = 0.5f, top = 0.4999f;
    auto quad = [&m](Point3 a, Point3 b, Point3 c, Point3 d) {
        const auto base = static_cast<std::uint32_t>(m.positions.size());
        m.positions.insert(m.positions.end(), {a, b, c, d});
        m.triangles.push_back({base, base + 1, base + 2});
        m.triangles.push_back({base, base + 2, base + 3});
    };
    quad({lo, lo, lo}, {hi, lo, lo}, {hi, lo, hi}, {lo, lo, hi});                      // floor
    quad({lo, hi, lo}, {lo, hi, hi}, {hi, hi, hi}, {hi, hi, lo});                      // top
    quad({lo, lo, hi}, {hi, lo, hi}, {hi, hi, hi}, {lo, hi, hi});                      // back
    quad({lo, lo, lo}, {lo, lo, hi}, {lo, hi, hi}, {lo, hi, lo});                      // left
    quad({hi, lo, lo}, {hi, hi, lo}, {hi, hi, hi}, {hi, lo, hi});                      // right
    quad({0.2f, top, 0.2f}, {0.3f, top, 0.2f}, {0.3f, top, 0.3f}, {0.2f, top, 0.3f});  // light
    for (const int width : kd_leaf_widths()) {
        BuildOptions options;
        options.leaf_width = width;
        const auto tree = make_kd_tree("kd-sah", m, options);
        REQUIRE(tree->stats().nodes == 1);
        // Rays from inside, from the faces and edges, from outside, in the walls' planes, axis-parallel with +0 and
        // -0, and with intervals that start or end before 0.
        std::mt19937 rng(41);
        std::uniform_real_distribution<float> u(-0.1f, 0.6f), d(-1.0f, 1.0f);
        const float grid[] = {lo, 0.2f, 0.25f, top, hi, -0.1f, 0.6f};
        std::vector<Ray> rays;
        for (int i = 0; i < 4000; ++i) {
            Point3 o(u(rng), u(rng), u(rng));
            if (i % 3 == 1) o[i % 2] = grid[(i / 3) % 7];
            Vec3 dir(d(rng), d(rng), d(rng));
            if (i % 5 == 2) dir[i % 3] = (i % 2) ? 0.0f : -0.0f;
            Ray r{o, dir};
            if (i % 7 == 3) r.tmin = -0.5f;
            if (i % 11 == 4) r.tmax = -0.01f;
            if (i % 13 == 5) r.tmax = 0.3f;
            rays.push_back(r);
        }
        std::vector<MeshHit> packet(rays.size());
        std::vector<std::uint8_t> blocked(rays.size());
        tree->intersect_packet(rays, packet);
        tree->occluded_packet(rays, blocked);
        int mismatches = 0, hits = 0;
        for (std::size_t i = 0; i < rays.size(); ++i) {
            MeshHit h;
            const bool hit = tree->intersect(rays[i], h);
            hits += hit;
            if (hit != packet[i].hit() ||
                (hit && (std::memcmp(&h.t, &packet[i].t, sizeof(float)) != 0 || h.primitive != packet[i].primitive ||
                         std::memcmp(&h.u, &packet[i].u, sizeof(float)) != 0 ||
                         std::memcmp(&h.v, &packet[i].v, sizeof(float)) != 0)))
                ++mismatches;
            if (tree->occluded(rays[i]) != (blocked[i] != 0)) ++mismatches;
        }
        CHECK(mismatches == 0);
        CHECK(hits > 1000);  // 1,631 measured
    }
}
