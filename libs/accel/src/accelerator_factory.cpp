#include <rtlab/accel/accelerator.hpp>
#include <rtlab/accel/kd_tree.hpp>
#include <rtlab/core/error.hpp>

#include "baselines.hpp"

#include <algorithm>

namespace rtlab {

std::vector<std::string> accelerator_methods() {
    std::vector<std::string> methods = kd_tree_methods();
    for (const char* m : {"kd-three-way", "bvh", "octree", "brute"}) methods.emplace_back(m);
#ifdef RTLAB_HAVE_EMBREE
    methods.emplace_back("embree");
#endif
    return methods;
}

std::unique_ptr<TriangleAccelerator> make_accelerator(std::string_view method, const TriangleMesh& mesh,
                                                      const BuildOptions& options) {
    const auto kd = kd_tree_methods();
    if (std::find(kd.begin(), kd.end(), method) != kd.end()) return make_kd_tree(method, mesh, options);
    if (method == "kd-three-way") return accel::make_kd_three_way(mesh, options);
    if (method == "bvh") return accel::make_bvh(mesh, options);
    if (method == "octree") return accel::make_octree(mesh, options);
    if (method == "brute") return accel::make_brute_force(mesh, options);
    if (method == "embree") {
        if (auto embree = accel::make_embree(mesh, options)) return embree;
        throw Error(
            "method 'embree' is not available: rtlab was built without Embree 3 (apt-get install libembree-dev)");
    }
    std::string known;
    for (const auto& m : accelerator_methods()) known += (known.empty() ? "" : ", ") + m;
    throw Error("unknown acceleration method '" + std::string(method) + "'; known: " + known);
}

}  // namespace rtlab
