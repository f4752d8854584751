#include "commands.hpp"

#include <rtlab/core/error.hpp>

#include <catch2/catch.hpp>

using namespace rtlab::view;

TEST_CASE("viewer commands are split into name and arguments", "[view]") {
    const auto c = parse_command("orbit 10 -5  # look left", "script:1");
    REQUIRE(c);
    CHECK(c->name == "orbit");
    CHECK(c->args == std::vector<std::string>{"10", "-5"});
    CHECK_FALSE(parse_command("   # only a comment", "script:2"));
    CHECK(parse_command("wait pass 3", "stdin:1")->args.size() == 2);
}

TEST_CASE("a bad viewer command names where it was", "[view]") {
    CHECK_THROWS_WITH(parse_command("orbt 1 2", "s.txt:4"), Catch::Contains("s.txt:4: unknown command 'orbt'"));
    CHECK_THROWS_WITH(parse_command("orbit 1", "s.txt:5"), Catch::Contains("orbit takes 2 argument(s), got 1"));
    CHECK_THROWS_WITH(parse_command("wait for it", "s.txt:6"), Catch::Contains("wait takes"));
}
