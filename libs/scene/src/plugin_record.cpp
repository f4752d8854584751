// Comparing a module's RtlabPluginRecord with the host's, field by field, in words a user can act on.
#include <rtlab/scene/plugin.hpp>

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

// One checked field: its name in messages and how each record shows it. Two records differ in the field
// when the shown texts differ, so the text is also what the message prints.
struct Field {
    const char* name;
    std::string (*show)(const RtlabPluginRecord&);
};

template <auto Member>
std::string show_number(const RtlabPluginRecord& r) {
    return std::to_string(r.*Member);
}

// The fields after abi_version and record_size, in the order a user reads them.
constexpr Field kFields[] = {
    {"rtlab version",
     [](const RtlabPluginRecord& r) {
         return version(r.rtlab_version_major, r.rtlab_version_minor, r.rtlab_version_patch);
     }},
    {"public headers hash", [](const RtlabPluginRecord& r) { return text(r.headers_hash); }},
    {"_GLIBCXX_USE_CXX11_ABI", show_number<&RtlabPluginRecord::glibcxx_use_cxx11_abi>},
    {"_GLIBCXX_RELEASE", show_number<&RtlabPluginRecord::glibcxx_release>},
    {"_GLIBCXX_DEBUG", show_number<&RtlabPluginRecord::glibcxx_debug>},
    {"GLM_VERSION", show_number<&RtlabPluginRecord::glm_version>},
    {"GLM configuration", [](const RtlabPluginRecord& r) { return glm_bits(r.glm_config); }},
    {"sizeof(Vec3)", show_number<&RtlabPluginRecord::size_vec3>},
    {"alignof(Vec3)", show_number<&RtlabPluginRecord::align_vec3>},
    {"sizeof(Vec4)", show_number<&RtlabPluginRecord::size_vec4>},
    {"alignof(Vec4)", show_number<&RtlabPluginRecord::align_vec4>},
    {"sizeof(Mat4)", show_number<&RtlabPluginRecord::size_mat4>},
    {"sizeof(std::string)", show_number<&RtlabPluginRecord::size_std_string>},
    {"sizeof(std::function)", show_number<&RtlabPluginRecord::size_std_function>},
    {"sizeof(std::shared_ptr)", show_number<&RtlabPluginRecord::size_shared_ptr>},
    {"sizeof(Params)", show_number<&RtlabPluginRecord::size_params>},
    {"sizeof(Registry)", show_number<&RtlabPluginRecord::size_registry>},
    {"sizeof(TextureLookup)", show_number<&RtlabPluginRecord::size_texture_lookup>},
    {"sizeof(SurfaceTerms)", show_number<&RtlabPluginRecord::size_surface_terms>},
};

}  // namespace

std::vector<std::string> plugin_record_differences(const RtlabPluginRecord& expected, const RtlabPluginRecord& got) {
    std::vector<std::string> out;
    auto compare = [&](const char* name, const std::string& want, const std::string& have) {
        if (want != have) out.push_back(std::string(name) + ": expected " + want + ", got " + have);
    };
    // A record of another layout: nothing after these two fields means what the host thinks it means.
    compare("plugin ABI version", std::to_string(expected.abi_version), std::to_string(got.abi_version));
    if (!out.empty()) return out;
    compare("record size", std::to_string(expected.record_size), std::to_string(got.record_size));
    if (!out.empty()) return out;
    // A missing hash never matches, not even another missing one (the table compares "(none)" equal).
    if (!expected.headers_hash && !got.headers_hash) out.push_back("public headers hash: expected (none), got (none)");
    for (const Field& f : kFields) compare(f.name, f.show(expected), f.show(got));
    return out;
}

}  // namespace rtlab
