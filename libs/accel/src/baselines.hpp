#pragma once
// The structures rtlab compares its kd-trees against (private; created through make_accelerator).
#include <rtlab/accel/accelerator.hpp>

#include <memory>

namespace rtlab::accel {

std::unique_ptr<TriangleAccelerator> make_brute_force(const TriangleMesh& mesh, const BuildOptions& options);
std::unique_ptr<TriangleAccelerator> make_bvh(const TriangleMesh& mesh, const BuildOptions& options);
std::unique_ptr<TriangleAccelerator> make_kd_three_way(const TriangleMesh& mesh, const BuildOptions& options);
std::unique_ptr<TriangleAccelerator> make_octree(const TriangleMesh& mesh, const BuildOptions& options);
/// nullptr when rtlab was built without Embree.
std::unique_ptr<TriangleAccelerator> make_embree(const TriangleMesh& mesh, const BuildOptions& options);

}  // namespace rtlab::accel
