// The recursion every kd strategy shares: choose a split, partition (clipping straddling primitives to
// each side for perfect splits), recurse -- large subtrees in parallel with oneTBB -- then flatten the
// tree depth-first into 8-byte nodes and compute its statistics.
#include <rtlab/accel/kd_build.hpp>
#include <rtlab/core/error.hpp>

#include "kd_split.hpp"

#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>

namespace rtlab {

namespace {

struct BuildNode {
    int axis = -1;  // -1: leaf
    float split = 0.0f;
    std::vector<std::uint32_t> primitives;
    std::unique_ptr<BuildNode> below, above;
};

constexpr std::size_t kParallelThreshold = 4096;
constexpr std::size_t kNaiveWarnSize = 20000;

class Builder {
public:
    Builder(const KdBuildInput& input, KdStrategy strategy, const KdCostModel& cost, int max_depth)
        : m_input(input), m_strategy(strategy), m_cost(cost), m_max_depth(max_depth) {}

    using Events = std::array<std::vector<kd::Event>, 3>;

    /// kd-sah: the events are sorted once at the root and stay sorted on the way down.
    std::unique_ptr<BuildNode> build_sah_root(std::vector<kd::Prim> prims, const AABB& box) const {
        Events events;
        for (auto& e : events) e.reserve(2 * prims.size());
        for (std::size_t i = 0; i < prims.size(); ++i) kd::add_events(prims[i].box, static_cast<std::uint32_t>(i), events);
        kd::sort_events(events);
        return build_sah(std::move(prims), std::move(events), box, 0);
    }

    std::unique_ptr<BuildNode> build_sah(std::vector<kd::Prim> prims, Events events, const AABB& box, int depth) const {
        auto node = std::make_unique<BuildNode>();
        const kd::Split split = depth < m_max_depth && !prims.empty() ? kd::sweep_sah(events, prims.size(), box, m_cost) : kd::Split{};
        auto make_leaf = [&] {
            node->primitives.reserve(prims.size());
            for (const kd::Prim& p : prims) node->primitives.push_back(p.index);
            return std::move(node);
        };
        if (split.axis < 0) return make_leaf();
        AABB below_box = box, above_box = box;
        below_box.hi[split.axis] = split.position;
        above_box.lo[split.axis] = split.position;
        // Slots in each child (kNone: not there) and the clipped boxes of straddling primitives.
        constexpr std::uint32_t kNone = 0xFFFFFFFFu;
        const std::size_t n = prims.size();
        std::vector<std::uint32_t> below_slot(n, kNone), above_slot(n, kNone);
        std::vector<kd::Prim> below, above;
        std::vector<std::uint32_t> straddling;
        for (std::uint32_t i = 0; i < n; ++i) {
            const kd::Prim& p = prims[i];
            const float lo = p.box.lo[split.axis], hi = p.box.hi[split.axis];
            const bool to_below = (lo == split.position && hi == split.position) ? split.planar_left : hi <= split.position;
            const bool to_above = (lo == split.position && hi == split.position) ? !split.planar_left : lo >= split.position;
            if (to_below) {
                below_slot[i] = static_cast<std::uint32_t>(below.size());
                below.push_back(p);
            } else if (to_above) {
                above_slot[i] = static_cast<std::uint32_t>(above.size());
                above.push_back(p);
            } else {
                straddling.push_back(i);
            }
        }
        // Straddlers are clipped to each side; their old events are dropped and new ones generated.
        Events below_new, above_new;
        const std::size_t below_kept = below.size(), above_kept = above.size();
        for (std::uint32_t i : straddling) {
            const AABB b = clip(prims[i], below_box), a = clip(prims[i], above_box);
            if (!b.is_empty()) {
                kd::add_events(b, static_cast<std::uint32_t>(below.size()), below_new);
                below.push_back({prims[i].index, b});
            }
            if (!a.is_empty()) {
                kd::add_events(a, static_cast<std::uint32_t>(above.size()), above_new);
                above.push_back({prims[i].index, a});
            }
        }
        if (2 * (below.size() + above.size()) > 3 * n) return make_leaf();
        kd::sort_events(below_new);
        kd::sort_events(above_new);
        Events below_events, above_events;
        for (int axis = 0; axis < 3; ++axis) {
            // A stable filter keeps the parent's order; the few new events are merged in.
            std::vector<kd::Event> b, a;
            b.reserve(2 * below_kept);
            a.reserve(2 * above_kept);
            for (const kd::Event& e : events[axis]) {
                if (below_slot[e.slot] != kNone) b.push_back({e.position, e.type, below_slot[e.slot]});
                else if (above_slot[e.slot] != kNone) a.push_back({e.position, e.type, above_slot[e.slot]});
            }
            below_events[axis].resize(b.size() + below_new[axis].size());
            std::merge(b.begin(), b.end(), below_new[axis].begin(), below_new[axis].end(), below_events[axis].begin());
            above_events[axis].resize(a.size() + above_new[axis].size());
            std::merge(a.begin(), a.end(), above_new[axis].begin(), above_new[axis].end(), above_events[axis].begin());
        }
        Events().swap(events);
        std::vector<kd::Prim>().swap(prims);
        node->axis = split.axis;
        node->split = split.position;
        if (below.size() + above.size() > kParallelThreshold) {
            tbb::task_group group;
            group.run([&] { node->below = build_sah(std::move(below), std::move(below_events), below_box, depth + 1); });
            node->above = build_sah(std::move(above), std::move(above_events), above_box, depth + 1);
            group.wait();
        } else {
            node->below = build_sah(std::move(below), std::move(below_events), below_box, depth + 1);
            node->above = build_sah(std::move(above), std::move(above_events), above_box, depth + 1);
        }
        return node;
    }

    std::unique_ptr<BuildNode> build(std::vector<kd::Prim> prims, const AABB& box, int depth) const {
        auto node = std::make_unique<BuildNode>();
        const kd::Split split = depth < m_max_depth && !prims.empty() ? choose(prims, box, depth) : kd::Split{};
        if (split.axis < 0) {
            node->primitives.reserve(prims.size());
            for (const kd::Prim& p : prims) node->primitives.push_back(p.index);
            return node;
        }
        AABB below_box = box, above_box = box;
        below_box.hi[split.axis] = split.position;
        above_box.lo[split.axis] = split.position;
        std::vector<kd::Prim> below, above;
        partition(prims, split, below_box, above_box, below, above);
        // A split that copies more than half of the primitives to both sides does not pay: stop. The
        // cost model alone misses this in flat nodes (all primitives in one plane, as with 1000 stacked
        // quads), where the two halves' areas add up to the parent's and every such split looks a little
        // cheaper than a leaf -- the tree would then grow exponentially. The spatial strategies, which
        // ignore cost, need the rule on any overlapping input.
        if (2 * (below.size() + above.size()) > 3 * prims.size()) {
            for (const kd::Prim& p : prims) node->primitives.push_back(p.index);
            return node;
        }
        std::vector<kd::Prim>().swap(prims);
        node->axis = split.axis;
        node->split = split.position;
        if (below.size() + above.size() > kParallelThreshold) {
            tbb::task_group group;
            group.run([&] { node->below = build(std::move(below), below_box, depth + 1); });
            node->above = build(std::move(above), above_box, depth + 1);
            group.wait();
        } else {
            node->below = build(std::move(below), below_box, depth + 1);
            node->above = build(std::move(above), above_box, depth + 1);
        }
        return node;
    }

private:
    kd::Split choose(const std::vector<kd::Prim>& prims, const AABB& box, int depth) const {
        switch (m_strategy) {
            case KdStrategy::sah: break;  // built from sorted events by build_sah
            case KdStrategy::sah_binned: return kd::find_split_binned(prims, box, m_cost);
            case KdStrategy::sah_naive: return kd::find_split_naive(prims, box, m_cost);
            case KdStrategy::median: return kd::find_split_median(prims, box, depth);
            case KdStrategy::midpoint: return kd::find_split_midpoint(prims, box);
        }
        return {};
    }

    AABB clip(const kd::Prim& p, const AABB& box) const {
        if (m_input.clip) return m_input.clip(p.index, box).intersected(box);
        return p.box.intersected(box);
    }

    void partition(const std::vector<kd::Prim>& prims, const kd::Split& s, const AABB& below_box,
                   const AABB& above_box, std::vector<kd::Prim>& below, std::vector<kd::Prim>& above) const {
        for (const kd::Prim& p : prims) {
            const float lo = p.box.lo[s.axis], hi = p.box.hi[s.axis];
            if (lo == s.position && hi == s.position) {
                (s.planar_left ? below : above).push_back(p);
            } else if (hi <= s.position) {
                below.push_back(p);
            } else if (lo >= s.position) {
                above.push_back(p);
            } else {
                // Straddles the plane: each side keeps the part of the primitive inside it, if any.
                const AABB b = clip(p, below_box), a = clip(p, above_box);
                if (!b.is_empty()) below.push_back({p.index, b});
                if (!a.is_empty()) above.push_back({p.index, a});
            }
        }
    }

    const KdBuildInput& m_input;
    KdStrategy m_strategy;
    const KdCostModel& m_cost;
    int m_max_depth;
};

struct Flattener {
    KdTreeData& out;
    const KdCostModel& cost;
    std::int64_t nodes = 0, leaves = 0, empty_leaves = 0, leaf_primitives = 0, max_depth = 0;

    // Writes the root at 0 and an empty leaf at 1, so that every sibling pair after them starts at an even
    // index. Returns the tree's SAH cost.
    double flatten_root(const BuildNode& root, const AABB& box) {
        out.nodes.resize(2, KdNode::leaf(0, 0));
        return flatten(root, 0, box, 0);
    }

    // Writes node at index and, below it, its children's pair and their subtrees. Returns the node's SAH
    // cost (absolute, relative to the node's own surface area).
    double flatten(const BuildNode& node, std::uint32_t index, const AABB& box, int depth) {
        ++nodes;
        max_depth = std::max<std::int64_t>(max_depth, depth);
        if (node.axis < 0) {
            const auto count = static_cast<std::uint32_t>(node.primitives.size());
            ++leaves;
            if (count == 0) ++empty_leaves;
            leaf_primitives += count;
            if (count == 1) {
                out.nodes[index] = KdNode::leaf(1, node.primitives[0]);
            } else {
                out.nodes[index] = KdNode::leaf(count, static_cast<std::uint32_t>(out.primitive_indices.size()));
                out.primitive_indices.insert(out.primitive_indices.end(), node.primitives.begin(), node.primitives.end());
            }
            return cost.leaf_cost(count);
        }
        const auto children = static_cast<std::uint32_t>(out.nodes.size());
        if (children + 1 > KdNode::kMaxIndex) throw Error("kd-tree: more than 2^28 nodes");
        out.nodes.resize(out.nodes.size() + 2);
        auto empty = [](const BuildNode& child) { return child.axis < 0 && child.primitives.empty(); };
        out.nodes[index] = KdNode::interior(node.axis, node.split, children, empty(*node.below), empty(*node.above));
        AABB below_box = box, above_box = box;
        below_box.hi[node.axis] = node.split;
        above_box.lo[node.axis] = node.split;
        const double below_cost = flatten(*node.below, children, below_box, depth + 1);
        const double above_cost = flatten(*node.above, children + 1, above_box, depth + 1);
        const double area = box.surface_area();
        if (!(area > 0.0)) return cost.traversal() + below_cost + above_cost;
        return cost.traversal() + (below_box.surface_area() * below_cost + above_box.surface_area() * above_cost) / area;
    }
};

}  // namespace

std::string_view kd_strategy_name(KdStrategy s) {
    switch (s) {
        case KdStrategy::sah: return "kd-sah";
        case KdStrategy::sah_binned: return "kd-sah-binned";
        case KdStrategy::sah_naive: return "kd-sah-naive";
        case KdStrategy::median: return "kd-median";
        case KdStrategy::midpoint: return "kd-midpoint";
    }
    return "?";
}

KdStrategy parse_kd_strategy(std::string_view name) {
    for (KdStrategy s : {KdStrategy::sah, KdStrategy::sah_binned, KdStrategy::sah_naive, KdStrategy::median,
                         KdStrategy::midpoint})
        if (kd_strategy_name(s) == name) return s;
    throw Error("unknown kd-tree strategy '" + std::string(name) +
                "'; known: kd-sah, kd-sah-binned, kd-sah-naive, kd-median, kd-midpoint");
}

KdTreeData build_kd_tree(const KdBuildInput& input, KdStrategy strategy, const KdCostModel& cost, int threads) {
    const auto start = std::chrono::steady_clock::now();
    std::vector<kd::Prim> prims;
    prims.reserve(input.bounds.size());
    KdTreeData out;
    for (std::size_t i = 0; i < input.bounds.size(); ++i) {
        const AABB& b = input.bounds[i];
        if (b.is_empty() || !is_finite(b.lo) || !is_finite(b.hi)) continue;
        prims.push_back({static_cast<std::uint32_t>(i), b});
        out.bounds.expand(b);
    }
    if (strategy == KdStrategy::sah_naive && prims.size() > kNaiveWarnSize)
        std::cerr << "warning: kd-sah-naive costs O(N^2) per node; " << prims.size()
                  << " primitives will take a long time (use kd-sah)\n";
    // A safety cap only (pbrt's 8 + 1.3 log2 N); the cost model ends the SAH strategies well before it.
    const int max_depth =
        std::min(60, 8 + static_cast<int>(std::round(1.3 * std::log2(std::max<std::size_t>(prims.size(), 1)))));
    Builder builder(input, strategy, cost, max_depth);
    std::unique_ptr<BuildNode> root;
    auto run = [&] {
        root = strategy == KdStrategy::sah ? builder.build_sah_root(std::move(prims), out.bounds)
                                           : builder.build(std::move(prims), out.bounds, 0);
    };
    if (threads > 0) tbb::task_arena(threads).execute(run);
    else run();

    Flattener f{out, cost};
    out.stats.sah_cost = f.flatten_root(*root, out.bounds);
    out.max_depth = static_cast<int>(f.max_depth) + 1;
    out.stats.nodes = f.nodes;
    out.stats.leaves = f.leaves;
    out.stats.empty_leaves = f.empty_leaves;
    out.stats.max_depth = f.max_depth;
    const std::int64_t full = f.leaves - f.empty_leaves;
    out.stats.mean_leaf_primitives = full > 0 ? static_cast<double>(f.leaf_primitives) / static_cast<double>(full) : 0.0;
    out.stats.bytes = static_cast<std::int64_t>(out.nodes.size() * sizeof(KdNode) +
                                                out.primitive_indices.size() * sizeof(std::uint32_t));
    out.stats.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

}  // namespace rtlab
