#pragma once
/// \brief Ray, hit and spawn files (RTRAYS01, RTHITS01, RTSPAWN1) and the standard ray sets of FORMATS.md.
#include <rtlab/accel/accelerator.hpp>
#include <rtlab/core/aabb.hpp>
#include <rtlab/core/ray.hpp>

#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

namespace rtlab {

/// Reads an RTRAYS01 file. Throws rtlab::Error naming the file for a wrong magic or a size that is not
/// 16 + 32 N bytes.
std::vector<Ray> read_ray_file(const std::filesystem::path& path);
void write_ray_file(const std::filesystem::path& path, std::span<const Ray> rays);

/// Writes an RTHITS01 file: record k answers ray k (t = +inf and prim = 0xFFFFFFFF for a miss).
void write_hit_file(const std::filesystem::path& path, std::span<const MeshHit> hits);
std::vector<MeshHit> read_hit_file(const std::filesystem::path& path);

/// Reads an RTSPAWN1 file: element k is the 0-based triangle that ray k's origin lies on (values are not
/// checked against any mesh). Throws rtlab::Error naming the file for a wrong magic or a size that is not
/// 16 + 4 N bytes.
std::vector<std::int32_t> read_spawn_file(const std::filesystem::path& path);
void write_spawn_file(const std::filesystem::path& path, std::span<const std::int32_t> triangles);

/// The "primary" set: n x n pinhole rays looking along -z at the box centre from 1.5 diagonals away.
std::vector<Ray> primary_rays(const AABB& bounds, int n = 1024);
/// The "random" set: origins on a sphere of 1.5 half-diagonals, aimed at uniform points in the box.
std::vector<Ray> random_rays(const AABB& bounds, std::size_t count = 1000000, std::uint32_t seed = 12345);

}  // namespace rtlab
