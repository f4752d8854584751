// Uses rtlab::accel from an installed rtlab: a kd-tree over two triangles, one ray.
#include <rtlab/accel/accelerator.hpp>

#include <cstdio>

int main() {
    rtlab::TriangleMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    const auto tree = rtlab::make_accelerator("kd-sah", mesh);
    rtlab::MeshHit hit;
    const rtlab::Ray ray{{0.25f, 0.75f, 2.0f}, {0.0f, 0.0f, -1.0f}};
    if (!tree->intersect(ray, hit) || hit.primitive != 1 || hit.t != 2.0f) {
        std::puts("consumer: unexpected result");
        return 1;
    }
    std::puts("consumer: ok");
    return 0;
}
