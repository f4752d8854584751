// Comparing a module's RtlabPluginRecord with the host's, field by field, in words a user can act on.
#include <rtlab/render/plugin.hpp>

#include <cstdio>
#include <cstring>

namespace rtlab {

namespace {

std::string text(const char* s) { return s ? "'" + std::string(s) + "'" : std::string("(none)"); }

std::string version(std::uint32_t major, std::uint32_t minor, std::uint32_t patch) {
    return std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(patch);
}

std::string glm_bits(std::uint32_t bits) {
    struct Flag {
        std::uint32_t bit;
        const char* name;
    };
    static constexpr Flag kFlags[] = {
        {RTLAB_GLM_SIMD, "GLM_CONFIG_SIMD"},
        {RTLAB_GLM_ALIGNED_GENTYPES, "GLM_CONFIG_ALIGNED_GENTYPES"},
        {RTLAB_GLM_DEFAULT_ALIGNED, "GLM_FORCE_DEFAULT_ALIGNED_GENTYPES"},
        {RTLAB_GLM_SWIZZLE_OPERATOR, "GLM_FORCE_SWIZZLE (operators)"},
        {RTLAB_GLM_SWIZZLE_FUNCTION, "GLM_FORCE_SWIZZLE (functions)"},
        {RTLAB_GLM_XYZW_ONLY, "GLM_FORCE_XYZW_ONLY"},
        {RTLAB_GLM_SIZE_T_LENGTH, "GLM_FORCE_SIZE_T_LENGTH"},
        {RTLAB_GLM_CTOR_INIT, "GLM_FORCE_CTOR_INIT"},
        {RTLAB_GLM_ANONYMOUS_STRUCT, "GLM_CONFIG_ANONYMOUS_STRUCT"},
        {RTLAB_GLM_PRECISION_NOT_HIGHP, "GLM_FORCE_PRECISION_MEDIUMP/LOWP_FLOAT"},
    };
    std::string out;
    for (const Flag& f : kFlags) {
        if (bits & f.bit) out += (out.empty() ? "" : " + ") + std::string(f.name);
        bits &= ~f.bit;
    }
    if (bits) {
        char hex[16];
        std::snprintf(hex, sizeof hex, "0x%x", bits);
        out += (out.empty() ? "unknown bits " : " + unknown bits ") + std::string(hex);
    }
    return out.empty() ? "defaults" : out;
}

}  // namespace

std::vector<std::string> plugin_record_differences(const RtlabPluginRecord& expected, const RtlabPluginRecord& got) {
    std::vector<std::string> out;
    auto differ = [&](const char* field, const std::string& want, const std::string& have) {
        out.push_back(std::string(field) + ": expected " + want + ", got " + have);
    };
    auto number = [&](const char* field, auto want, auto have) {
        if (want != have) differ(field, std::to_string(want), std::to_string(have));
    };
    // A record of another layout: nothing after these two fields means what the host thinks it means.
    number("plugin ABI version", expected.abi_version, got.abi_version);
    if (!out.empty()) return out;
    number("record size", expected.record_size, got.record_size);
    if (!out.empty()) return out;

    const std::string want_version =
        version(expected.rtlab_version_major, expected.rtlab_version_minor, expected.rtlab_version_patch);
    const std::string have_version = version(got.rtlab_version_major, got.rtlab_version_minor, got.rtlab_version_patch);
    if (want_version != have_version) differ("rtlab version", want_version, have_version);
    const bool same_hash =
        expected.headers_hash && got.headers_hash && std::strcmp(expected.headers_hash, got.headers_hash) == 0;
    if (!same_hash) differ("public headers hash", text(expected.headers_hash), text(got.headers_hash));
    number("_GLIBCXX_USE_CXX11_ABI", expected.glibcxx_use_cxx11_abi, got.glibcxx_use_cxx11_abi);
    number("_GLIBCXX_RELEASE", expected.glibcxx_release, got.glibcxx_release);
    number("_GLIBCXX_DEBUG", expected.glibcxx_debug, got.glibcxx_debug);
    number("GLM_VERSION", expected.glm_version, got.glm_version);
    if (expected.glm_config != got.glm_config)
        differ("GLM configuration", glm_bits(expected.glm_config), glm_bits(got.glm_config));
    number("sizeof(Vec3)", expected.size_vec3, got.size_vec3);
    number("alignof(Vec3)", expected.align_vec3, got.align_vec3);
    number("sizeof(Vec4)", expected.size_vec4, got.size_vec4);
    number("alignof(Vec4)", expected.align_vec4, got.align_vec4);
    number("sizeof(Mat4)", expected.size_mat4, got.size_mat4);
    number("sizeof(std::string)", expected.size_std_string, got.size_std_string);
    number("sizeof(std::function)", expected.size_std_function, got.size_std_function);
    number("sizeof(std::shared_ptr)", expected.size_shared_ptr, got.size_shared_ptr);
    number("sizeof(Params)", expected.size_params, got.size_params);
    number("sizeof(Registry)", expected.size_registry, got.size_registry);
    number("sizeof(TextureLookup)", expected.size_texture_lookup, got.size_texture_lookup);
    number("sizeof(SurfaceTerms)", expected.size_surface_terms, got.size_surface_terms);
    return out;
}

}  // namespace rtlab
