#include <rtlab/accel/kd_tree.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/render/scene.hpp>

#include <algorithm>
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

/// A plain list below the threshold, a kd-tree (SAH, the library's default cost model) from it.
class Scene::Set {
public:
    Set(std::vector<const Shape*> shapes, std::size_t threshold) {
        if (shapes.size() >= threshold && !shapes.empty())
            m_tree.emplace(ObjectSource{std::move(shapes)}, KdStrategy::sah);
        else {
            m_list = std::move(shapes);
            for (const Shape* s : m_list) m_defers.push_back(s->defers_record());
        }
    }

    bool is_tree() const { return m_tree.has_value(); }

    bool intersect(const Ray& ray, SurfaceHit& hit) const {
        if (m_tree) return m_tree->intersect(ray, hit);
        // Shapes that defer their record only report distances; the one that stays nearest is completed at the
        // end, so a hit a closer one replaces costs no record.
        Ray r = ray;
        const Shape* deferred = nullptr;
        const Shape* found = nullptr;
        for (std::size_t i = 0; i < m_list.size(); ++i) {
            const Shape* s = m_list[i];
            if (m_defers[i]) {
                float t;
                if (!s->intersect_distance(r, t)) continue;
                r.tmax = t;
                deferred = s;
            } else {
                if (!s->intersect(r, hit)) continue;
                r.tmax = hit.t;
                deferred = nullptr;
            }
            found = s;
        }
        if (deferred) deferred->complete_hit(ray, r.tmax, hit);
        if (found) hit.shape = found;
        return found != nullptr;
    }

    bool occluded(const Ray& ray) const {
        if (m_tree) return m_tree->occluded(ray);
        for (const Shape* s : m_list)
            if (s->occluded(ray)) return true;
        return false;
    }

    std::size_t bytes() const {
        if (!m_tree) return m_list.capacity() * sizeof(const Shape*);
        const KdTreeData& d = m_tree->data();
        return m_tree->source().shapes.capacity() * sizeof(const Shape*) + d.nodes.capacity() * sizeof(KdNode) +
               d.primitive_indices.capacity() * sizeof(std::uint32_t);
    }

private:
    std::vector<const Shape*> m_list;
    std::vector<char> m_defers;  // m_list[i]->defers_record(), asked once
    std::optional<KdTree<ObjectSource>> m_tree;
};

Scene::Scene(std::vector<SceneObject> objects, SceneOptions options) : m_objects(std::move(objects)) {
    std::vector<const Shape*> all, opaque, transmissive;
    all.reserve(m_objects.size());
    m_index.reserve(m_objects.size());
    for (std::size_t i = 0; i < m_objects.size(); ++i) {
        const SceneObject& o = m_objects[i];
        if (!o.shape) throw Error("scene: " + object_label(o, i) + " has no shape");
        if (!o.material) throw Error("scene: " + object_label(o, i) + " has no material");
        all.push_back(o.shape.get());
        m_index.emplace_back(o.shape.get(), i);
        m_bounds.expand(o.shape->bounds());
        if (!o.flags.casts_shadows) continue;
        (o.material->transmits_shadows() ? transmissive : opaque).push_back(o.shape.get());
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
    m_all = std::make_unique<Set>(std::move(all), options.tree_threshold);
    if (!m_opaque_is_all) m_opaque = std::make_unique<Set>(std::move(opaque), options.tree_threshold);
    m_transmissive = std::make_unique<Set>(std::move(transmissive), options.tree_threshold);
}

Scene::~Scene() = default;

bool Scene::intersect(const Ray& ray, SurfaceHit& hit) const { return m_all->intersect(ray, hit); }

bool Scene::occluded(const Ray& ray) const { return (m_opaque_is_all ? m_all : m_opaque)->occluded(ray); }

bool Scene::intersect_transmissive(const Ray& ray, SurfaceHit& hit) const {
    return m_transmissive->intersect(ray, hit);
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

std::size_t Scene::structure_bytes() const {
    std::size_t bytes = m_index.capacity() * sizeof(m_index[0]) + m_all->bytes() + m_transmissive->bytes();
    if (m_opaque) bytes += m_opaque->bytes();
    return bytes;
}

}  // namespace rtlab
