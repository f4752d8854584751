#include "packet_bench.hpp"

#include <rtlab/accel/ray_io.hpp>
#include <rtlab/core/error.hpp>

#include <fmt/core.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <bit>
#include <cstdint>
#include <span>
#include <string>

namespace rtlab::accel_app {

namespace {

constexpr std::size_t kPacket = 8;  // one 4 x 2 tile

// The row-major n x n primary set reordered into 4 x 2 tiles, row by row of tiles: rays 0-3 of a tile are
// its upper row, 4-7 its lower one.
std::vector<Ray> tiled(const std::vector<Ray>& rows, int n) {
    std::vector<Ray> rays;
    rays.reserve(rows.size());
    const auto at = [&](int x, int y) { return rows[static_cast<std::size_t>(y) * static_cast<std::size_t>(n) + x]; };
    for (int ty = 0; ty < n; ty += 2)
        for (int tx = 0; tx < n; tx += 4)
            for (int y = ty; y < ty + 2; ++y)
                for (int x = tx; x < tx + 4; ++x) rays.push_back(at(x, y));
    return rays;
}

// Shadow rays from the closest hits of `primary` (misses left out, the order kept, so that consecutive rays
// leave neighbouring pixels' hits) towards `light`: t runs from the hit (t = 0) to the light (t = 1), the
// first 1e-4 left out so that a ray does not find its own surface again, the light itself outside (t < 1).
std::vector<Ray> shadow_rays(const TriangleAccelerator& accel, const std::vector<Ray>& primary, const Point3& light,
                             tbb::task_arena& arena) {
    std::vector<MeshHit> hits(primary.size());
    arena.execute([&] { accel.intersect_packet(primary, hits); });
    std::vector<Ray> rays;
    for (std::size_t i = 0; i < primary.size(); ++i) {
        if (!hits[i].hit()) continue;
        const Point3 p = primary[i].at(hits[i].t);
        rays.push_back(Ray{p, light - p, 1e-4f, 1.0f});
    }
    return rays;
}

template <class F>
void for_packets(std::size_t count, F&& f) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 1024), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t first = r.begin(); first < r.end(); first += kPacket)
            f(first, std::min(kPacket, r.end() - first));
    });
}

// One pass of each kind; blocks of 1024 rays keep the tiles whole.
void trace(const TriangleAccelerator& accel, const std::vector<Ray>& rays, bool packets, bool thread_time, Traced& t) {
    const double start = clock_seconds(thread_time);
    if (packets) {
        for_packets(rays.size(), [&](std::size_t first, std::size_t n) {
            accel.intersect_packet(std::span(rays).subspan(first, n), std::span(t.hits).subspan(first, n));
        });
    } else {
        for_packets(rays.size(), [&](std::size_t first, std::size_t n) {
            for (std::size_t i = first; i < first + n; ++i) {
                MeshHit h;
                t.hits[i] = accel.intersect(rays[i], h) ? h : MeshHit{};
            }
        });
    }
    const double middle = clock_seconds(thread_time);
    if (packets) {
        for_packets(rays.size(), [&](std::size_t first, std::size_t n) {
            accel.occluded_packet(std::span(rays).subspan(first, n), std::span(t.blocked).subspan(first, n));
        });
    } else {
        for_packets(rays.size(), [&](std::size_t first, std::size_t n) {
            for (std::size_t i = first; i < first + n; ++i) t.blocked[i] = accel.occluded(rays[i]) ? 1 : 0;
        });
    }
    t.closest_s.push_back(middle - start);
    t.any_s.push_back(clock_seconds(thread_time) - middle);
}

bool same_bits(float a, float b) { return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b); }

// Rays whose packet answer is not the single ray's, bit for bit (closest-hit; any-hit).
std::pair<std::size_t, std::size_t> differences(const Traced& single, const Traced& packets) {
    std::size_t closest = 0, any = 0;
    for (std::size_t i = 0; i < single.hits.size(); ++i) {
        const MeshHit &a = single.hits[i], &b = packets.hits[i];
        closest += !(same_bits(a.t, b.t) && a.primitive == b.primitive && same_bits(a.u, b.u) && same_bits(a.v, b.v));
        any += single.blocked[i] != packets.blocked[i];
    }
    return {closest, any};
}

}  // namespace

void run_packet_sets(const Options& o, const TriangleMesh& mesh, const std::vector<Built>& built,
                     const TriangleAccelerator* reference, Report& report, tbb::task_arena& arena) {
    if (o.primary_size % 4 != 0)
        throw Error("--packets traces 4 x 2 tiles: --primary-size " + std::to_string(o.primary_size) +
                    " is not a multiple of 4");
    const AABB bounds = mesh.bounds();
    const std::vector<Ray> primary = tiled(primary_rays(bounds, o.primary_size), o.primary_size);
    // Above the mesh (+y), towards the camera (+z) and to one side: most shadow rays of a tile share an
    // octant, those of tiles below the light's x and z lines do not.
    const Point3 light = bounds.center() + bounds.diagonal() * Vec3(0.25f, 1.0f, 0.5f);
    struct Set {
        std::string name;
        std::vector<Ray> rays;
    };
    const std::vector<Set> sets = {{"primary", primary},
                                   {"shadow", shadow_rays(*built.front().accel, primary, light, arena)}};
    fmt::print(
        "packets: {} x {} primary rays in 4 x 2 tiles; {} shadow rays from their hits ({}) towards ({}, {}, {})\n",
        o.primary_size, o.primary_size, sets[1].rays.size(), built.front().method, light.x, light.y, light.z);
    std::vector<std::string> summary;
    for (const Set& set : sets) {
        const Reference ref = reference_answers(reference, set.rays, o.sample_size, arena);
        std::vector<Traced> single(built.size()), packets(built.size());
        for (std::size_t m = 0; m < built.size(); ++m)
            for (Traced* t : {&single[m], &packets[m]}) {
                t->rays = &set.rays;
                t->hits.resize(set.rays.size());
                t->blocked.resize(set.rays.size());
            }
        // The methods and both ways take turns in each round (round -1 untimed), as trace_in_rounds.
        const bool thread_time = arena.max_concurrency() == 1;
        arena.execute([&] {
            for (int round = -1; round < o.runs; ++round)
                for (std::size_t m = 0; m < built.size(); ++m) {
                    trace(*built[m].accel, set.rays, false, thread_time, single[m]);
                    trace(*built[m].accel, set.rays, true, thread_time, packets[m]);
                }
        });
        for (std::size_t m = 0; m < built.size(); ++m) {
            for (Traced* t : {&single[m], &packets[m]}) {  // drop the warm-up round
                t->closest_s.erase(t->closest_s.begin());
                t->any_s.erase(t->any_s.begin());
            }
            report.add(score(built[m], single[m], ref, mesh), set.name, ref.name);
            Score s = score(built[m], packets[m], ref, mesh);
            s.method += " 4x2";
            report.add(s, set.name, ref.name);
            const auto [closest, any] = differences(single[m], packets[m]);
            summary.push_back(
                fmt::format("{} {}: packets differ from single rays (bit for bit) on {} closest-hit and "
                            "{} any-hit answers of {}",
                            set.name, built[m].method, closest, any, set.rays.size()));
        }
        // Each method's packets against every method's single rays and packets, from the same rounds.
        for (std::size_t m = 0; m < built.size(); ++m)
            for (std::size_t k = 0; k < built.size(); ++k) {
                if (k == m) continue;
                auto ratio = [](const std::vector<double>& a, const std::vector<double>& b) {
                    return median(b) / median(a);
                };
                summary.push_back(fmt::format(
                    "{} {} 4x2 speed / {}: single {:.3f} closest, {:.3f} any-hit; 4x2 {:.3f} closest, {:.3f} any-hit",
                    set.name, built[m].method, built[k].method, ratio(packets[m].closest_s, single[k].closest_s),
                    ratio(packets[m].any_s, single[k].any_s), ratio(packets[m].closest_s, packets[k].closest_s),
                    ratio(packets[m].any_s, packets[k].any_s)));
            }
        for (std::size_t m = 0; m < built.size(); ++m)
            summary.push_back(fmt::format("{} {} 4x2 speed / its single rays: {:.3f} closest, {:.3f} any-hit", set.name,
                                          built[m].method, median(single[m].closest_s) / median(packets[m].closest_s),
                                          median(single[m].any_s) / median(packets[m].any_s)));
    }
    for (const std::string& line : summary) fmt::print("{}\n", line);
}

}  // namespace rtlab::accel_app
