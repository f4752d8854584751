#include <rtlab/accel/mesh_shape.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/geometry/disk.hpp>
#include <rtlab/geometry/instance.hpp>
#include <rtlab/geometry/quad.hpp>
#include <rtlab/geometry/sphere.hpp>
#include <rtlab/render/sampled_lights.hpp>
#include <rtlab/textures/texture_param.hpp>

#include <cmath>
#include <optional>
#include <string>

namespace rtlab {

namespace {

// An `area` light's quad under the sampling integrators: it emits and reflects nothing.
class EmitterOnly final : public Material {
public:
    explicit EmitterOnly(Whitted whitted) : Material(std::move(whitted)) { local_terms_are_constant(); }
    RGB direct(const SurfaceTerms&, const Vec3&, const Vec3&, Convention) const override { return {}; }
    bool reflects_direct_light() const override { return false; }

protected:
    void local_terms(const TextureLookup&, SurfaceTerms&) const override {}
};

Point3 transform_point(const Mat4& m, const Point3& p) { return Point3(m * glm::vec4(p, 1.0f)); }

// The scale of a similarity (equal, orthogonal column lengths), or nullopt for another linear map.
std::optional<float> similarity_scale(const Mat4& m) {
    const Vec3 a(m[0]), b(m[1]), c(m[2]);
    const float la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
    const float tol = 1e-4f * la;
    if (std::abs(la - lb) > tol || std::abs(la - lc) > tol) return std::nullopt;
    if (std::abs(glm::dot(a, b)) > tol * la || std::abs(glm::dot(a, c)) > tol * la ||
        std::abs(glm::dot(b, c)) > tol * la)
        return std::nullopt;
    return la;
}

void add_triangles(EmitterShape& out, const std::array<Point3, 3>& t, const Mat4& m, bool flip) {
    std::array<Point3, 3> w{transform_point(m, t[0]), transform_point(m, t[1]), transform_point(m, t[2])};
    if (flip) std::swap(w[1], w[2]);
    out.triangles.push_back(w);
}

// The emitting surface of `shape` placed by `m`; flip when the shape's outside is to be the back (a mirroring
// matrix or the reversed flag). nullopt for a shape without a sampler.
std::optional<EmitterShape> emitter_shape(const Shape& shape, const Mat4& m, bool flip) {
    EmitterShape out;
    if (const auto* q = dynamic_cast<const Quad*>(&shape)) {
        const Point3 c = q->corner();
        add_triangles(out, {c, c + q->edge_u(), c + q->edge_u() + q->edge_v()}, m, flip);
        add_triangles(out, {c, c + q->edge_u() + q->edge_v(), c + q->edge_v()}, m, flip);
        return out;
    }
    if (const auto* mesh = dynamic_cast<const MeshShape*>(&shape)) {
        const TriangleMesh& tm = mesh->mesh();
        out.triangles.reserve(tm.triangle_count());
        for (std::size_t i = 0; i < tm.triangle_count(); ++i)
            if (!tm.is_degenerate(i)) add_triangles(out, {tm.corner(i, 0), tm.corner(i, 1), tm.corner(i, 2)}, m, flip);
        return out;
    }
    if (const auto* inst = dynamic_cast<const Instance*>(&shape)) {
        const Mat4 to_world = m * inst->to_world();
        const bool mirrors = glm::determinant(Mat3(inst->to_world())) < 0.0f;
        return emitter_shape(inst->shape(), to_world, flip != mirrors);
    }
    const std::optional<float> scale = similarity_scale(m);
    if (!scale) return std::nullopt;
    if (const auto* d = dynamic_cast<const Disk*>(&shape)) {
        out.kind = EmitterShape::Kind::disk;
        out.centre = transform_point(m, d->centre());
        Normal3 n = glm::normalize(Mat3(m) * d->normal());  // a similarity keeps normals
        if (glm::determinant(Mat3(m)) < 0.0f) n = -n;       // a mirror turns the outside over with the orientation
        out.normal = flip ? -n : n;
        out.radius = d->radius() * *scale;
        out.inner_radius = d->inner_radius() * *scale;
        return out;
    }
    if (const auto* s = dynamic_cast<const Sphere*>(&shape)) {
        out.kind = EmitterShape::Kind::sphere;
        out.centre = transform_point(m, s->centre());
        out.radius = s->radius() * *scale;
        out.inward = flip;
        return out;
    }
    return std::nullopt;
}

}  // namespace

std::shared_ptr<const AreaEmitter> make_area_emitter(const SceneObject& object) {
    const auto& emission = object.material->emission();
    const RGB* radiance = emission ? emission->constant() : nullptr;
    if (!radiance || radiance->is_black()) return nullptr;
    std::optional<EmitterShape> shape = emitter_shape(*object.shape, Mat4(1.0f), object.flags.reversed);
    if (!shape) return nullptr;
    return std::make_shared<AreaEmitter>(std::move(*shape), *radiance, object.material->emission_two_sided());
}

SampledLights make_sampled_lights(std::shared_ptr<const Scene> scene,
                                  const std::vector<std::shared_ptr<const Light>>& lights,
                                  const WhittedOptions& whitted,
                                  std::shared_ptr<const EnvironmentEmitter> environment) {
    if (!scene) throw Error("sampled lights: no scene");
    if (whitted.convention == Convention::classic)
        throw Error("convention: 'classic' is not physical; the direct and path integrators need 'physical'");
    SampledLights out;
    std::vector<SceneObject> quads;
    const float radius = scene->bounds().is_empty() ? 1.0f : 0.5f * scene->bounds().diagonal();
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const auto& light = lights[i];
        if (!light) throw Error("sampled lights: light " + std::to_string(i) + " is null");
        if (!light->ambient().is_black())
            throw Error("light " + std::to_string(i) +
                        ": an 'ambient' light is not physical; the direct and path integrators cannot use it");
        if (const std::optional<EmittingQuad> q = light->emitting_quad()) {
            Material::Whitted w;
            w.emission = make_constant_texture(q->radiance);
            w.emission_two_sided = q->two_sided;
            SceneObject object;
            object.shape = std::make_shared<Quad>(q->corner, q->edge_u, q->edge_v);
            object.material = std::make_shared<EmitterOnly>(std::move(w));
            object.name = "area light " + std::to_string(i);
            quads.push_back(std::move(object));
        } else if (light->is_delta()) {
            out.lights.add(std::make_shared<DeltaEmitter>(light, radius));
        } else {
            throw Error("light " + std::to_string(i) + ": not a light the direct and path integrators can sample");
        }
    }
    if (!quads.empty()) {
        std::vector<SceneObject> objects = scene->objects();
        for (auto& q : quads) objects.push_back(std::move(q));
        scene = std::make_shared<const Scene>(std::move(objects));
    }
    for (const SceneObject& object : scene->objects())
        if (auto emitter = make_area_emitter(object)) out.lights.add(std::move(emitter), object.shape.get());
    if (environment)
        out.lights.set_environment(environment->for_scene_radius(radius));
    else if (!whitted.environment && !whitted.background.is_black())
        out.lights.set_environment(std::make_shared<UniformEnvironment>(whitted.background, radius));
    out.lights.finish();
    out.sphere = SceneSphere{scene->bounds().is_empty() ? Point3(0.0f) : scene->bounds().center(), radius};
    out.scene = std::move(scene);
    return out;
}

}  // namespace rtlab
