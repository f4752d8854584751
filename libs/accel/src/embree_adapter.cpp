// Embree 3 as a reference backend (libembree-dev, optional). Debian's libembree3 is built with
// assertions, so rays Embree would reject (NaN or infinite components, a zero direction,
// tmin > tmax, huge coordinates) are answered here as misses and never handed over.
#include "baselines.hpp"

#ifdef RTLAB_HAVE_EMBREE
#include <rtlab/core/error.hpp>

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

namespace rtlab::accel {

namespace {

/// \brief The bytes an Embree device holds, as its memory monitor reports them: Embree calls it for the
/// blocks it allocates and frees itself (geometry buffers it owns, the build's primitive arrays, the tree's
/// node and leaf blocks -- whole blocks, so a partly used one counts in full), not for small objects or the
/// thread pool. Called from Embree's build threads, hence atomics.
struct EmbreeMemoryCount {
    std::atomic<std::int64_t> current{0};
    std::atomic<std::int64_t> peak{0};

    static bool monitor(void* self, ssize_t bytes, bool post) {
        // Allocations are reported before they happen (post = false), frees after (post = true); each once.
        auto& count = *static_cast<EmbreeMemoryCount*>(self);
        const std::int64_t now = count.current.fetch_add(bytes) + bytes;
        std::int64_t peak = count.peak.load();
        while (now > peak && !count.peak.compare_exchange_weak(peak, now)) {
        }
        static_cast<void>(post);
        return true;  // never refuse
    }
};

class EmbreeAccelerator final : public TriangleAccelerator {
public:
    EmbreeAccelerator(const TriangleMesh& mesh, const BuildOptions& options) {
        const std::string config = options.threads > 0 ? "threads=" + std::to_string(options.threads) : "";
        m_device = rtcNewDevice(config.empty() ? nullptr : config.c_str());
        if (!m_device) throw Error("embree: cannot create a device");
        rtcSetDeviceMemoryMonitorFunction(m_device, &EmbreeMemoryCount::monitor, &m_memory);
        const auto start = std::chrono::steady_clock::now();
        m_scene = rtcNewScene(m_device);
        rtcSetSceneBuildQuality(m_scene, RTC_BUILD_QUALITY_HIGH);
        RTCGeometry geometry = rtcNewGeometry(m_device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.vertex_count()));
        for (std::size_t i = 0; i < mesh.vertex_count(); ++i)
            for (int k = 0; k < 3; ++k) vertices[3 * i + k] = mesh.positions[i][k];
        auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), mesh.triangle_count()));
        for (std::size_t i = 0; i < mesh.triangle_count(); ++i)
            for (int k = 0; k < 3; ++k) indices[3 * i + k] = mesh.triangles[i][k];
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(m_scene, geometry);
        rtcReleaseGeometry(geometry);
        // The tree's bytes: what the scene's build allocated net of what it freed, not the vertex and index
        // buffers above (the mesh's own data, which the kd-trees' bytes leave out too). The peak is the
        // most the build held at once beyond those buffers (its temporary primitive arrays included).
        const std::int64_t before = m_memory.current.load();
        m_memory.peak = before;
        rtcCommitScene(m_scene);
        m_stats.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        m_stats.bytes = m_memory.current.load() - before;
        m_stats.build_peak_bytes = m_memory.peak.load() - before;
    }
    ~EmbreeAccelerator() override {
        if (m_scene) rtcReleaseScene(m_scene);
        if (m_device) rtcReleaseDevice(m_device);
    }
    EmbreeAccelerator(const EmbreeAccelerator&) = delete;
    EmbreeAccelerator& operator=(const EmbreeAccelerator&) = delete;

    std::string_view name() const override { return "embree"; }

    bool intersect(const Ray& ray, MeshHit& hit) const override {
        if (!acceptable(ray)) return false;
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit rh{};
        fill(ray, rh.ray);
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(m_scene, &context, &rh);
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID || !(rh.ray.tfar > ray.tmin && rh.ray.tfar < ray.tmax))
            return false;
        hit = MeshHit{rh.ray.tfar, rh.hit.primID, rh.hit.u, rh.hit.v};
        return true;
    }

    bool occluded(const Ray& ray) const override {
        if (!acceptable(ray)) return false;
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRay r{};
        fill(ray, r);
        rtcOccluded1(m_scene, &context, &r);
        return r.tfar == -std::numeric_limits<float>::infinity();
    }

    // Packets of 8 through rtcIntersect8 / rtcOccluded8 (the packet interface Embree offers for coherent
    // rays); rays Embree would reject are left out by the valid mask and answered as misses.
    void intersect_packet(std::span<const Ray> rays, std::span<MeshHit> hits) const override {
        for (std::size_t first = 0; first < rays.size(); first += 8) {
            const std::size_t n = std::min<std::size_t>(8, rays.size() - first);
            alignas(32) int valid[8] = {};
            alignas(32) RTCRayHit8 rh{};
            for (std::size_t k = 0; k < n; ++k) {
                const Ray& ray = rays[first + k];
                valid[k] = acceptable(ray) ? -1 : 0;
                if (!valid[k]) continue;
                fill8(ray, rh.ray, k);
                rh.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
                rh.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
            }
            RTCIntersectContext context;
            rtcInitIntersectContext(&context);
            context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
            rtcIntersect8(valid, m_scene, &context, &rh);
            for (std::size_t k = 0; k < n; ++k) {
                const Ray& ray = rays[first + k];
                const float t = rh.ray.tfar[k];
                const bool hit =
                    valid[k] && rh.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID && t > ray.tmin && t < ray.tmax;
                hits[first + k] = hit ? MeshHit{t, rh.hit.primID[k], rh.hit.u[k], rh.hit.v[k]} : MeshHit{};
            }
        }
    }

    void occluded_packet(std::span<const Ray> rays, std::span<std::uint8_t> blocked) const override {
        for (std::size_t first = 0; first < rays.size(); first += 8) {
            const std::size_t n = std::min<std::size_t>(8, rays.size() - first);
            alignas(32) int valid[8] = {};
            alignas(32) RTCRay8 r{};
            for (std::size_t k = 0; k < n; ++k) {
                valid[k] = acceptable(rays[first + k]) ? -1 : 0;
                if (valid[k]) fill8(rays[first + k], r, k);
            }
            RTCIntersectContext context;
            rtcInitIntersectContext(&context);
            context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
            rtcOccluded8(valid, m_scene, &context, &r);
            for (std::size_t k = 0; k < n; ++k)
                blocked[first + k] = valid[k] && r.tfar[k] == -std::numeric_limits<float>::infinity() ? 1 : 0;
        }
    }

    AccelStats stats() const override { return m_stats; }

private:
    // Lane k of a packet, as fill() fills a single ray.
    static void fill8(const Ray& ray, RTCRay8& r, std::size_t k) {
        RTCRay one;
        fill(ray, one);
        r.org_x[k] = one.org_x;
        r.org_y[k] = one.org_y;
        r.org_z[k] = one.org_z;
        r.dir_x[k] = one.dir_x;
        r.dir_y[k] = one.dir_y;
        r.dir_z[k] = one.dir_z;
        r.tnear[k] = one.tnear;
        r.tfar[k] = one.tfar;
        r.mask[k] = one.mask;
        r.time[k] = one.time;
        r.flags[k] = one.flags;
    }

    static bool acceptable(const Ray& ray) {
        constexpr float kLarge = 1e18f;  // Embree's FLT_LARGE is 1.844e18
        for (int a = 0; a < 3; ++a)
            if (!(std::abs(ray.origin[a]) <= kLarge) || !(std::abs(ray.direction[a]) <= kLarge)) return false;
        if (ray.direction == Vec3(0.0f)) return false;
        return ray.tmax > std::max(ray.tmin, 0.0f);
    }
    static void fill(const Ray& ray, RTCRay& r) {
        r.org_x = ray.origin.x;
        r.org_y = ray.origin.y;
        r.org_z = ray.origin.z;
        r.dir_x = ray.direction.x;
        r.dir_y = ray.direction.y;
        r.dir_z = ray.direction.z;
        // Embree accepts tnear < t <= tfar; rtlab's interval is open at both ends, so only tfar moves in by
        // one float (moving tnear too would lose hits at the float just above tmin).
        r.tnear = std::max(ray.tmin, 0.0f);
        r.tfar = std::nextafter(ray.tmax, -std::numeric_limits<float>::infinity());
        r.mask = 0xFFFFFFFFu;
        r.time = 0.0f;
        r.flags = 0;
    }

    EmbreeMemoryCount m_memory;  // before the device, which reports to it until released
    RTCDevice m_device = nullptr;
    RTCScene m_scene = nullptr;
    AccelStats m_stats;
};

}  // namespace

std::unique_ptr<TriangleAccelerator> make_embree(const TriangleMesh& mesh, const BuildOptions& options) {
    return std::make_unique<EmbreeAccelerator>(mesh, options);
}

}  // namespace rtlab::accel

#else

namespace rtlab::accel {
std::unique_ptr<TriangleAccelerator> make_embree(const TriangleMesh&, const BuildOptions&) { return nullptr; }
}  // namespace rtlab::accel

#endif
