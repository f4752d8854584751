#include <rtlab/accel/kd_tree.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/geometry/quad.hpp>
#include <rtlab/geometry/sphere.hpp>
#include <rtlab/render/scene.hpp>

#include "flat_meshes.hpp"

#include <algorithm>
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
};

namespace {

bool same_bits(const Point3& a, const Point3& b) { return std::memcmp(&a, &b, sizeof(Point3)) == 0; }

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
        }
    }

    bool is_tree() const { return m_tree.has_value(); }
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

    bool occluded(const Ray& ray) const { return (m_flat && m_flat->occluded(ray)) || occluded_other(ray); }

    std::size_t bytes() const {
        const std::size_t flat = m_flat ? m_flat->bytes() : 0;
        if (!m_tree) return flat + m_list.capacity() * sizeof(SetMember);
        const KdTreeData& d = m_tree->data();
        return flat + m_tree->source().shapes.capacity() * sizeof(const Shape*) + d.nodes.capacity() * sizeof(KdNode) +
               d.primitive_indices.capacity() * sizeof(std::uint32_t);
    }

private:
    // closest() over the objects outside the flat tree, for hits before tmax.
    std::size_t closest_other(const Ray& ray, float tmax, SurfaceHit& hit, bool for_shading) const {
        Ray r = ray;
        r.tmax = tmax;
        if (m_tree) return m_tree->intersect(r, hit) ? kLookUp : kNone;
        // Shapes that defer their record only report distances; the one that stays nearest is completed at the
        // end, so a hit a closer one replaces costs no record.
        const SetMember* deferred = nullptr;
        const SetMember* found = nullptr;
        float alpha = 0.0f, beta = 0.0f;  // the deferred quad's plane coordinates
        Sphere::RayTerms terms;
        for (const SetMember& m : m_list) {
            float t;
            if (m.sphere) {
                if (!m.shares_centre) terms = m.sphere->ray_terms(r);
                if (!m.sphere->intersect_distance(r, terms, t)) continue;
                r.tmax = t;
                deferred = &m;
            } else if (m.quad) {
                float a, b;
                if (!m.quad->hit_params(r, t, a, b)) continue;
                r.tmax = t;
                alpha = a;
                beta = b;
                deferred = &m;
            } else if (m.defers) {
                if (!m.shape->intersect_distance(r, t)) continue;
                r.tmax = t;
                deferred = &m;
            } else {
                if (!m.shape->intersect(r, hit)) continue;
                r.tmax = hit.t;
                deferred = nullptr;
            }
            found = &m;
        }
        if (!found) return kNone;
        if (deferred) {
            if (deferred->quad)
                deferred->quad->fill_record(ray, r.tmax, alpha, beta, hit);
            else if (deferred->sphere && for_shading)
                deferred->sphere->complete_hit_for(ray, r.tmax, hit, deferred->reads_uv, deferred->reads_tangent);
            else if (for_shading && !deferred->reads_uv)
                deferred->shape->complete_hit_without_uv(ray, r.tmax, hit);
            else
                deferred->shape->complete_hit(ray, r.tmax, hit);
        }
        hit.shape = found->shape;
        return found->object;
    }

    bool occluded_other(const Ray& ray) const {
        if (m_tree) return m_tree->occluded(ray);
        Sphere::RayTerms terms;
        for (const SetMember& m : m_list) {
            float t, alpha, beta;
            if (m.sphere) {
                if (!m.shares_centre) terms = m.sphere->ray_terms(ray);
                if (m.sphere->intersect_distance(ray, terms, t)) return true;
            } else if (m.quad ? m.quad->hit_params(ray, t, alpha, beta) : m.shape->occluded(ray)) {
                return true;
            }
        }
        return false;
    }

    std::optional<FlatMeshes> m_flat;
    std::vector<SetMember> m_list;
    std::optional<KdTree<ObjectSource>> m_tree;
};

Scene::Scene(std::vector<SceneObject> objects, SceneOptions options) : m_objects(std::move(objects)) {
    std::vector<SetMember> all, opaque, transmissive;
    all.reserve(m_objects.size());
    m_index.reserve(m_objects.size());
    for (std::size_t i = 0; i < m_objects.size(); ++i) {
        const SceneObject& o = m_objects[i];
        if (!o.shape) throw Error("scene: " + object_label(o, i) + " has no shape");
        if (!o.material) throw Error("scene: " + object_label(o, i) + " has no material");
        const SetMember member{o.shape.get(),
                               i,
                               o.shape->defers_record(),
                               o.material->reads_lookup(),
                               o.material->reflects_direct_light(),
                               dynamic_cast<const Sphere*>(o.shape.get()),
                               dynamic_cast<const Quad*>(o.shape.get())};
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
    const std::size_t object = m_transmissive->closest(ray, hit, true);
    if (object == Set::kNone) return ShadowHit::clear;
    info = this->info(object, hit);
    return ShadowHit::transmissive;
}

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
