#include <rtlab/accel/ray_io.hpp>
#include <rtlab/core/error.hpp>
#include <rtlab/core/file.hpp>

#include <bit>
#include <cstring>
#include <string>

namespace rtlab {

namespace {
static_assert(std::endian::native == std::endian::little, "ray, hit and spawn files are little-endian");

constexpr char kRayMagic[8] = {'R', 'T', 'R', 'A', 'Y', 'S', '0', '1'};
constexpr char kHitMagic[8] = {'R', 'T', 'H', 'I', 'T', 'S', '0', '1'};
constexpr char kSpawnMagic[8] = {'R', 'T', 'S', 'P', 'A', 'W', 'N', '1'};

template <class T>
void append(std::vector<unsigned char>& out, const T& value) {
    const auto* p = reinterpret_cast<const unsigned char*>(&value);
    out.insert(out.end(), p, p + sizeof(T));
}

// Checks magic and size, returns the record count.
std::uint64_t check_header(const std::vector<unsigned char>& bytes, const char (&magic)[8], std::size_t record,
                           const std::filesystem::path& path, const char* kind) {
    if (bytes.size() < 16)
        throw Error(file_error_message(path, std::string(kind) + " file shorter than its 16-byte header"));
    if (std::memcmp(bytes.data(), magic, 8) != 0)
        throw Error(file_error_message(
            path, std::string("not a ") + kind + " file (magic is not '" + std::string(magic, 8) + "')"));
    std::uint64_t count;
    std::memcpy(&count, bytes.data() + 8, 8);
    const std::uint64_t payload = bytes.size() - 16;
    if (count > payload / record || payload != count * record)
        throw Error(file_error_message(path, std::string(kind) + " file of " + std::to_string(bytes.size()) +
                                                 " bytes does not hold the " + std::to_string(count) +
                                                 " records its header claims (16 + " + std::to_string(record) +
                                                 " N bytes)"));
    return count;
}
}  // namespace

std::vector<Ray> read_ray_file(const std::filesystem::path& path) {
    const auto bytes = read_binary_file(path);
    const std::uint64_t n = check_header(bytes, kRayMagic, 32, path, "ray");
    std::vector<Ray> rays(n);
    for (std::uint64_t i = 0; i < n; ++i) {
        float f[8];
        std::memcpy(f, bytes.data() + 16 + 32 * i, 32);
        rays[i] = Ray{{f[0], f[1], f[2]}, {f[3], f[4], f[5]}, f[6], f[7]};
    }
    return rays;
}

void write_ray_file(const std::filesystem::path& path, std::span<const Ray> rays) {
    std::vector<unsigned char> out(kRayMagic, kRayMagic + 8);
    out.reserve(16 + 32 * rays.size());
    append(out, static_cast<std::uint64_t>(rays.size()));
    for (const Ray& r : rays) {
        const float f[8] = {r.origin.x,    r.origin.y,    r.origin.z, r.direction.x,
                            r.direction.y, r.direction.z, r.tmin,     r.tmax};
        append(out, f);
    }
    write_binary_file(path, out);
}

void write_hit_file(const std::filesystem::path& path, std::span<const MeshHit> hits) {
    std::vector<unsigned char> out(kHitMagic, kHitMagic + 8);
    out.reserve(16 + 16 * hits.size());
    append(out, static_cast<std::uint64_t>(hits.size()));
    for (const MeshHit& h : hits) {
        const bool hit = h.hit();
        append(out, hit ? h.t : std::numeric_limits<float>::infinity());
        append(out, hit ? h.primitive : 0xFFFFFFFFu);
        append(out, hit ? h.u : 0.0f);
        append(out, hit ? h.v : 0.0f);
    }
    write_binary_file(path, out);
}

std::vector<MeshHit> read_hit_file(const std::filesystem::path& path) {
    const auto bytes = read_binary_file(path);
    const std::uint64_t n = check_header(bytes, kHitMagic, 16, path, "hit");
    std::vector<MeshHit> hits(n);
    for (std::uint64_t i = 0; i < n; ++i) {
        const unsigned char* p = bytes.data() + 16 + 16 * i;
        std::memcpy(&hits[i].t, p, 4);
        std::memcpy(&hits[i].primitive, p + 4, 4);
        std::memcpy(&hits[i].u, p + 8, 4);
        std::memcpy(&hits[i].v, p + 12, 4);
    }
    return hits;
}

std::vector<std::int32_t> read_spawn_file(const std::filesystem::path& path) {
    const auto bytes = read_binary_file(path);
    const std::uint64_t n = check_header(bytes, kSpawnMagic, 4, path, "spawn");
    std::vector<std::int32_t> triangles(n);
    if (n > 0) std::memcpy(triangles.data(), bytes.data() + 16, 4 * n);
    return triangles;
}

void write_spawn_file(const std::filesystem::path& path, std::span<const std::int32_t> triangles) {
    std::vector<unsigned char> out(kSpawnMagic, kSpawnMagic + 8);
    out.reserve(16 + 4 * triangles.size());
    append(out, static_cast<std::uint64_t>(triangles.size()));
    for (const std::int32_t t : triangles) append(out, t);
    write_binary_file(path, out);
}

}  // namespace rtlab
