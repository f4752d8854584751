#include <rtlab/accel/accelerator.hpp>
#include <rtlab/core/error.hpp>

#include <catch2/catch.hpp>

#include "test_meshes.hpp"

#include <algorithm>

using namespace rtlab;

TEST_CASE("the factory builds every listed method under its own name and lists all names on a typo", "[accel]") {
    const TriangleMesh mesh = test::icosphere(1);
    const auto methods = accelerator_methods();
    for (const char* baseline : {"brute", "bvh", "octree", "kd-sah"})
        CHECK(std::count(methods.begin(), methods.end(), baseline) == 1);
    for (const std::string& method : methods) {
        INFO(method);
        const auto accel = make_accelerator(method, mesh);
        REQUIRE(accel);
        CHECK(accel->name() == method);
        CHECK(accel->stats().build_seconds >= 0.0);
    }
    try {
        make_accelerator("octtree", mesh);
        FAIL("no error for an unknown method");
    } catch (const Error& e) {
        const std::string message = e.what();
        CHECK(message.find("'octtree'") != std::string::npos);
        for (const std::string& method : methods) CHECK(message.find(method) != std::string::npos);
    }
    if (std::find(methods.begin(), methods.end(), "embree") == methods.end())
        CHECK_THROWS_WITH(make_accelerator("embree", mesh), Catch::Matchers::Contains("without Embree"));
}
