#include <rtlab/accel/point_kd_tree.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/core/rng.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

using namespace rtlab;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

bool by_distance_then_index(const PointNeighbor& a, const PointNeighbor& b) {
    return a.distance2 < b.distance2 || (a.distance2 == b.distance2 && a.index < b.index);
}

bool by_index(const PointNeighbor& a, const PointNeighbor& b) { return a.index < b.index; }

float gaussian(Rng& rng) {
    const float u = 1.0f - rng.uniform();  // (0, 1]
    return std::sqrt(-2.0f * std::log(u)) * std::cos(2.0f * kPi * rng.uniform());
}

Point3 uniform_point(Rng& rng) {
    const float x = rng.uniform();
    const float y = rng.uniform();
    return {x, y, rng.uniform()};
}

/// A point cloud to search, and the scale of its spread (for radii and queries).
struct Cloud {
    std::vector<Point3> points;
    float scale = 1.0f;
    float radius2 = 0.0225f;  // a finite search radius, squared: (0.15 scale)^2
};

enum class Shape {
    uniform,
    clustered,
    duplicates,
    coplanar,
    collinear,
    all_equal,
    tiny,
    huge,
    far_offset,
    overflowing
};

Cloud make_cloud(Shape shape, std::size_t n, std::uint64_t seed) {
    Rng rng(seed, static_cast<std::uint64_t>(shape));
    Cloud c;
    c.points.reserve(n);
    Point3 centres[5];
    float sigmas[5];
    for (int b = 0; b < 5; ++b) {
        centres[b] = uniform_point(rng);
        sigmas[b] = 0.005f + 0.01f * static_cast<float>(b);
    }
    for (std::size_t i = 0; i < n; ++i) {
        switch (shape) {
            case Shape::uniform:
                c.points.push_back(uniform_point(rng));
                break;
            case Shape::clustered: {
                const std::uint32_t b = rng.uniform_u32(5);
                const float x = gaussian(rng);
                const float y = gaussian(rng);
                c.points.push_back(centres[b] + sigmas[b] * Vec3(x, y, gaussian(rng)));
                break;
            }
            case Shape::duplicates: {  // 125 grid positions: many equal points and many equal distances
                const float x = static_cast<float>(rng.uniform_u32(5)) * 0.25f;
                const float y = static_cast<float>(rng.uniform_u32(5)) * 0.25f;
                c.points.push_back({x, y, static_cast<float>(rng.uniform_u32(5)) * 0.25f});
                break;
            }
            case Shape::coplanar: {
                const float x = rng.uniform();
                c.points.push_back({x, rng.uniform(), 0.5f});
                break;
            }
            case Shape::collinear:
                c.points.push_back({rng.uniform(), 0.25f, 0.75f});
                break;
            case Shape::all_equal:
                c.points.push_back({0.3f, -0.7f, 0.1f});
                break;
            case Shape::tiny:
                c.points.push_back(1e-6f * uniform_point(rng));
                break;
            case Shape::huge:
                c.points.push_back(2e6f * uniform_point(rng) - Vec3(1e6f));
                break;
            // Spacing of floats near 1e6 is 1/16: a 4-wide cube holds 64^3 positions, so distances tie often.
            case Shape::far_offset:
                c.points.push_back(Vec3(1e6f) + 4.0f * uniform_point(rng));
                break;
            // Squared distances overflow to infinity: they tie, and only an infinite radius reaches them.
            case Shape::overflowing:
                c.points.push_back(4e20f * uniform_point(rng) - Vec3(2e20f));
                break;
        }
    }
    switch (shape) {
        case Shape::tiny:
            c.scale = 1e-6f;
            break;
        case Shape::huge:
            c.scale = 2e6f;
            break;
        case Shape::far_offset:
            c.scale = 4.0f;
            break;
        case Shape::overflowing:
            c.scale = 4e20f;
            break;
        default:
            break;
    }
    c.radius2 = shape == Shape::overflowing ? 1e38f : (0.15f * c.scale) * (0.15f * c.scale);
    return c;
}

/// Queries inside the points' bounds (some exactly at points), outside them, and far away.
std::vector<Point3> make_queries(const Cloud& c, std::size_t count, std::uint64_t seed) {
    Rng rng(seed, 99);
    AABB box;
    for (const Point3& p : c.points) box.expand(p);
    if (box.is_empty()) box = {Point3(0.0f), Point3(c.scale)};
    std::vector<Point3> queries;
    for (std::size_t i = 0; i < count; ++i) {
        switch (i % 4) {
            case 0:
                queries.push_back(box.lo + uniform_point(rng) * box.extent());
                break;
            case 1:
                queries.push_back(
                    c.points.empty() ? box.lo : c.points[rng.uniform_u32(static_cast<std::uint32_t>(c.points.size()))]);
                break;
            case 2:
                queries.push_back(box.lo - Vec3(c.scale) + uniform_point(rng) * (box.extent() + Vec3(2.0f * c.scale)));
                break;
            default:
                queries.push_back(box.hi + Vec3(c.scale) * (1.0f + 3.0f * uniform_point(rng)));
                break;
        }
    }
    return queries;
}

std::string describe(const std::vector<PointNeighbor>& list) {
    std::ostringstream s;
    s << list.size() << " results:";
    for (std::size_t i = 0; i < std::min<std::size_t>(list.size(), 12); ++i)
        s << " (" << list[i].index << ", " << list[i].distance2 << ")";
    return s.str();
}

/// Compares every search of `tree` at one query and radius with brute force; returns the problems found.
std::string compare_with_brute_force(const PointKdTree& tree, const std::vector<Point3>& points, const Point3& q,
                                     float radius2) {
    std::vector<PointNeighbor> expected;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const float d2 = squared_distance(q, points[i]);
        if (d2 <= radius2) expected.push_back({static_cast<std::uint32_t>(i), d2});
    }
    std::sort(expected.begin(), expected.end(), by_distance_then_index);
    std::ostringstream problems;

    for (std::size_t k : {std::size_t{1}, std::size_t{8}, std::size_t{50}, points.size() + 5}) {
        // The search must write only out[0, k): the guard entries after it stay as they are.
        const PointNeighbor guard{0xdeadbeef, -1.0f};
        std::vector<PointNeighbor> out(k + 2, guard);
        const std::size_t count = tree.nearest(q, radius2, std::span(out.data(), k));
        const std::vector<PointNeighbor> found(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(count));
        const std::vector<PointNeighbor> want(
            expected.begin(), expected.begin() + static_cast<std::ptrdiff_t>(std::min(k, expected.size())));
        std::vector<float> found_d2, want_d2;
        for (const PointNeighbor& r : found) found_d2.push_back(r.distance2);
        for (const PointNeighbor& r : want) want_d2.push_back(r.distance2);
        if (found_d2 != want_d2)
            problems << "k = " << k << ": distances differ: tree " << describe(found) << "; brute force "
                     << describe(want) << "\n";
        else if (found != want)
            problems << "k = " << k << ": same distances, other indices: tree " << describe(found) << "; brute force "
                     << describe(want) << "\n";
        if (out[k] != guard || out[k + 1] != guard) problems << "k = " << k << ": wrote past the buffer\n";
    }

    std::vector<PointNeighbor> in_tree_order;
    tree.within(q, radius2, in_tree_order);
    std::vector<PointNeighbor> in_index_order{{7, 7.0f}};  // appended to, not replaced
    tree.within(q, radius2, in_index_order, PointOrder::index);
    std::vector<PointNeighbor> want = expected;
    std::sort(want.begin(), want.end(), by_index);
    if (in_index_order.empty() || in_index_order.front() != PointNeighbor{7, 7.0f})
        problems << "within: the vector's earlier content was lost\n";
    else if (!std::equal(in_index_order.begin() + 1, in_index_order.end(), want.begin(), want.end()))
        problems << "within (index order): tree " << describe(in_index_order) << "; brute force " << describe(want)
                 << "\n";
    std::sort(in_tree_order.begin(), in_tree_order.end(), by_index);
    if (in_tree_order != want) problems << "within (tree order) is not the same set as by index\n";

    std::size_t calls = 0;
    tree.for_each_within(q, radius2, [&](std::uint32_t, float) { ++calls; });
    if (calls != want.size()) problems << "for_each_within: " << calls << " calls for " << want.size() << " points\n";
    return problems.str();
}

void check_shape(Shape shape) {
    const float kInf = std::numeric_limits<float>::infinity();
    for (std::size_t n : {0, 1, 2, 7, 1000, 20000}) {
        const Cloud cloud = make_cloud(shape, n, 1234 + n);
        const PointKdTree tree(cloud.points);
        REQUIRE(tree.size() == n);
        const std::vector<Point3> queries = make_queries(cloud, n >= 20000 ? 8 : 24, 77 + n);
        for (const Point3& q : queries) {
            for (float radius2 : {0.0f, cloud.radius2, kInf}) {
                const std::string problems = compare_with_brute_force(tree, cloud.points, q, radius2);
                if (!problems.empty()) {
                    std::ostringstream where;
                    where << "n = " << n << ", query (" << q.x << ", " << q.y << ", " << q.z
                          << "), radius2 = " << radius2 << ":\n"
                          << problems;
                    FAIL_CHECK(where.str());
                }
            }
        }
    }
}

/// The points a radius search visits, in its order.
std::vector<std::uint32_t> visit_order(const PointKdTree& tree, const Point3& q, float radius2) {
    std::vector<std::uint32_t> order;
    tree.for_each_within(q, radius2, [&](std::uint32_t i, float) { order.push_back(i); });
    return order;
}

}  // namespace

TEST_CASE("point kd-tree agrees with brute force on uniform random points", "[point_kd_tree]") {
    check_shape(Shape::uniform);
}
TEST_CASE("point kd-tree agrees with brute force on Gaussian clusters", "[point_kd_tree]") {
    check_shape(Shape::clustered);
}
TEST_CASE("point kd-tree agrees with brute force on many duplicate points", "[point_kd_tree]") {
    check_shape(Shape::duplicates);
}
TEST_CASE("point kd-tree agrees with brute force on coplanar points", "[point_kd_tree]") {
    check_shape(Shape::coplanar);
}
TEST_CASE("point kd-tree agrees with brute force on collinear points", "[point_kd_tree]") {
    check_shape(Shape::collinear);
}
TEST_CASE("point kd-tree agrees with brute force when all points are equal", "[point_kd_tree]") {
    check_shape(Shape::all_equal);
}
TEST_CASE("point kd-tree agrees with brute force at the 1e-6 scale", "[point_kd_tree]") { check_shape(Shape::tiny); }
TEST_CASE("point kd-tree agrees with brute force at the 1e6 scale", "[point_kd_tree]") { check_shape(Shape::huge); }
TEST_CASE("point kd-tree agrees with brute force on points offset by 1e6 where distances tie", "[point_kd_tree]") {
    check_shape(Shape::far_offset);
}
TEST_CASE("point kd-tree agrees with brute force when squared distances overflow to infinity", "[point_kd_tree]") {
    check_shape(Shape::overflowing);
}

TEST_CASE("point kd-tree: equal distances are broken by the smaller index", "[point_kd_tree]") {
    // Six points at distance 1 from the origin, two of them twice, listed out of axis order.
    const std::vector<Point3> points = {{0, 0, -1}, {1, 0, 0}, {0, -1, 0}, {0, 0, 1}, {-1, 0, 0},
                                        {0, 1, 0},  {1, 0, 0}, {0, 0, -1}, {2, 0, 0}};
    const PointKdTree tree(points);
    PointNeighbor out[3];
    REQUIRE(tree.nearest(Point3(0.0f), kInfinity, out) == 3);
    CHECK(out[0] == PointNeighbor{0, 1.0f});
    CHECK(out[1] == PointNeighbor{1, 1.0f});
    CHECK(out[2] == PointNeighbor{2, 1.0f});
    PointNeighbor all[12];
    REQUIRE(tree.nearest(Point3(0.0f), 1.0f, all) == 8);  // the radius is inclusive; point 8 is at 4
    for (std::uint32_t i = 0; i < 8; ++i) CHECK(all[i] == PointNeighbor{i, 1.0f});
}

TEST_CASE("point kd-tree: radius 0 finds exactly the points equal to the query", "[point_kd_tree]") {
    const Point3 q(0.5f, 0.25f, 0.125f);
    const std::vector<Point3> points = {q, {next_float_up(0.5f), 0.25f, 0.125f}, q, {0.5f, 0.25f, 0.0f}};
    const PointKdTree tree(points);
    std::vector<PointNeighbor> found;
    tree.within(q, 0.0f, found, PointOrder::index);
    CHECK(found == std::vector<PointNeighbor>{{0, 0.0f}, {2, 0.0f}});
    PointNeighbor out[4];
    CHECK(tree.nearest(q, 0.0f, out) == 2);
}

TEST_CASE("point kd-tree: empty trees and k = 0 find nothing", "[point_kd_tree]") {
    const std::vector<Point3> none;
    for (const PointKdTree& tree : {PointKdTree(), PointKdTree(none)}) {
        CHECK(tree.empty());
        CHECK(tree.bounds().is_empty());
        PointNeighbor out[4];
        CHECK(tree.nearest(Point3(0.0f), kInfinity, out) == 0);
        std::vector<PointNeighbor> found;
        tree.within(Point3(0.0f), kInfinity, found);
        CHECK(found.empty());
    }
    const std::vector<Point3> points = {{0, 0, 0}, {1, 1, 1}};
    const PointKdTree tree(points);
    CHECK(tree.nearest(Point3(0.0f), kInfinity, std::span<PointNeighbor>()) == 0);
}

TEST_CASE("point kd-tree: a negative or NaN radius and a NaN query find nothing", "[point_kd_tree]") {
    const Cloud cloud = make_cloud(Shape::uniform, 100, 5);
    const PointKdTree tree(cloud.points);
    PointNeighbor out[8];
    CHECK(tree.nearest(Point3(0.5f), -1.0f, out) == 0);
    CHECK(tree.nearest(Point3(0.5f), kNaN, out) == 0);
    CHECK(tree.nearest(Point3(0.5f, kNaN, 0.5f), kInfinity, out) == 0);
    std::vector<PointNeighbor> found;
    tree.within(Point3(kNaN), kInfinity, found);
    tree.within(Point3(0.5f), -kInfinity, found);
    CHECK(found.empty());
}

TEST_CASE("point kd-tree refuses NaN and infinite points and names the index", "[point_kd_tree]") {
    std::vector<Point3> points(10, Point3(1.0f));
    const auto message_for = [&](std::size_t i, Point3 bad) {
        std::vector<Point3> copy = points;
        copy[i] = bad;
        try {
            PointKdTree tree(copy);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    using Catch::Matchers::Contains;
    CHECK_THAT(message_for(5, Point3(0.0f, kNaN, 0.0f)), Contains("point 5 ") && Contains("finite"));
    CHECK_THAT(message_for(0, Point3(kInfinity, 0.0f, 0.0f)), Contains("point 0 ") && Contains("finite"));
    CHECK_THAT(message_for(9, Point3(0.0f, 0.0f, -kInfinity)), Contains("point 9 ") && Contains("finite"));
}

TEST_CASE("point kd-tree: the tree and its search order do not depend on the thread count", "[point_kd_tree]") {
    // Large enough for the build to split work between threads.
    const Cloud cloud = make_cloud(Shape::clustered, 40000, 11);
    const PointKdTree one(cloud.points, 1);
    const PointKdTree two(cloud.points, 2);
    const PointKdTree any(cloud.points);
    for (const Point3& q : make_queries(cloud, 8, 3)) {
        const std::vector<std::uint32_t> order = visit_order(one, q, cloud.radius2);
        CHECK(visit_order(two, q, cloud.radius2) == order);
        CHECK(visit_order(any, q, cloud.radius2) == order);
        // A sum in tree order is the same float from every build.
        const auto sum = [&](const PointKdTree& tree) {
            float s = 0.0f;
            tree.for_each_within(q, cloud.radius2, [&](std::uint32_t, float d2) { s += d2; });
            return s;
        };
        CHECK(sum(two) == sum(one));
    }
}
