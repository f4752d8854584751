#include <rtlab/core/error.hpp>
#include <rtlab/core/spelling.hpp>
#include <rtlab/geometry/instance.hpp>
#include <rtlab/render/ray_recorder.hpp>
#include <rtlab/render/sampled_lights.hpp>

#include <string>

namespace rtlab {

RayRecorder::RayRecorder(const AABB& bounds, std::size_t max_per_kind) : m_bounds(bounds), m_max(max_per_kind) {}

void RayRecorder::closest(const Ray& ray, bool hit, const Answer& answer) {
    const bool overlaps = m_bounds.intersect(ray).has_value();
    std::lock_guard lock(m_mutex);
    ++m_closest_answered;
    if (!overlaps) return;
    ++m_closest_overlapping;
    if (m_closest.size() >= m_max) return;
    m_closest.push_back(ray);
    m_answers.push_back(hit ? answer : Answer{kInfinity, kNoPrimitive});
}

void RayRecorder::shadow(const Ray& ray, bool blocked) {
    const bool overlaps = m_bounds.intersect(ray).has_value();
    std::lock_guard lock(m_mutex);
    ++m_shadow_answered;
    if (!overlaps) return;
    ++m_shadow_overlapping;
    if (m_shadow.size() >= m_max) return;
    m_shadow.push_back(ray);
    m_blocked.push_back(blocked ? 1 : 0);
}

RayRecorder::Counts RayRecorder::closest_counts() const {
    std::lock_guard lock(m_mutex);
    return {m_closest_answered, m_closest_overlapping, m_closest.size()};
}

RayRecorder::Counts RayRecorder::shadow_counts() const {
    std::lock_guard lock(m_mutex);
    return {m_shadow_answered, m_shadow_overlapping, m_shadow.size()};
}

namespace {

/// The decorator: every answer is the inner shape's, bit for bit; a hit names the decorator where the inner shape
/// named itself, so that the decorator stands in for it everywhere (an Instance above puts its own name anyway).
class RecordingShape final : public Shape {
public:
    RecordingShape(std::shared_ptr<const Shape> inner, std::shared_ptr<RayRecorder> recorder)
        : m_inner(std::move(inner)), m_recorder(std::move(recorder)) {}

    AABB bounds() const override { return m_inner->bounds(); }
    bool intersect(const Ray& ray, SurfaceHit& hit) const override {
        const bool found = m_inner->intersect(ray, hit);
        if (found) own(hit);
        m_recorder->closest(ray, found, {hit.t, hit.primitive});
        return found;
    }
    bool occluded(const Ray& ray) const override {
        const bool blocked = m_inner->occluded(ray);
        m_recorder->shadow(ray, blocked);
        return blocked;
    }
    bool defers_record() const override { return m_inner->defers_record(); }
    // The distance is the query; completing its record asks the inner shape again, which is not recorded.
    bool intersect_distance(const Ray& ray, float& t) const override {
        const bool found = m_inner->intersect_distance(ray, t);
        m_recorder->closest(ray, found, {t, kNoPrimitive});
        return found;
    }
    void complete_hit(const Ray& ray, float t, SurfaceHit& hit) const override {
        m_inner->complete_hit(ray, t, hit);
        own(hit);
    }
    void complete_hit_without_uv(const Ray& ray, float t, SurfaceHit& hit) const override {
        m_inner->complete_hit_without_uv(ray, t, hit);
        own(hit);
    }
    using Shape::uv_footprint;
    std::optional<UvFootprint> uv_footprint(const Mat4& to_world) const override {
        return m_inner->uv_footprint(to_world);
    }

private:
    void own(SurfaceHit& hit) const {
        if (hit.shape == m_inner.get()) hit.shape = this;
    }
    std::shared_ptr<const Shape> m_inner;
    std::shared_ptr<RayRecorder> m_recorder;
};

/// `shape` with its innermost shape (below every Instance) decorated; the Instances are made again with their
/// matrices, which gives them the same inverse and so the same rays.
std::shared_ptr<const Shape> decorate_innermost(const std::shared_ptr<const Shape>& shape, std::size_t max_per_kind,
                                                std::shared_ptr<RayRecorder>& recorder) {
    if (const auto* instance = dynamic_cast<const Instance*>(shape.get())) {
        // Shares the outer shape's ownership, which keeps the inner one alive.
        const std::shared_ptr<const Shape> inner(shape, &instance->shape());
        return std::make_shared<Instance>(decorate_innermost(inner, max_per_kind, recorder), instance->to_world());
    }
    recorder = std::make_shared<RayRecorder>(shape->bounds(), max_per_kind);
    return std::make_shared<RecordingShape>(shape, recorder);
}

}  // namespace

std::shared_ptr<RayRecorder> record_object_rays(std::vector<SceneObject>& objects, std::string_view name,
                                                std::size_t max_per_kind) {
    std::vector<std::string> names;
    for (SceneObject& object : objects) {
        if (object.name != name) {
            if (!object.name.empty()) names.push_back(object.name);
            continue;
        }
        if (make_area_emitter(object))
            throw Error("object '" + object.name +
                        "' emits light: its area light samples the shape itself, so it cannot be recorded");
        std::shared_ptr<RayRecorder> recorder;
        object.shape = decorate_innermost(object.shape, max_per_kind, recorder);
        return recorder;
    }
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
    throw Error("no object named '" + std::string(name) + "'" + did_you_mean(name, names) +
                " (objects: " + (list.empty() ? "none with a name" : list) + ")");
}

}  // namespace rtlab
