#include "scene_hash.hpp"

#include <rtlab/core/error.hpp>
#include <rtlab/core/file.hpp>
#include <rtlab/render/pixel_sampler.hpp>

#include <array>
#include <cstring>
#include <fstream>

namespace rtlab::app {

namespace {

class Fnv1a {
public:
    void bytes(const void* data, std::size_t n) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < n; ++i) m_h = (m_h ^ p[i]) * 0x100000001b3ULL;
    }
    // Length first, so that ("ab", "c") and ("a", "bc") differ.
    void text(const std::string& s) {
        number(s.size());
        bytes(s.data(), s.size());
    }
    void number(std::uint64_t v) {
        unsigned char b[8];
        for (int i = 0; i < 8; ++i) b[i] = static_cast<unsigned char>(v >> (8 * i));
        bytes(b, 8);
    }
    void file(const std::filesystem::path& path) {
        std::ifstream in(path, std::ios::binary);
        if (!in) throw Error(file_error_message(path, "cannot read it for the scene hash"));
        std::array<char, 1 << 16> buffer;
        std::uint64_t total = 0;
        while (in) {
            in.read(buffer.data(), buffer.size());
            const auto n = static_cast<std::size_t>(in.gcount());
            bytes(buffer.data(), n);
            total += n;
        }
        number(total);
    }
    std::uint64_t value() const { return m_h; }

private:
    std::uint64_t m_h = 0xcbf29ce484222325ULL;
};

}  // namespace

std::uint64_t scene_hash(const std::filesystem::path& scene_file, const LoadedScene& scene,
                         const std::vector<std::filesystem::path>& plugins) {
    Fnv1a h;
    h.text("rtlab scene hash 1");
    h.file(scene_file);
    for (const AssetUse& asset : scene.assets) {
        h.text(asset.name);
        if (asset.file) h.file(asset.file->path);
    }
    for (const auto& plugin : plugins) h.text(plugin.filename().string());
    for (const auto& plugin : scene.plugins) h.text(plugin);
    h.text(std::string(integrator_name(scene.job.integrator)));
    h.number(static_cast<std::uint64_t>(scene.job.whitted.max_depth));
    h.number(static_cast<std::uint64_t>(scene.job.path.max_depth));
    h.text(std::string(pixel_pattern_name(scene.job.settings.pattern)));
    return h.value();
}

}  // namespace rtlab::app
