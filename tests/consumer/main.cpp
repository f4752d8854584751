// Uses rtlab::core from an installed rtlab: a ray against a box.
#include <rtlab/core/aabb.hpp>

#include <cstdio>

int main() {
    const rtlab::AABB box{{-1, -1, -1}, {1, 1, 1}};
    const rtlab::Ray ray{{0, 0, -5}, {0, 0, 1}};
    const auto hit = box.intersect(ray);
    if (!hit || hit->min != 4.0f) {
        std::puts("consumer: unexpected result");
        return 1;
    }
    std::puts("consumer: ok");
    return 0;
}
