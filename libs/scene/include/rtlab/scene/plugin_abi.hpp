#pragma once
/// \brief The plugin boundary: the two C entry points a module exports, the plain C record the host checks
/// before it lets any C++ object cross, and the helpers a module uses to fill them (docs/plugins.md).
///
/// A module exports exactly
///
///     extern "C" const RtlabPluginRecord* rtlab_plugin_query(void);
///     extern "C" int rtlab_plugin_register(const RtlabPluginRegistries* registries, char* error,
///                                          size_t error_size);
///
/// The host calls rtlab_plugin_query first and compares every field of the record with its own (built by the
/// same inline function below, so each side describes the headers, standard library and GLM it was compiled
/// with). Only when all agree does it call rtlab_plugin_register, which adds the module's types to the
/// registries it is given and returns 0, or writes a message into `error` and returns non-zero. No exception
/// crosses the C boundary: rtlab::plugin_register() below catches them.
///
/// A module writes both with one line, RTLAB_DEFINE_PLUGIN("description", register_types), where
/// register_types is a function `void register_types(rtlab::PluginRegistries&)` (at the end of this file).
#include <rtlab/scene/plugin_build_info.hpp>
#include <rtlab/shading/light.hpp>
#include <rtlab/shading/material.hpp>
#include <rtlab/textures/texture.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <exception>
#include <functional>
#include <memory>
#include <string>

/// The version of this boundary: the record's layout and the entry points' signatures. A module built for
/// another one is refused before any other field is read.
#define RTLAB_PLUGIN_ABI_VERSION 3

/// Marks the module's two entry points as exported while everything else stays hidden (-fvisibility=hidden).
#define RTLAB_PLUGIN_EXPORT extern "C" __attribute__((visibility("default")))

/// The names the host looks up with dlsym.
#define RTLAB_PLUGIN_QUERY_SYMBOL "rtlab_plugin_query"
#define RTLAB_PLUGIN_REGISTER_SYMBOL "rtlab_plugin_register"

// Bits of RtlabPluginRecord::glm_config: GLM settings that change the size, alignment or members of the
// vector and matrix types every rtlab interface passes around.
#define RTLAB_GLM_SIMD 0x1u                   // GLM_CONFIG_SIMD (GLM_FORCE_INTRINSICS with SSE/AVX enabled)
#define RTLAB_GLM_ALIGNED_GENTYPES 0x2u       // GLM_CONFIG_ALIGNED_GENTYPES (GLM_FORCE_ALIGNED_GENTYPES)
#define RTLAB_GLM_DEFAULT_ALIGNED 0x4u        // GLM_FORCE_DEFAULT_ALIGNED_GENTYPES: vec3 is 16-byte aligned
#define RTLAB_GLM_SWIZZLE_OPERATOR 0x8u       // GLM_FORCE_SWIZZLE with anonymous unions: extra members
#define RTLAB_GLM_SWIZZLE_FUNCTION 0x10u      // GLM_FORCE_SWIZZLE as functions
#define RTLAB_GLM_XYZW_ONLY 0x20u             // GLM_FORCE_XYZW_ONLY: no r, g, b / s, t, p aliases
#define RTLAB_GLM_SIZE_T_LENGTH 0x40u         // GLM_FORCE_SIZE_T_LENGTH: length() returns size_t
#define RTLAB_GLM_CTOR_INIT 0x80u             // GLM_FORCE_CTOR_INIT: vectors are zero-initialised
#define RTLAB_GLM_ANONYMOUS_STRUCT 0x100u     // GLM_CONFIG_ANONYMOUS_STRUCT
#define RTLAB_GLM_PRECISION_NOT_HIGHP 0x200u  // GLM_FORCE_PRECISION_* other than highp for float

extern "C" {

/// \brief What a module was built against. Plain C: the host reads it before trusting any C++ layout.
///
/// The first two fields never move: abi_version is checked first and record_size next, so a record from
/// another boundary version is refused without reading past its end.
typedef struct RtlabPluginRecord {
    uint32_t abi_version;  ///< RTLAB_PLUGIN_ABI_VERSION
    uint32_t record_size;  ///< sizeof(RtlabPluginRecord)
    uint32_t rtlab_version_major, rtlab_version_minor, rtlab_version_patch;
    /// SHA-256 (hex) of rtlab's public headers, computed when rtlab was configured (plugin_build_info.hpp).
    const char* headers_hash;
    int32_t glibcxx_use_cxx11_abi;  ///< _GLIBCXX_USE_CXX11_ABI: std::string and std::list layouts
    int32_t glibcxx_release;        ///< _GLIBCXX_RELEASE: the libstdc++ major version
    int32_t glibcxx_debug;          ///< _GLIBCXX_DEBUG: the debug-mode containers have other layouts
    int32_t glm_version;            ///< GLM_VERSION (998 for 0.9.9.8)
    uint32_t glm_config;            ///< RTLAB_GLM_* bits
    /// Sizes of types that cross the boundary, as measured by the compiler that built each side: a last
    /// line of defence against a setting the fields above do not name.
    uint32_t size_vec3, align_vec3, size_vec4, align_vec4, size_mat4;
    uint32_t size_std_string, size_std_function, size_shared_ptr;
    uint32_t size_params, size_registry, size_texture_lookup, size_surface_terms;
    const char* description;  ///< one line for listings; not checked
} RtlabPluginRecord;

/// \brief The host's registries, given to rtlab_plugin_register. Each pointer is an
/// rtlab::MaterialRegistry*, rtlab::TextureRegistry* or rtlab::LightRegistry* (void* keeps this a C struct).
typedef struct RtlabPluginRegistries {
    uint32_t abi_version;  ///< RTLAB_PLUGIN_ABI_VERSION
    void* materials;
    void* textures;
    void* lights;
} RtlabPluginRegistries;

typedef const RtlabPluginRecord* (*RtlabPluginQueryFn)(void);
typedef int (*RtlabPluginRegisterFn)(const RtlabPluginRegistries* registries, char* error, size_t error_size);

}  // extern "C"

namespace rtlab {

/// The GLM configuration of the code that includes this header, as RTLAB_GLM_* bits.
constexpr std::uint32_t plugin_glm_config() {
    std::uint32_t bits = 0;
#if GLM_CONFIG_SIMD == GLM_ENABLE
    bits |= RTLAB_GLM_SIMD;
#endif
#if GLM_CONFIG_ALIGNED_GENTYPES == GLM_ENABLE
    bits |= RTLAB_GLM_ALIGNED_GENTYPES;
#endif
#if defined(GLM_FORCE_DEFAULT_ALIGNED_GENTYPES)
    bits |= RTLAB_GLM_DEFAULT_ALIGNED;
#endif
#if GLM_CONFIG_SWIZZLE == GLM_SWIZZLE_OPERATOR
    bits |= RTLAB_GLM_SWIZZLE_OPERATOR;
#elif GLM_CONFIG_SWIZZLE == GLM_SWIZZLE_FUNCTION
    bits |= RTLAB_GLM_SWIZZLE_FUNCTION;
#endif
#if GLM_CONFIG_XYZW_ONLY == GLM_ENABLE
    bits |= RTLAB_GLM_XYZW_ONLY;
#endif
#if GLM_CONFIG_LENGTH_TYPE == GLM_LENGTH_SIZE_T
    bits |= RTLAB_GLM_SIZE_T_LENGTH;
#endif
#if GLM_CONFIG_CTOR_INIT != GLM_CTOR_INIT_DISABLE
    bits |= RTLAB_GLM_CTOR_INIT;
#endif
#if GLM_CONFIG_ANONYMOUS_STRUCT == GLM_ENABLE
    bits |= RTLAB_GLM_ANONYMOUS_STRUCT;
#endif
#if defined(GLM_FORCE_PRECISION_MEDIUMP_FLOAT) || defined(GLM_FORCE_PRECISION_LOWP_FLOAT)
    bits |= RTLAB_GLM_PRECISION_NOT_HIGHP;
#endif
    return bits;
}

/// The record describing the code that includes this header: a module returns it from rtlab_plugin_query
/// (kept in a static, so the pointer stays valid), and the host builds its own to compare.
inline RtlabPluginRecord make_plugin_record(const char* description) {
    RtlabPluginRecord r{};
    r.abi_version = RTLAB_PLUGIN_ABI_VERSION;
    r.record_size = sizeof(RtlabPluginRecord);
    r.rtlab_version_major = RTLAB_VERSION_MAJOR;
    r.rtlab_version_minor = RTLAB_VERSION_MINOR;
    r.rtlab_version_patch = RTLAB_VERSION_PATCH;
    r.headers_hash = RTLAB_PUBLIC_HEADERS_HASH;
#if defined(_GLIBCXX_USE_CXX11_ABI)
    r.glibcxx_use_cxx11_abi = _GLIBCXX_USE_CXX11_ABI;
#else
    r.glibcxx_use_cxx11_abi = -1;  // not libstdc++
#endif
#if defined(_GLIBCXX_RELEASE)
    r.glibcxx_release = _GLIBCXX_RELEASE;
#else
    r.glibcxx_release = -1;
#endif
#if defined(_GLIBCXX_DEBUG)
    r.glibcxx_debug = 1;
#else
    r.glibcxx_debug = 0;
#endif
    r.glm_version = GLM_VERSION;
    r.glm_config = plugin_glm_config();
    r.size_vec3 = sizeof(Vec3);
    r.align_vec3 = alignof(Vec3);
    r.size_vec4 = sizeof(Vec4);
    r.align_vec4 = alignof(Vec4);
    r.size_mat4 = sizeof(Mat4);
    r.size_std_string = sizeof(std::string);
    r.size_std_function = sizeof(std::function<void()>);
    r.size_shared_ptr = sizeof(std::shared_ptr<const Texture>);
    r.size_params = sizeof(Params);
    r.size_registry = sizeof(MaterialRegistry);
    r.size_texture_lookup = sizeof(TextureLookup);
    r.size_surface_terms = sizeof(SurfaceTerms);
    r.description = description;
    return r;
}

/// \brief The registries as C++ references, inside a module's registration function.
struct PluginRegistries {
    MaterialRegistry& materials;
    TextureRegistry& textures;
    LightRegistry& lights;
};

/// The body of a module's rtlab_plugin_register: calls `fill(PluginRegistries&)` and turns any exception into
/// the error text and a non-zero result, so that none unwinds through the C entry point.
template <class Fill>
int plugin_register(const RtlabPluginRegistries* registries, char* error, std::size_t error_size,
                    Fill&& fill) noexcept {
    auto fail = [&](const char* message) {
        if (error && error_size > 0) {
            const std::size_t n = std::min(std::strlen(message), error_size - 1);
            std::memcpy(error, message, n);
            error[n] = '\0';
        }
        return 1;
    };
    if (!registries || registries->abi_version != RTLAB_PLUGIN_ABI_VERSION || !registries->materials ||
        !registries->textures || !registries->lights)
        return fail("the host passed no registries or registries of another plugin ABI version");
    try {
        PluginRegistries r{*static_cast<MaterialRegistry*>(registries->materials),
                           *static_cast<TextureRegistry*>(registries->textures),
                           *static_cast<LightRegistry*>(registries->lights)};
        fill(r);
        return 0;
    } catch (const std::exception& e) {
        return fail(e.what());
    } catch (...) {
        return fail("an exception that is not a std::exception");
    }
}

}  // namespace rtlab

/// Defines both entry points of a module: rtlab_plugin_query returns the record of this compilation with
/// `description`, and rtlab_plugin_register calls `fill(rtlab::PluginRegistries&)` through
/// rtlab::plugin_register. `fill` names a function (or a lambda variable): a lambda written inline would
/// split into macro arguments at its first top-level comma. Use it once per module, at namespace scope.
#define RTLAB_DEFINE_PLUGIN(description, fill)                                                          \
    RTLAB_PLUGIN_EXPORT const RtlabPluginRecord* rtlab_plugin_query(void) {                             \
        static const RtlabPluginRecord record = ::rtlab::make_plugin_record(description);               \
        return &record;                                                                                 \
    }                                                                                                   \
    RTLAB_PLUGIN_EXPORT int rtlab_plugin_register(const RtlabPluginRegistries* registries, char* error, \
                                                  size_t error_size) {                                  \
        return ::rtlab::plugin_register(registries, error, error_size, fill);                           \
    }
