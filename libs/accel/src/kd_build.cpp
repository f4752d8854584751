// The recursion every kd strategy shares: choose a split, partition (clipping straddling primitives to
// each side for perfect splits), recurse -- large subtrees in parallel with oneTBB -- then flatten the
// tree depth-first into 8-byte nodes and compute its statistics.
#include <rtlab/accel/kd_build.hpp>
#include <rtlab/core/error.hpp>

#include "kd_split.hpp"
#include "thread_arena.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_invoke.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <deque>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>

namespace rtlab {

namespace {

struct BuildNode {
    int axis = -1;  // -1: leaf
    float split = 0.0f;
    std::vector<std::uint32_t> primitives;
    BuildNode *below = nullptr, *above = nullptr;
};

/// \brief The build's nodes, in one deque per thread (stable addresses): a node costs no allocation of
/// its own, and the whole tree goes at once when the build ends.
using NodeArena = tbb::enumerable_thread_specific<std::deque<BuildNode>>;

constexpr std::size_t kParallelThreshold = 1024;
/// Events (of the three axes) of a node large enough for its own work to be split between threads.
constexpr std::size_t kParallelEvents = 3 * 32768;
constexpr std::size_t kNaiveWarnSize = 20000;
constexpr std::uint32_t kNone = 0xFFFFFFFFu;

constexpr std::uint32_t kAbove = 1u << 31;

/// \brief Per-thread lists a node's split needs only until its children's lists are made (before any
/// recursion or wait, so on one thread): kept between nodes, so that they are allocated a few times per
/// thread rather than once per node.
struct Scratch {
    std::vector<std::uint32_t> moved;                         // by the node's slot, see Partition
    std::vector<std::uint32_t> below_clipped, above_clipped;  // slots in Partition::below / above
    std::array<std::vector<kd::Event>, 3> below_new, above_new;

    // Lists grown past kKept are dropped once their node is split: a thread would otherwise hold the largest
    // node's (the root's: hundreds of kB) after the build, and how many threads do varies from build to build.
    // Reallocating them costs little beside such a node's split.
    static constexpr std::size_t kKept = 1u << 12;
    void release_large() {
        const auto drop = [](auto& v) {
            if (v.capacity() > kKept) std::remove_reference_t<decltype(v)>().swap(v);
        };
        drop(moved);
        drop(below_clipped);
        drop(above_clipped);
        for (auto& v : below_new) drop(v);
        for (auto& v : above_new) drop(v);
    }
};

Scratch& thread_scratch() {
    thread_local Scratch scratch;
    return scratch;
}

/// \brief A node's primitives split between its children, in the node's order. A primitive lying wholly on
/// one side keeps its box there, and `moved` records its slot on that side (with kAbove set for the
/// upper side); one straddling the plane goes, clipped, to each side its clipped box is not empty on, is
/// kNone in `moved` and is listed in `*_clipped`. `moved` and `*_clipped` are the thread's scratch lists.
struct Partition {
    std::vector<kd::Prim> below, above;
    const std::vector<std::uint32_t>& moved;
    const std::vector<std::uint32_t>& below_clipped;
    const std::vector<std::uint32_t>& above_clipped;
};

/// Copies the events of `from` whose primitive goes to one side into `below` or `above`, renumbered to
/// the side's slots, and merges in the sides' new (sorted) events on the way -- one pass, no second buffer.
/// Each side's list needs room for one event more than it gets: every event is written to both and only the
/// side it goes to moves on.
void filter_and_merge(const std::vector<kd::Event>& from, const std::uint32_t* moved,
                      const std::vector<kd::Event>& below_new, const std::vector<kd::Event>& above_new,
                      std::vector<kd::Event>& below, std::vector<kd::Event>& above) {
    kd::Event* out_b = below.data();
    kd::Event* out_a = above.data();
    const kd::Event *nb = below_new.data(), *nb_end = nb + below_new.size();
    const kd::Event *na = above_new.data(), *na_end = na + above_new.size();
    // The least position of the sides' next new events: an event before it goes out without a merge step.
    constexpr float kNoMore = std::numeric_limits<float>::infinity();
    const auto next_new = [&] {
        return std::min(nb != nb_end ? nb->position : kNoMore, na != na_end ? na->position : kNoMore);
    };
    float next = next_new();
    for (const kd::Event& e : from) {
        const std::uint32_t m = moved[e.slot()];
        const kd::Event x = e.with_slot(m & ~kAbove);
        if (!(x.position < next)) [[unlikely]] {
            // A side's new events before x go before any later event of that side too (the events come
            // sorted), so both sides take theirs here, whichever side x goes to.
            while (nb != nb_end && *nb < x) *out_b++ = *nb++;
            while (na != na_end && *na < x) *out_a++ = *na++;
            next = next_new();
        }
        // Branch-free: on the two axes other than the split's, the side an event goes to is as good as
        // random (the filter's share of the bunny build's samples 25.2% -> 23.2%, perf). Bit operations for
        // the lower side: GCC turned the comparison back into a branch.
        *out_b = x;
        *out_a = x;
        out_b += ~m >> 31;                                    // below: kAbove clear (kNone has it set)
        out_a += m - kAbove <= kd::Event::kSlotMask ? 1 : 0;  // above: kAbove set, not kNone
    }
    out_b = std::copy(nb, nb_end, out_b);
    out_a = std::copy(na, na_end, out_a);
    below.resize(static_cast<std::size_t>(out_b - below.data()));
    above.resize(static_cast<std::size_t>(out_a - above.data()));
}

/// \brief kd-sah: the split events are sorted once at the root and stay sorted on the way down; a node's
/// state is its events.
struct SahStrategy {
    using State = std::array<std::vector<kd::Event>, 3>;
    const KdCostModel& cost;

    State root_state(const std::vector<kd::Prim>& prims) const { return kd::root_events(prims); }
    kd::Split choose(const std::vector<kd::Prim>& prims, const State& events, const AABB& box, int) const {
        return kd::sweep_sah(events, prims.size(), box, cost);
    }
    /// The children's events: a filter of the parent's keeps their order; only the clipped primitives get
    /// new events, which are sorted among themselves and merged in.
    std::pair<State, State> child_states(State events, const Partition& part) const {
        Scratch& scratch = thread_scratch();
        State& below_new = scratch.below_new;
        State& above_new = scratch.above_new;
        kd::sorted_events(part.below, part.below_clipped, below_new);
        kd::sorted_events(part.above, part.above_clipped, above_new);
        State below_events, above_events;
        auto filter = [&](std::size_t axis) {
            // Sized for the most events the sides can get and the one more filter_and_merge writes (left
            // uninitialized), cut to size after.
            below_events[axis].resize(2 * (part.below.size() - part.below_clipped.size()) + below_new[axis].size() + 1);
            above_events[axis].resize(2 * (part.above.size() - part.above_clipped.size()) + above_new[axis].size() + 1);
            filter_and_merge(events[axis], part.moved.data(), below_new[axis], above_new[axis], below_events[axis],
                             above_events[axis]);
            std::vector<kd::Event>().swap(events[axis]);
        };
        // A large node's axes in parallel (the root's cut and the few nodes below it, before the build has
        // forked enough to keep every thread busy). Isolated: this thread's scratch lists are in use until
        // the filters end, so it must not take up another node's work while it waits for them.
        if (events[0].size() + events[1].size() + events[2].size() >= kParallelEvents)
            tbb::this_task_arena::isolate(
                [&] { tbb::parallel_invoke([&] { filter(0); }, [&] { filter(1); }, [&] { filter(2); }); });
        else
            for (std::size_t axis = 0; axis < 3; ++axis) filter(axis);
        return {std::move(below_events), std::move(above_events)};
    }
};

/// \brief The strategies that choose a split from the node's primitives alone (binned, naive, median,
/// midpoint): no state.
struct PrimitiveStrategy {
    struct State {};
    KdStrategy strategy;
    const KdCostModel& cost;

    State root_state(const std::vector<kd::Prim>&) const { return {}; }
    kd::Split choose(const std::vector<kd::Prim>& prims, const State&, const AABB& box, int depth) const {
        switch (strategy) {
            case KdStrategy::sah:
                break;  // SahStrategy's
            case KdStrategy::sah_binned:
                return kd::find_split_binned(prims, box, cost);
            case KdStrategy::sah_naive:
                return kd::find_split_naive(prims, box, cost);
            case KdStrategy::median:
                return kd::find_split_median(prims, box, depth);
            case KdStrategy::midpoint:
                return kd::find_split_midpoint(prims, box);
        }
        return {};
    }
    std::pair<State, State> child_states(State, const Partition&) const { return {}; }
};

/// \brief The recursion every strategy shares: ask the strategy for a split, partition the primitives
/// (clipping straddlers to each side), stop at a leaf when the split copies too many, hand the children
/// their share of the strategy's state, recurse -- large subtrees in parallel.
template <class Strategy>
class Builder {
public:
    using State = typename Strategy::State;

    Builder(const KdBuildInput& input, const Strategy& strategy, int max_depth, NodeArena& arena)
        : m_input(input), m_strategy(strategy), m_max_depth(max_depth), m_arena(arena) {}

    const BuildNode* build_root(std::vector<kd::Prim> prims, const AABB& box) const {
        State state = m_strategy.root_state(prims);
        return build(std::move(prims), std::move(state), box, 0);
    }

private:
    BuildNode* build(std::vector<kd::Prim> prims, State state, const AABB& box, int depth) const {
        const kd::Split split =
            depth < m_max_depth && !prims.empty() ? m_strategy.choose(prims, state, box, depth) : kd::Split{};
        if (split.axis < 0) return leaf(prims);
        AABB below_box = box, above_box = box;
        below_box.hi[split.axis] = split.position;
        above_box.lo[split.axis] = split.position;
        Partition part = partition(prims, split, below_box, above_box);
        // A split that copies more than half of the primitives to both sides does not pay: stop. The
        // cost model alone misses this in flat nodes (all primitives in one plane, as with 1000 stacked
        // quads), where the two halves' areas add up to the parent's and every such split looks a little
        // cheaper than a leaf -- the tree would then grow exponentially. The spatial strategies, which
        // ignore cost, need the rule on any overlapping input.
        if (2 * (part.below.size() + part.above.size()) > 3 * prims.size()) {
            thread_scratch().release_large();
            return leaf(prims);
        }
        auto [below_state, above_state] = m_strategy.child_states(std::move(state), part);
        thread_scratch().release_large();
        std::vector<kd::Prim>().swap(prims);
        BuildNode* node = new_node();
        node->axis = split.axis;
        node->split = split.position;
        auto build_below = [&] {
            node->below = build(std::move(part.below), std::move(below_state), below_box, depth + 1);
        };
        auto build_above = [&] {
            node->above = build(std::move(part.above), std::move(above_state), above_box, depth + 1);
        };
        if (part.below.size() + part.above.size() > kParallelThreshold) {
            tbb::task_group group;
            group.run(build_below);
            build_above();
            group.wait();
        } else {
            build_below();
            build_above();
        }
        return node;
    }

    BuildNode* new_node() const { return &m_arena.local().emplace_back(); }

    BuildNode* leaf(const std::vector<kd::Prim>& prims) const {
        BuildNode* node = new_node();
        node->primitives.reserve(prims.size());
        for (const kd::Prim& p : prims) node->primitives.push_back(p.index);
        return node;
    }

    AABB clip(const kd::Prim& p, const AABB& box) const {
        if (m_input.clip) return m_input.clip(p.index, box).intersected(box);
        return p.box.intersected(box);
    }

    // Primitives lying in the plane go to the side the split chose for them; the others to the side
    // they lie on, or clipped to both.
    Partition partition(const std::vector<kd::Prim>& prims, const kd::Split& s, const AABB& below_box,
                        const AABB& above_box) const {
        enum Side : std::uint8_t { kBelow, kAboveSide, kBoth };
        auto side = [&s](const kd::Prim& p) {
            const float lo = p.box.lo[s.axis], hi = p.box.hi[s.axis];
            const bool planar = lo == s.position && hi == s.position;
            if (planar ? s.planar_left : hi <= s.position) return kBelow;
            if (planar || lo >= s.position) return kAboveSide;
            return kBoth;
        };
        // Counted first, so that each list is allocated once at its final size -- by the split finder
        // when it did (the SAH sweep: the pass over the primitives, streaming them from memory in a large
        // node, would cost about as much as the partition's own).
        std::size_t below = 0, above = 0;
        if (s.below >= 0 && s.above >= 0) {
            below = static_cast<std::size_t>(s.below);
            above = static_cast<std::size_t>(s.above);
        } else {
            std::size_t counts[3] = {0, 0, 0};
            for (const kd::Prim& p : prims) ++counts[side(p)];
            below = counts[kBelow] + counts[kBoth];
            above = counts[kAboveSide] + counts[kBoth];
        }
        Scratch& scratch = thread_scratch();
        scratch.moved.resize(prims.size());
        scratch.below_clipped.clear();
        scratch.above_clipped.clear();
        Partition part{{}, {}, scratch.moved, scratch.below_clipped, scratch.above_clipped};
        part.below.reserve(below);
        part.above.reserve(above);
        auto add = [](std::vector<kd::Prim>& list, const kd::Prim& p) {
            list.push_back(p);
            return static_cast<std::uint32_t>(list.size() - 1);
        };
        for (std::size_t i = 0; i < prims.size(); ++i) {
            const kd::Prim& p = prims[i];
            switch (side(p)) {
                case kBelow:
                    scratch.moved[i] = add(part.below, p);
                    break;
                case kAboveSide:
                    scratch.moved[i] = add(part.above, p) | kAbove;
                    break;
                case kBoth: {
                    scratch.moved[i] = kNone;
                    const AABB b = clip(p, below_box), a = clip(p, above_box);
                    if (!b.is_empty()) scratch.below_clipped.push_back(add(part.below, {p.index, b}));
                    if (!a.is_empty()) scratch.above_clipped.push_back(add(part.above, {p.index, a}));
                    break;
                }
            }
        }
        return part;
    }

    const KdBuildInput& m_input;
    Strategy m_strategy;
    int m_max_depth;
    NodeArena& m_arena;
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
                out.primitive_indices.insert(out.primitive_indices.end(), node.primitives.begin(),
                                             node.primitives.end());
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
        return cost.traversal() +
               (below_box.surface_area() * below_cost + above_box.surface_area() * above_cost) / area;
    }
};

}  // namespace

std::string_view kd_strategy_name(KdStrategy s) {
    switch (s) {
        case KdStrategy::sah:
            return "kd-sah";
        case KdStrategy::sah_binned:
            return "kd-sah-binned";
        case KdStrategy::sah_naive:
            return "kd-sah-naive";
        case KdStrategy::median:
            return "kd-median";
        case KdStrategy::midpoint:
            return "kd-midpoint";
    }
    return "?";
}

KdStrategy parse_kd_strategy(std::string_view name) {
    std::string known;
    for (KdStrategy s : kKdStrategies) {
        if (kd_strategy_name(s) == name) return s;
        known += (known.empty() ? "" : ", ") + std::string(kd_strategy_name(s));
    }
    throw Error("unknown kd-tree strategy '" + std::string(name) + "'; known: " + known);
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
    if (prims.size() >= kd::Event::kMaxSlots)
        throw Error("kd-tree: " + std::to_string(prims.size()) + " primitives; at most 2^30 are supported");
    if (strategy == KdStrategy::sah_naive && prims.size() > kNaiveWarnSize)
        out.stats.warnings.push_back("kd-sah-naive costs O(N^2) per node; " + std::to_string(prims.size()) +
                                     " primitives took a long time (kd-sah builds the same kind of tree fast)");
    // A safety cap only (pbrt's 8 + 1.3 log2 N); the cost model ends the SAH strategies well before it.
    const int max_depth =
        std::min(60, 8 + static_cast<int>(std::round(1.3 * std::log2(std::max<std::size_t>(prims.size(), 1)))));
    NodeArena arena;
    const BuildNode* root = nullptr;
    auto run = [&] {
        if (strategy == KdStrategy::sah)
            root = Builder(input, SahStrategy{cost}, max_depth, arena).build_root(std::move(prims), out.bounds);
        else
            root = Builder(input, PrimitiveStrategy{strategy, cost}, max_depth, arena)
                       .build_root(std::move(prims), out.bounds);
    };
    accel::run_on_threads(threads, run);

    // The flat arrays sized once from the build's nodes (node 1 is padding; a leaf of one primitive keeps
    // it in its node): grown by doubling, they were copied again and again into fresh memory, serially.
    std::size_t node_count = 1, index_count = 0;
    for (const std::deque<BuildNode>& nodes : arena)
        for (const BuildNode& node : nodes) {
            ++node_count;
            if (node.primitives.size() > 1) index_count += node.primitives.size();
        }
    out.nodes.reserve(node_count);
    out.primitive_indices.reserve(index_count);
    Flattener f{out, cost};
    out.stats.sah_cost = f.flatten_root(*root, out.bounds);
    out.max_depth = static_cast<int>(f.max_depth) + 1;
    out.stats.nodes = f.nodes;
    out.stats.leaves = f.leaves;
    out.stats.empty_leaves = f.empty_leaves;
    out.stats.max_depth = f.max_depth;
    const std::int64_t full = f.leaves - f.empty_leaves;
    out.stats.mean_leaf_primitives =
        full > 0 ? static_cast<double>(f.leaf_primitives) / static_cast<double>(full) : 0.0;
    out.stats.bytes = static_cast<std::int64_t>(out.nodes.size() * sizeof(KdNode) +
                                                out.primitive_indices.size() * sizeof(std::uint32_t));
    out.stats.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

}  // namespace rtlab
