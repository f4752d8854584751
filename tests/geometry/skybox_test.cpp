#include <rtlab/geometry/skybox.hpp>

#include <catch2/catch.hpp>

using namespace rtlab;

TEST_CASE("skybox faces for the six axes", "[skybox]") {
    const std::pair<Vec3, CubeFace> axes[] = {{{1, 0, 0}, CubeFace::px}, {{-1, 0, 0}, CubeFace::nx},
                                              {{0, 1, 0}, CubeFace::py}, {{0, -1, 0}, CubeFace::ny},
                                              {{0, 0, 1}, CubeFace::pz}, {{0, 0, -1}, CubeFace::nz}};
    for (const auto& [d, face] : axes) {
        const auto c = skybox_lookup(d);
        REQUIRE(c);
        CHECK(c->face == face);
        CHECK(c->s == 0.5f);
        CHECK(c->t == 0.5f);
    }
    CHECK_FALSE(skybox_lookup({0, 0, 0}));
    CHECK_FALSE(skybox_lookup({std::nanf(""), 1, 0}));
}

TEST_CASE("adjacent skybox faces meet without a seam at all 12 edges", "[skybox]") {
    // For each edge direction e, step a little onto each of the two faces: the points on the two faces
    // must map back to nearly the same direction (a flipped or rotated face would put them far apart).
    int edges = 0;
    for (int a = 0; a < 3; ++a)
        for (int b = a + 1; b < 3; ++b)
            for (float sa : {1.0f, -1.0f})
                for (float sb : {1.0f, -1.0f})
                    for (float along : {-0.6f, 0.0f, 0.6f}) {
                        Vec3 e(0.0f);
                        e[a] = sa;
                        e[b] = sb;
                        e[3 - a - b] = along;
                        Vec3 onto_a = e, onto_b = e;
                        onto_a[a] *= 1.001f;
                        onto_b[b] *= 1.001f;
                        const auto ca = skybox_lookup(onto_a), cb = skybox_lookup(onto_b);
                        REQUIRE(ca);
                        REQUIRE(cb);
                        CHECK(ca->face != cb->face);
                        const Vec3 da = glm::normalize(cube_face_direction(ca->face, ca->s, ca->t));
                        const Vec3 db = glm::normalize(cube_face_direction(cb->face, cb->s, cb->t));
                        CHECK(glm::length(da - db) < 2e-3f);
                        // And each face coordinate lies on that face's border.
                        CHECK((ca->s < 0.001f || ca->s > 0.999f || ca->t < 0.001f || ca->t > 0.999f));
                        if (along == 0.0f) ++edges;
                    }
    CHECK(edges == 12);
}
