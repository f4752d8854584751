#include <rtlab/core/error.hpp>
#include <rtlab/shading/scene_query.hpp>

namespace rtlab {

std::size_t ShapeList::add(std::shared_ptr<const Shape> shape, std::shared_ptr<const Material> material,
                           SurfaceFlags flags) {
    if (!shape) throw Error("shape list: object " + std::to_string(m_entries.size()) + " has no shape");
    if (!material) throw Error("shape list: object " + std::to_string(m_entries.size()) + " has no material");
    const std::size_t index = m_entries.size();
    if (!m_index.emplace(shape.get(), index).second)
        throw Error("shape list: object " + std::to_string(index) + " repeats the shape of object " +
                    std::to_string(m_index.at(shape.get())) + " (use an Instance to show a shape twice)");
    m_entries.push_back({std::move(shape), std::move(material), flags});
    return index;
}

bool ShapeList::closest(const Ray& ray, SurfaceHit& hit, Filter filter) const {
    Ray r = ray;
    bool found = false;
    for (const Entry& e : m_entries) {
        if (filter == Filter::transmissive && !(e.flags.casts_shadows && e.material->transmits_shadows())) continue;
        if (e.shape->intersect(r, hit)) {
            found = true;
            r.tmax = hit.t;  // hit.shape is e.shape: every shape, an Instance included, reports itself
        }
    }
    return found;
}

bool ShapeList::intersect(const Ray& ray, SurfaceHit& hit) const { return closest(ray, hit, Filter::all); }

bool ShapeList::intersect_transmissive(const Ray& ray, SurfaceHit& hit) const {
    return closest(ray, hit, Filter::transmissive);
}

bool ShapeList::occluded(const Ray& ray) const {
    for (const Entry& e : m_entries)
        if (e.flags.casts_shadows && !e.material->transmits_shadows() && e.shape->occluded(ray)) return true;
    return false;
}

SurfaceInfo ShapeList::surface(const SurfaceHit& hit) const {
    const auto it = m_index.find(hit.shape);
    if (it == m_index.end()) throw Error("shape list: a hit on a shape that is not in the list");
    const Entry& e = m_entries[it->second];
    return {e.material.get(), e.flags};
}

}  // namespace rtlab
