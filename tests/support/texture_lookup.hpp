#pragma once
// A texture lookup at a uv point and nothing else, for texture tests.
#include <rtlab/textures/texture.hpp>

namespace rtlab::test {

inline TextureLookup at_uv(float u, float v) {
    TextureLookup q;
    q.uv = {u, v};
    return q;
}

}  // namespace rtlab::test
