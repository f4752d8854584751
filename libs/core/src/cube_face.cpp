#include <rtlab/core/cube_face.hpp>

#include <cmath>

namespace rtlab {

CubeFaceCoord cube_face_coord(const Vec3& d) {
    const float ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
    CubeFace face;
    float sc, tc, ma;
    if (ax >= ay && ax >= az) {
        ma = ax;
        face = d.x >= 0.0f ? CubeFace::px : CubeFace::nx;
        sc = d.x >= 0.0f ? -d.z : d.z;
        tc = -d.y;
    } else if (ay >= az) {
        ma = ay;
        face = d.y >= 0.0f ? CubeFace::py : CubeFace::ny;
        sc = d.x;
        tc = d.y >= 0.0f ? d.z : -d.z;
    } else {
        ma = az;
        face = d.z >= 0.0f ? CubeFace::pz : CubeFace::nz;
        sc = d.z >= 0.0f ? d.x : -d.x;
        tc = -d.y;
    }
    // |sc|, |tc| <= ma, so the correctly rounded quotients stay in [-1, 1] and s, t in [0, 1].
    return {face, 0.5f * (sc / ma + 1.0f), 0.5f * (tc / ma + 1.0f)};
}

Vec3 cube_face_direction(CubeFace face, float s, float t) {
    const float sc = 2.0f * s - 1.0f, tc = 2.0f * t - 1.0f;
    switch (face) {
        case CubeFace::px:
            return {1.0f, -tc, -sc};
        case CubeFace::nx:
            return {-1.0f, -tc, sc};
        case CubeFace::py:
            return {sc, 1.0f, tc};
        case CubeFace::ny:
            return {sc, -1.0f, -tc};
        case CubeFace::pz:
            return {sc, -tc, 1.0f};
        case CubeFace::nz:
            return {-sc, -tc, -1.0f};
    }
    return {0.0f, 0.0f, 1.0f};
}

}  // namespace rtlab
