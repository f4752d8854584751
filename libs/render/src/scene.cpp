#include <rtlab/accel/kd_tree.hpp>
#include <rtlab/accel/mesh_shape.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/geometry/instance.hpp>
#include <rtlab/geometry/mesh_surface.hpp>
#include <rtlab/geometry/quad.hpp>
#include <rtlab/geometry/sphere.hpp>
#include <rtlab/render/scene.hpp>

#include "flat_meshes.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <optional>

namespace rtlab {

namespace {

/// The objects of one set as kd-tree primitives. A hit reports the object's own shape, whatever the shape
/// itself put there, so surface() finds the object even for shapes that report an inner shape.
struct ObjectSource {
    using Hit = SurfaceHit;
    std::vector<const Shape*> shapes;

    std::size_t size() const { return shapes.size(); }
    AABB bounds(std::uint32_t i) const { return shapes[i]->bounds(); }
    bool intersect(std::uint32_t i, const Ray& ray, SurfaceHit& hit) const {
        if (!shapes[i]->intersect(ray, hit)) return false;
        hit.shape = shapes[i];
        return true;
    }
    bool occluded(std::uint32_t i, const Ray& ray) const { return shapes[i]->occluded(ray); }
};

std::string object_label(const SceneObject& o, std::size_t i) {
    return o.name.empty() ? "object " + std::to_string(i) : "object " + std::to_string(i) + " ('" + o.name + "')";
}

}  // namespace

/// Instances around a mesh that a set's walk goes through itself; a deeper nest is asked through its virtual calls.
inline constexpr std::size_t kMaxPlacements = 4;

/// One object of a set.
struct SetMember {
    const Shape* shape;
    std::size_t object;    // index into the scene's objects
    bool defers;           // shape->defers_record(), asked once
    bool reads_uv = true;  // the object's material reads its lookup: shading needs the hit's uv
    // The object's material reflects direct light: shading builds its frame from the hit's tangent.
    bool reads_tangent = true;
    // The shape when it is a Sphere: its distance and shadow tests are inline, so the walk runs them without a
    // virtual call (rtlab-whitted: the list walks and sphere tests took 18% fewer instructions so).
    const Sphere* sphere = nullptr;
    // The shape when it is a Quad: tested inline too, and its record filled only if it stays the nearest hit.
    const Quad* quad = nullptr;
    // A sphere with the very centre of the member before it in its set: it reuses that sphere's ray terms.
    bool shares_centre = false;
    // The shape when it is a MeshShape, or the MeshShape inside it when it is Instances of one (placed[0] the shape,
    // each next one inside the one before; a mesh with "fit" and a "transform" is two): single rays go through its
    // accelerator from the walk, with no virtual call through the shapes, and its record is filled only if it stays
    // the nearest hit.
    const MeshShape* traced = nullptr;
    std::array<const Instance*, kMaxPlacements> placed{};
    std::size_t placements = 0;
    // `traced` sits in at most one Instance and its accelerator's packets give its single rays' answers: packets of
    // rays go through it together.
    bool packets = false;
};

/// Rays a scene's packet queries hand to the structures at once (a group of more is taken in such chunks).
inline constexpr std::size_t kPacketChunk = 16;

namespace {

bool same_bits(const Point3& a, const Point3& b) { return std::memcmp(&a, &b, sizeof(Point3)) == 0; }

/// Where one ray's walk over a list stands: the ray with tmax at the nearest hit so far, and whose hit that is.
struct ListWalk {
    Ray r;
    const SetMember* deferred = nullptr;  // the nearest member when its record is still to be filled
    const SetMember* found = nullptr;
    float alpha = 0.0f, beta = 0.0f;  // the deferred quad's plane coordinates
    MeshHit triangle;                 // the deferred mesh's hit
};

/// True when the mesh's accelerator's packets give its single rays' answers bit for bit: the kd-trees' (Embree's
/// rtcIntersect8 may differ from rtcIntersect1 in the last bits of t).
bool packets_as_single_rays(const MeshShape& mesh) {
    static const std::vector<std::string> kd = kd_tree_methods();
    return std::find(kd.begin(), kd.end(), mesh.accelerator().name()) != kd.end();
}

}  // namespace

/// The small meshes of the set in one flat triangle tree (when there are two or more), and the other objects in a
/// plain list below the threshold, a kd-tree (SAH, the library's default cost model) from it.
class Scene::Set {
public:
    /// closest(): no hit; a hit the tree found, whose object the caller looks up by shape.
    static constexpr std::size_t kNone = SIZE_MAX, kLookUp = SIZE_MAX - 1;

    Set(std::vector<SetMember> members, const SceneOptions& options) {
        std::vector<FlatMeshes::Part> parts;
        for (const SetMember& m : members)
            if (const MeshShape* mesh = FlatMeshes::joinable(*m.shape, options.flat_mesh_triangles))
                parts.push_back({mesh, m.object});
        if (parts.size() >= 2) {
            m_flat.emplace(std::move(parts));
            std::erase_if(members, [&](const SetMember& m) {
                return FlatMeshes::joinable(*m.shape, options.flat_mesh_triangles) != nullptr;
            });
        }
        const std::size_t threshold = options.tree_threshold;
        if (members.size() >= threshold && !members.empty()) {
            std::vector<const Shape*> shapes;
            shapes.reserve(members.size());
            for (const SetMember& m : members) shapes.push_back(m.shape);
            m_tree.emplace(ObjectSource{std::move(shapes)}, KdStrategy::sah);
        } else {
            m_list = std::move(members);
            for (std::size_t i = 1; i < m_list.size(); ++i) {
                const Sphere* prev = m_list[i - 1].sphere;
                m_list[i].shares_centre =
                    m_list[i].sphere && prev && same_bits(prev->centre(), m_list[i].sphere->centre());
            }
            m_packet_members = std::any_of(m_list.begin(), m_list.end(), [](const SetMember& m) { return m.packets; });
        }
    }

    bool is_tree() const { return m_tree.has_value(); }
    bool empty() const { return !m_flat && !m_tree && m_list.empty(); }
    bool traces_packets() const { return m_flat || m_packet_members; }
    std::size_t flat_meshes() const { return m_flat ? m_flat->part_count() : 0; }

    /// The closest hit's object index, kLookUp for a tree's hit or kNone. for_shading: the record may leave
    /// out the uv where the object's material does not read it.
    std::size_t closest(const Ray& ray, SurfaceHit& hit, bool for_shading) const {
        if (!m_flat) return closest_other(ray, ray.tmax, hit, for_shading);
        // The flat tree first: its hit bounds the other objects' search, and its record is filled only if none
        // of them is nearer (a tie stays with the flat tree's triangle).
        MeshHit found;
        if (!m_flat->intersect(ray, found)) return closest_other(ray, ray.tmax, hit, for_shading);
        const std::size_t other = closest_other(ray, found.t, hit, for_shading);
        return other != kNone ? other : m_flat->complete(ray, found, hit);
    }

    // The other objects first: the flat tree's small meshes are mostly a room's walls, which seldom block a shadow
    // ray inside it (cornell_box_bunny: the bunny blocks, the box never does).
    bool occluded(const Ray& ray) const { return occluded_other(ray) || (m_flat && m_flat->occluded(ray)); }

    /// closest() of up to kPacketChunk rays: the flat tree and the list's meshes trace them together, every other
    /// member one ray at a time, each ray meeting the members in closest()'s order with closest()'s tmax.
    void closest_packet(std::span<const Ray> rays, std::span<SurfaceHit> hits, std::span<std::size_t> objects,
                        bool for_shading) const {
        const std::size_t n = rays.size();
        if (!m_flat && !m_packet_members) {
            for (std::size_t i = 0; i < n; ++i) objects[i] = closest(rays[i], hits[i], for_shading);
            return;
        }
        std::array<MeshHit, kPacketChunk> flat;
        if (m_flat) m_flat->intersect_packet(rays, std::span<MeshHit>(flat.data(), n));
        std::array<ListWalk, kPacketChunk> walks;
        for (std::size_t i = 0; i < n; ++i) {
            walks[i].r = rays[i];
            if (flat[i].hit()) walks[i].r.tmax = flat[i].t;
        }
        if (m_tree) {
            for (std::size_t i = 0; i < n; ++i) objects[i] = m_tree->intersect(walks[i].r, hits[i]) ? kLookUp : kNone;
        } else {
            // A run starts with no sphere before it, so none of its members shares ray terms across a mesh.
            for_each_run(
                [&](std::size_t begin, std::size_t end) {
                    for (std::size_t i = 0; i < n; ++i) {
                        Sphere::RayTerms terms;
                        for (std::size_t j = begin; j < end; ++j) step(m_list[j], walks[i], terms, hits[i]);
                    }
                },
                [&](const SetMember& m) { mesh_packet(m, std::span<ListWalk>(walks.data(), n)); });
            for (std::size_t i = 0; i < n; ++i) objects[i] = finish(rays[i], walks[i], hits[i], for_shading);
        }
        for (std::size_t i = 0; i < n; ++i)
            if (objects[i] == kNone && flat[i].hit()) objects[i] = m_flat->complete(rays[i], flat[i], hits[i]);
    }

    /// occluded() of up to kPacketChunk rays: the same answers (whether anything blocks does not depend on the
    /// order the members are asked in), the flat tree and the list's meshes tracing the rays together.
    void occluded_packet(std::span<const Ray> rays, std::span<std::uint8_t> blocked) const {
        const std::size_t n = rays.size();
        if (!m_flat && !m_packet_members) {
            for (std::size_t i = 0; i < n; ++i) blocked[i] = occluded(rays[i]) ? 1 : 0;
            return;
        }
        if (m_flat)
            m_flat->occluded_packet(rays, blocked);
        else
            std::fill_n(blocked.begin(), n, std::uint8_t{0});
        if (m_tree) {
            for (std::size_t i = 0; i < n; ++i)
                if (!blocked[i]) blocked[i] = m_tree->occluded(rays[i]) ? 1 : 0;
            return;
        }
        for_each_run(
            [&](std::size_t begin, std::size_t end) {
                for (std::size_t i = 0; i < n; ++i)
                    if (!blocked[i]) blocked[i] = occluded_range(rays[i], begin, end) ? 1 : 0;
            },
            [&](const SetMember& m) {
                // The rays still open, in their order, through the mesh's accelerator.
                std::array<Ray, kPacketChunk> open;
                std::array<std::uint8_t, kPacketChunk> index, hit;
                std::size_t count = 0;
                for (std::size_t i = 0; i < n; ++i) {
                    if (blocked[i]) continue;
                    open[count] = packet_ray(m, rays[i]);
                    index[count++] = static_cast<std::uint8_t>(i);
                }
                if (count > 0)
                    m.traced->accelerator().occluded_packet(std::span<const Ray>(open.data(), count),
                                                            std::span<std::uint8_t>(hit.data(), count));
                for (std::size_t c = 0; c < count; ++c) blocked[index[c]] = hit[c];
            });
    }

    std::size_t bytes() const {
        const std::size_t flat = m_flat ? m_flat->bytes() : 0;
        if (!m_tree) return flat + m_list.capacity() * sizeof(SetMember);
        const KdTreeData& d = m_tree->data();
        return flat + m_tree->source().shapes.capacity() * sizeof(const Shape*) + d.nodes.capacity() * sizeof(KdNode) +
               d.primitive_indices.capacity() * sizeof(std::uint32_t);
    }

private:
    // The list in order as runs of single-ray members, each handed to run(begin, end) as the index range [begin,
    // end), and the mesh members between them, each handed to mesh(member): the packet queries trace the runs one
    // ray at a time and the meshes with all rays together.
    template <class Run, class Mesh>
    void for_each_run(Run&& run, Mesh&& mesh) const {
        std::size_t begin = 0;
        for (std::size_t k = 0; k <= m_list.size(); ++k) {
            if (k < m_list.size() && !m_list[k].packets) continue;
            if (begin < k) run(begin, k);
            if (k < m_list.size()) mesh(m_list[k]);
            begin = k + 1;
        }
    }

    // closest() over the objects outside the flat tree, for hits before tmax.
    std::size_t closest_other(const Ray& ray, float tmax, SurfaceHit& hit, bool for_shading) const {
        ListWalk w;
        w.r = ray;
        w.r.tmax = tmax;
        if (m_tree) return m_tree->intersect(w.r, hit) ? kLookUp : kNone;
        Sphere::RayTerms terms;
        for (const SetMember& m : m_list) step(m, w, terms, hit);
        return finish(ray, w, hit, for_shading);
    }

    // One member of the list for one ray. Shapes that defer their record only report distances; the one that stays
    // nearest is completed at the end (finish), so a hit a closer one replaces costs no record.
    static void step(const SetMember& m, ListWalk& w, Sphere::RayTerms& terms, SurfaceHit& hit) {
        float t;
        if (m.sphere) {
            if (!m.shares_centre) terms = m.sphere->ray_terms(w.r);
            if (!m.sphere->intersect_distance(w.r, terms, t)) return;
            w.r.tmax = t;
            w.deferred = &m;
        } else if (m.quad) {
            float a, b;
            if (!m.quad->hit_params(w.r, t, a, b)) return;
            w.r.tmax = t;
            w.alpha = a;
            w.beta = b;
            w.deferred = &m;
        } else if (m.traced) {
            // Every Instance's guard. Tried: the outer one's alone (cornell_box_bunny, callgrind): 25% more of the
            // bunny's closest-hit rays and 53% more of its shadow rays walked its tree (the outer box holds the inner
            // one turned by 200 degrees), +0.28 M walk instructions against -0.40 M guard ones; kept, as a walk's
            // cache misses and mispredicts cost more than its instructions say (not timed).
            Ray r = w.r;
            MeshHit found;
            if (!to_traced_space(m, r) || !m.traced->accelerator().intersect(r, found)) return;
            w.r.tmax = found.t;
            w.triangle = found;
            w.deferred = &m;
        } else if (m.defers) {
            if (!m.shape->intersect_distance(w.r, t)) return;
            w.r.tmax = t;
            w.deferred = &m;
        } else {
            if (!m.shape->intersect(w.r, hit)) return;
            w.r.tmax = hit.t;
            w.deferred = nullptr;
        }
        w.found = &m;
    }

    // The ray in the space of m's traced mesh, through each Instance in turn; false when it passes clear of one's
    // bounds, and so misses the mesh.
    static bool to_traced_space(const SetMember& m, Ray& r) {
        for (std::size_t k = 0; k < m.placements; ++k) {
            if (m.placed[k]->misses_bounds(r)) return false;
            r = m.placed[k]->to_object(r);
        }
        return true;
    }

    // The ray a packet member's accelerator answers (no bounds guard: the rays of a packet go in together).
    static Ray packet_ray(const SetMember& m, const Ray& r) { return m.placements ? m.placed[0]->to_object(r) : r; }

    // step() of a packet member for a group of rays, through its accelerator's packets: each ray asks with
    // the tmax its walk has reached; finish() fills the record MeshShape::intersect() (through the Instance) fills.
    static void mesh_packet(const SetMember& m, std::span<ListWalk> walks) {
        const std::size_t n = walks.size();
        std::array<Ray, kPacketChunk> rays;
        std::array<MeshHit, kPacketChunk> found;
        for (std::size_t i = 0; i < n; ++i) rays[i] = packet_ray(m, walks[i].r);
        m.traced->accelerator().intersect_packet(std::span<const Ray>(rays.data(), n),
                                                 std::span<MeshHit>(found.data(), n));
        // Deferred as step() defers a mesh's hit: a nearer sphere that leaves out its uv or tangent must leave the
        // same bits there as the single query's.
        for (std::size_t i = 0; i < n; ++i) {
            if (!found[i].hit()) continue;
            ListWalk& w = walks[i];
            w.r.tmax = found[i].t;
            w.triangle = found[i];
            w.deferred = &m;
            w.found = &m;
        }
    }

    // The record of the member a walk found, and its object (kNone when it found none).
    static std::size_t finish(const Ray& ray, const ListWalk& w, SurfaceHit& hit, bool for_shading) {
        if (!w.found) return kNone;
        if (const SetMember* deferred = w.deferred) {
            if (deferred->quad)
                deferred->quad->fill_record(ray, w.r.tmax, w.alpha, w.beta, hit);
            else if (deferred->traced)
                fill_traced(*deferred, ray, w.triangle, hit);
            else if (deferred->sphere && for_shading)
                deferred->sphere->complete_hit_for(ray, w.r.tmax, hit, deferred->reads_uv, deferred->reads_tangent);
            else if (for_shading && !deferred->reads_uv)
                deferred->shape->complete_hit_without_uv(ray, w.r.tmax, hit);
            else
                deferred->shape->complete_hit(ray, w.r.tmax, hit);
        }
        hit.shape = w.found->shape;
        return w.found->object;
    }

    // The record MeshShape::intersect() (through the Instances) fills for a hit its accelerator found.
    static void fill_traced(const SetMember& m, const Ray& ray, const MeshHit& f, SurfaceHit& hit) {
        if (m.placements == 0) {
            fill_mesh_hit(m.traced->mesh(), f.primitive, ray, f.t, f.u, f.v, m.traced, hit);
            return;
        }
        // The ray as each Instance receives it, outermost first, and the record each one makes of the next's.
        std::array<Ray, kMaxPlacements + 1> rays;
        rays[0] = ray;
        for (std::size_t k = 0; k < m.placements; ++k) rays[k + 1] = m.placed[k]->to_object(rays[k]);
        SurfaceHit inner, outer;
        fill_mesh_hit(m.traced->mesh(), f.primitive, rays[m.placements], f.t, f.u, f.v, m.traced, inner);
        for (std::size_t k = m.placements; k-- > 1;) {
            m.placed[k]->finish_hit(rays[k], inner, outer);
            inner = outer;
        }
        m.placed[0]->finish_hit(ray, inner, hit);
    }

    bool occluded_other(const Ray& ray) const {
        if (m_tree) return m_tree->occluded(ray);
        return occluded_range(ray, 0, m_list.size());
    }

    // occluded() over the list's members [begin, end).
    bool occluded_range(const Ray& ray, std::size_t begin, std::size_t end) const {
        Sphere::RayTerms terms;
        for (std::size_t i = begin; i < end; ++i) {
            const SetMember& m = m_list[i];
            float t, alpha, beta;
            if (m.sphere) {
                if (!m.shares_centre) terms = m.sphere->ray_terms(ray);
                if (m.sphere->intersect_distance(ray, terms, t)) return true;
            } else if (m.traced) {
                Ray r = ray;
                if (to_traced_space(m, r) && m.traced->accelerator().occluded(r)) return true;
            } else if (m.quad ? m.quad->hit_params(ray, t, alpha, beta) : m.shape->occluded(ray)) {
                return true;
            }
        }
        return false;
    }

    std::optional<FlatMeshes> m_flat;
    std::vector<SetMember> m_list;
    std::optional<KdTree<ObjectSource>> m_tree;
    bool m_packet_members = false;  // the list holds a mesh member
};

Scene::Scene(std::vector<SceneObject> objects, SceneOptions options) : m_objects(std::move(objects)) {
    std::vector<SetMember> all, opaque, transmissive;
    all.reserve(m_objects.size());
    m_index.reserve(m_objects.size());
    for (std::size_t i = 0; i < m_objects.size(); ++i) {
        const SceneObject& o = m_objects[i];
        if (!o.shape) throw Error("scene: " + object_label(o, i) + " has no shape");
        if (!o.material) throw Error("scene: " + object_label(o, i) + " has no material");
        SetMember member{o.shape.get(),
                         i,
                         o.shape->defers_record(),
                         o.material->reads_lookup(),
                         o.material->reflects_direct_light(),
                         dynamic_cast<const Sphere*>(o.shape.get()),
                         dynamic_cast<const Quad*>(o.shape.get())};
        const Shape* inner = o.shape.get();
        while (const auto* instance = dynamic_cast<const Instance*>(inner)) {
            if (member.placements == kMaxPlacements) break;
            member.placed[member.placements++] = instance;
            inner = &instance->shape();
        }
        member.traced = dynamic_cast<const MeshShape*>(inner);
        if (!member.traced) member.placements = 0;
        member.packets = member.traced && member.placements <= 1 && packets_as_single_rays(*member.traced);
        all.push_back(member);
        m_index.emplace_back(o.shape.get(), i);
        m_bounds.expand(o.shape->bounds());
        if (!o.flags.casts_shadows) continue;
        (o.material->transmits_shadows() ? transmissive : opaque).push_back(member);
    }
    std::sort(m_index.begin(), m_index.end());
    const auto repeated = std::adjacent_find(m_index.begin(), m_index.end(),
                                             [](const auto& a, const auto& b) { return a.first == b.first; });
    if (repeated != m_index.end()) {
        const std::size_t a = std::min(repeated->second, std::next(repeated)->second);
        const std::size_t b = std::max(repeated->second, std::next(repeated)->second);
        throw Error("scene: " + object_label(m_objects[b], b) + " repeats the shape of " +
                    object_label(m_objects[a], a) + " (show one shape twice through instances)");
    }

    m_opaque_is_all = opaque.size() == all.size();
    m_all = std::make_unique<Set>(std::move(all), options);
    if (!m_opaque_is_all) m_opaque = std::make_unique<Set>(std::move(opaque), options);
    m_transmissive = std::make_unique<Set>(std::move(transmissive), options);
}

Scene::~Scene() = default;

bool Scene::intersect(const Ray& ray, SurfaceHit& hit) const { return m_all->closest(ray, hit, false) != Set::kNone; }

bool Scene::occluded(const Ray& ray) const { return (m_opaque_is_all ? m_all : m_opaque)->occluded(ray); }

bool Scene::intersect_transmissive(const Ray& ray, SurfaceHit& hit) const {
    return m_transmissive->closest(ray, hit, false) != Set::kNone;
}

SurfaceInfo Scene::info(std::size_t object, const SurfaceHit& hit) const {
    if (object == Set::kLookUp) return surface(hit);
    const SceneObject& o = m_objects[object];
    return {o.material.get(), o.flags};
}

bool Scene::intersect_surface(const Ray& ray, SurfaceHit& hit, SurfaceInfo& info) const {
    const std::size_t object = m_all->closest(ray, hit, true);
    if (object == Set::kNone) return false;
    info = this->info(object, hit);
    return true;
}

ShadowHit Scene::shadow(const Ray& ray, bool check_opaque, SurfaceHit& hit, SurfaceInfo& info) const {
    if (check_opaque && occluded(ray)) return ShadowHit::opaque;
    // Most scenes have no transmissive caster: no walk set up for nothing (cornell_box_bunny: 36 instructions a
    // shadow ray).
    if (m_transmissive->empty()) return ShadowHit::clear;
    const std::size_t object = m_transmissive->closest(ray, hit, true);
    if (object == Set::kNone) return ShadowHit::clear;
    info = this->info(object, hit);
    return ShadowHit::transmissive;
}

void Scene::intersect_surface_packet(std::span<const Ray> rays, std::span<SurfaceHit> hits,
                                     std::span<SurfaceInfo> infos, std::span<std::uint8_t> found) const {
    std::array<std::size_t, kPacketChunk> objects;
    for (std::size_t first = 0; first < rays.size(); first += kPacketChunk) {
        const std::size_t n = std::min(kPacketChunk, rays.size() - first);
        m_all->closest_packet(rays.subspan(first, n), hits.subspan(first, n), std::span<std::size_t>(objects.data(), n),
                              true);
        for (std::size_t i = 0; i < n; ++i) {
            found[first + i] = objects[i] != Set::kNone ? 1 : 0;
            if (objects[i] != Set::kNone) infos[first + i] = info(objects[i], hits[first + i]);
        }
    }
}

void Scene::occluded_packet(std::span<const Ray> rays, std::span<std::uint8_t> blocked) const {
    const Set& set = m_opaque_is_all ? *m_all : *m_opaque;
    for (std::size_t first = 0; first < rays.size(); first += kPacketChunk) {
        const std::size_t n = std::min(kPacketChunk, rays.size() - first);
        set.occluded_packet(rays.subspan(first, n), blocked.subspan(first, n));
    }
}

// The opaque and transmissive sets hold some of m_all's members: none has packets where m_all has none.
bool Scene::traces_packets() const { return m_all->traces_packets(); }

SurfaceInfo Scene::surface(const SurfaceHit& hit) const {
    const auto it = std::lower_bound(m_index.begin(), m_index.end(), hit.shape,
                                     [](const auto& entry, const Shape* s) { return entry.first < s; });
    if (it == m_index.end() || it->first != hit.shape)
        throw Error("scene: a hit on a shape that is not one of the scene's objects");
    const SceneObject& o = m_objects[it->second];
    return {o.material.get(), o.flags};
}

std::string_view Scene::structure() const { return m_all->is_tree() ? "kd-tree" : "list"; }

std::size_t Scene::flat_meshes() const { return m_all->flat_meshes(); }

std::size_t Scene::structure_bytes() const {
    std::size_t bytes = m_index.capacity() * sizeof(m_index[0]) + m_all->bytes() + m_transmissive->bytes();
    if (m_opaque) bytes += m_opaque->bytes();
    return bytes;
}

}  // namespace rtlab
