#include "image_plane.hpp"
#include "noisy_sphere.hpp"

#include <rtlab/core/error.hpp>
#include <rtlab/render/sample_share.hpp>
#include <shared_data.hpp>

#include <catch2/catch.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

using namespace rtlab;
using namespace rtlab::test;
namespace fs = std::filesystem;

namespace {

/// Shading from the stream's integrator pairs, so that every sample's value differs in every bit.
class StreamSource final : public RadianceSource {
public:
    RGB radiance(const Ray& r, const SampleKey& key, RayCounters& counters) const override {
        return sample_radiance(CameraSample{r, SampleStream(SampleSequence::independent, key)}, counters);
    }
    RGB sample_radiance(const CameraSample& s, RayCounters& counters) const override {
        const Vec2 u = s.stream.get2d(kFirstIntegratorPair), v = s.stream.get2d(kFirstIntegratorPair + 1);
        (void)counters;
        return RGB(0.1f + 3.0f * u.x * s.ray.origin.x, v.y / (0.1f + u.y), 0.7f * u.y * v.x + s.ray.origin.y);
    }
};

ProgressiveSettings share_settings(std::uint32_t first, int spp, int threads = 1) {
    ProgressiveSettings s;
    s.first_sample = first;
    s.spp = spp;
    s.seed = 77;
    s.threads = threads;
    s.tile_size = 4;
    s.block_samples = 4;
    return s;
}

std::vector<unsigned char> bytes_of(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const fs::path& p, const std::vector<unsigned char>& b) {
    std::ofstream out(p, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
}

}  // namespace

TEST_CASE("blocks added whole give the bytes of their samples added one by one", "[share]") {
    SampleBuffer one(1, 1, 0, 4), whole(1, 1, 0, 4);
    SampleSums block;
    for (std::uint32_t i = 0; i < 11; ++i) {
        const RGB v(0.1f * static_cast<float>(i * i) + 0.3f, 1.0f / (1.0f + static_cast<float>(i)), 0.7f);
        one.add(0, 0, i, v);
        block.add(i, v);
        if (i % 4 == 3 || i == 10) {
            whole.add_block(0, 0, i / 4 * 4, block);
            block = SampleSums{};
        }
    }
    CHECK(one == whole);
    CHECK(one.count(0, 0) == 11);
    // The block must start at the pixel's next sample, on a boundary, and stay within its block.
    SampleSums two;
    two.add(11, RGB(1, 1, 1));
    CHECK_THROWS_WITH(whole.add_block(0, 0, 12, two), Catch::Contains("next sample is 11"));
    SampleBuffer fresh(1, 1, 0, 4);
    SampleSums five;
    for (std::uint32_t i = 0; i < 5; ++i) five.add(i, RGB(1, 1, 1));
    CHECK_THROWS_WITH(fresh.add_block(0, 0, 0, five), Catch::Contains("runs past its block"));
    SampleSums odd;
    odd.add(1, RGB(1, 1, 1));  // one sample counted as odd for a block starting at the even index 0
    CHECK_THROWS_WITH(fresh.add_block(0, 0, 0, odd), Catch::Contains("even and odd counts"));
}

TEST_CASE("the merge of 1 2 and 3 shares gives the bytes of one render for 1 and 2 threads", "[share]") {
    const fs::path dir = scratch_dir("sample_shares");
    const ImagePlaneCamera camera(9, 7);
    const StreamSource source;
    ProgressiveSettings whole = share_settings(0, 11);
    const ProgressiveResult reference = render_progressive(camera, source, whole);
    // Samples 0 to 10 in blocks of 4: the last share may end inside a block.
    const std::vector<std::vector<std::pair<std::uint32_t, int>>> splits = {
        {{0, 11}}, {{0, 8}, {8, 3}}, {{4, 4}, {0, 4}, {8, 3}}};
    for (const int threads : {1, 2}) {
        for (const auto& split : splits) {
            std::vector<fs::path> files;
            for (const auto& [first, spp] : split) {
                files.push_back(dir / ("s" + std::to_string(first) + "-" + std::to_string(threads) + ".rtshare"));
                const ShareRenderResult r =
                    render_share(camera, source, share_settings(first, spp, threads), 0xabcdef, files.back());
                REQUIRE(r.written);
                CHECK(r.end == first + static_cast<std::uint32_t>(spp));
                CHECK(fs::file_size(files.back()) ==
                      kShareHeaderBytes + ShareReader(files.back()).header().block_count() * 9 * 7 * kShareRecordBytes);
            }
            ShareHeader merged;
            const SampleBuffer buffer = merge_shares(files, &merged);
            INFO(split.size() << " shares, " << threads << " threads");
            CHECK(buffer == reference.buffer);
            CHECK(same_bytes(buffer.mean_image(), reference.image));
            CHECK(merged.end == 11);
            CHECK(merged.scene_hash == 0xabcdef);
            CHECK(merged.seed == 77);
        }
    }
}

TEST_CASE("the merge refuses shares of another frame and overlapping or missing samples", "[share]") {
    const fs::path dir = scratch_dir("sample_share_refusals");
    const ImagePlaneCamera camera(5, 4);
    const StreamSource source;
    auto share = [&](const std::string& name, std::uint32_t first, int spp, std::uint64_t hash = 1,
                     std::uint64_t seed = 77, int width = 5) {
        ProgressiveSettings s = share_settings(first, spp);
        s.seed = seed;
        const fs::path p = dir / name;
        render_share(ImagePlaneCamera(width, 4), source, s, hash, p);
        return p;
    };
    (void)camera;
    const fs::path a = share("a.rtshare", 0, 4), b = share("b.rtshare", 4, 4);
    auto refused = [&](std::vector<fs::path> files, const std::string& what) {
        INFO(what);
        CHECK_THROWS_WITH(merge_shares(files), Catch::Contains(what));
    };
    refused({a, share("seed.rtshare", 4, 4, 1, 78)}, "seed.rtshare': its seed 78 differs from 77");
    refused({a, share("hash.rtshare", 4, 4, 2)}, "its scene hash 0x0000000000000002 (another scene");
    refused({a, share("size.rtshare", 4, 4, 1, 77, 6)}, "its image size 6x4 differs from 5x4");
    refused({a, b, share("over.rtshare", 4, 4)}, "samples 4 to 7 are in both");
    refused({a, share("gap.rtshare", 12, 4)}, "samples 4 to 11 are in no share");
    refused({b}, "samples 0 to 3 are in no share");
    refused({share("short.rtshare", 0, 3), b}, "ends at sample 3, inside a block of 4");
    CHECK_NOTHROW(merge_shares({b, a}));  // any order
    CHECK_THROWS_WITH(merge_shares({}), Catch::Contains("no share files"));
}

TEST_CASE("bad share files are refused with the file named and no allocation from the header", "[share]") {
    const fs::path dir = scratch_dir("sample_share_bad_files");
    const fs::path good = dir / "good.rtshare";
    render_share(ImagePlaneCamera(5, 4), StreamSource(), share_settings(0, 8), 1, good);
    const std::vector<unsigned char> bytes = bytes_of(good);
    REQUIRE(bytes.size() == kShareHeaderBytes + 2 * 5 * 4 * kShareRecordBytes);
    auto refused = [&](const std::string& name, std::vector<unsigned char> b, const std::string& what) {
        const fs::path p = dir / name;
        write_bytes(p, b);
        INFO(name);
        CHECK_THROWS_WITH(ShareReader(p), Catch::Contains(name) && Catch::Contains(what));
    };
    auto set_u32 = [](std::vector<unsigned char> b, std::size_t at, std::uint32_t v) {
        for (int i = 0; i < 4; ++i) b[at + static_cast<std::size_t>(i)] = static_cast<unsigned char>(v >> (8 * i));
        return b;
    };
    refused("truncated.rtshare", {bytes.begin(), bytes.end() - 1}, "truncated or padded");
    refused(
        "padded.rtshare",
        [&] {
            auto b = bytes;
            b.push_back(0);
            return b;
        }(),
        "truncated or padded");
    refused("header.rtshare", {bytes.begin(), bytes.begin() + 20}, "shorter than the 64-byte header");
    refused("empty.rtshare", {}, "not a share file");
    refused(
        "magic.rtshare",
        [&] {
            auto b = bytes;
            b[0] = 'X';
            return b;
        }(),
        "not RTLSHARE");
    refused("version.rtshare", set_u32(bytes, 8, 2), "version 2");
    // A header claiming 2^31 x 2^31 pixels or 2^32 samples in a 4 kB file: refused before anything is allocated.
    refused("wide.rtshare", set_u32(bytes, 32, 0x80000000u), "more than 16384 a side");
    refused("many.rtshare", set_u32(set_u32(bytes, 32, 16384), 36, 16384), "pixels");
    refused("long.rtshare", set_u32(bytes, 44, 0xffffffffu), "truncated or padded");
    refused("range.rtshare", set_u32(bytes, 44, 0), "empty sample range");
    refused("block.rtshare", set_u32(bytes, 48, 0), "block size 0");
    refused("aligned.rtshare", set_u32(bytes, 40, 2), "not on a block boundary");
    refused("sequence.rtshare", set_u32(bytes, 52, 9), "unknown sample sequence");
    // A record whose counts do not match its block: found when the data is read.
    const fs::path corrupt = dir / "corrupt.rtshare";
    write_bytes(corrupt, set_u32(bytes, kShareHeaderBytes + 72, 3));
    CHECK_THROWS_WITH(merge_shares({corrupt}), Catch::Contains("corrupt.rtshare") && Catch::Contains("pixel (0, 0)"));
    CHECK_THROWS_WITH(ShareReader(dir / "missing.rtshare"), Catch::Contains("missing.rtshare"));
    CHECK_THROWS_WITH(ShareReader(dir), Catch::Contains("is a directory"));
}

TEST_CASE("a stopped share keeps its finished blocks and a share never starts inside a block", "[share]") {
    const fs::path dir = scratch_dir("sample_share_stop");
    const fs::path p = dir / "stopped.rtshare";
    fs::remove(p);
    std::atomic<bool> stop{false};
    ProgressiveCallbacks cb;
    cb.stop = &stop;
    cb.pass = [&](const PassUpdate& u) {
        if (u.pass_end == 8) stop = true;  // after the second block
    };
    const ShareRenderResult r = render_share(ImagePlaneCamera(5, 4), StreamSource(), share_settings(0, 16), 3, p, cb);
    CHECK(r.written);
    CHECK(r.end == 8);
    CHECK(ShareReader(p).header().end == 8);
    stop = true;
    const fs::path none = dir / "none.rtshare";
    fs::remove(none);
    const ShareRenderResult early =
        render_share(ImagePlaneCamera(5, 4), StreamSource(), share_settings(0, 16), 3, none, cb);
    CHECK_FALSE(early.written);
    CHECK_FALSE(fs::exists(none));
    for (const auto& entry : fs::directory_iterator(dir))  // no temporary file left behind
        CHECK(entry.path().filename().string().find(".tmp-") == std::string::npos);
    CHECK_THROWS_WITH(render_share(ImagePlaneCamera(5, 4), StreamSource(), share_settings(2, 6), 3, dir / "x.rtshare"),
                      Catch::Contains("not on a block boundary"));
}
