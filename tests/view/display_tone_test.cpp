#include "display_tone.hpp"

#include <rtlab/core/params.hpp>
#include <rtlab/tonemap/tone_operator.hpp>

#include <catch2/catch.hpp>

#include <cmath>

using namespace rtlab;
using namespace rtlab::view;

namespace {

/// An HDR image spanning four decades, with a black pixel.
Image hdr_ramp() {
    Image image(16, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 16; ++x) {
            const float v = std::pow(10.0f, static_cast<float>(x) / 4.0f - 2.0f);
            image.at(x, y) = RGB(v, v * 0.5f * static_cast<float>(y + 1) / 4.0f, v * 0.1f);
        }
    image.at(0, 0) = RGB(0.0f, 0.0f, 0.0f);
    return image;
}

std::vector<float> floats(const Image& image) {
    std::vector<float> out;
    for (const RGB& p : image.pixels()) out.insert(out.end(), {p.r, p.g, p.b});
    return out;
}

void check_against(const std::string& name, ToneChoice choice) {
    const Image hdr = hdr_ramp();
    const ToneRegistry registry = make_tone_registry();
    const Image expected = registry.create(name, Params{})->apply(hdr);
    const ToneParams params = tone_params(choice, 0.0f, floats(hdr));
    for (int y = 0; y < hdr.height(); ++y)
        for (int x = 0; x < hdr.width(); ++x) {
            const RGB got = tone_map(params, hdr.at(x, y));
            for (int c = 0; c < 3; ++c) REQUIRE(got[c] == Approx(expected.at(x, y)[c]).margin(2e-6).epsilon(1e-5));
        }
}

}  // namespace

TEST_CASE("the viewer's Reinhard mapping is rtlab's reinhard operator", "[view]") {
    check_against("reinhard", ToneChoice::reinhard);
}

TEST_CASE("the viewer's Ward mapping is rtlab's ward operator", "[view]") { check_against("ward", ToneChoice::ward); }

TEST_CASE("the viewer's ACES mapping is rtlab's aces operator", "[view]") { check_against("aces", ToneChoice::aces); }

TEST_CASE("the viewer's none clamps and its exposure doubles per stop", "[view]") {
    const ToneParams none = tone_params(ToneChoice::none, 0.0f, {});
    CHECK(tone_map(none, RGB(2.0f, 0.25f, -1.0f)) == RGB(1.0f, 0.25f, 0.0f));
    const ToneParams two = tone_params(ToneChoice::none, 2.0f, {});
    CHECK(tone_map(two, RGB(0.1f, 0.2f, 0.0f))[0] == Approx(0.4f));
}

TEST_CASE("tone statistics leave out pixels without samples", "[view]") {
    const std::vector<float> rgb{1.0f, 1.0f, 1.0f, 100.0f, 100.0f, 100.0f};
    const ToneParams all = tone_params(ToneChoice::reinhard, 0.0f, rgb);
    const ToneParams first = tone_params(ToneChoice::reinhard, 0.0f, rgb, {1, 0});
    CHECK(first.scale == Approx(0.18f / (1.0f + 1e-4f)).epsilon(1e-4));
    CHECK(all.scale < first.scale);
}

TEST_CASE("tone choices are parsed by name", "[view]") {
    ToneChoice c = ToneChoice::none;
    CHECK(parse_tone_choice("aces", c));
    CHECK(c == ToneChoice::aces);
    CHECK_FALSE(parse_tone_choice("filmic", c));
}
