// Test module: a plugin whose record differs from the host's in the one field named by the WRONG_* macro
// it is compiled with (tests/render/CMakeLists.txt), as a module built against another rtlab, standard
// library or GLM configuration would. The host must refuse it before calling rtlab_plugin_register.
#include <rtlab/scene/plugin_abi.hpp>

#include <cstdio>

namespace {
RtlabPluginRecord wrong_record() {
    RtlabPluginRecord r = rtlab::make_plugin_record("a module with a wrong record");
#if defined(WRONG_ABI)
    r.abi_version = RTLAB_PLUGIN_ABI_VERSION + 98;
    r.glibcxx_release = 1;  // must not be reported: nothing after the ABI version is read
#elif defined(WRONG_HEADERS)
    r.headers_hash = "0000000000000000000000000000000000000000000000000000000000000000";
#elif defined(WRONG_GLIBCXX)
    r.glibcxx_release -= 1;
#elif defined(WRONG_CXX11_ABI)
    r.glibcxx_use_cxx11_abi = r.glibcxx_use_cxx11_abi == 0 ? 1 : 0;
#elif defined(WRONG_GLM)
    // What GLM_FORCE_DEFAULT_ALIGNED_GENTYPES does to a build: the flag, and 16-byte vec3 and vec4.
    r.glm_config |= RTLAB_GLM_DEFAULT_ALIGNED | RTLAB_GLM_ALIGNED_GENTYPES;
    r.size_vec3 = 16;
    r.align_vec4 = 16;
#elif defined(WRONG_VERSION)
    r.rtlab_version_minor += 1;
#else
#error "define one WRONG_* macro"
#endif
    return r;
}
}  // namespace

RTLAB_PLUGIN_EXPORT const RtlabPluginRecord* rtlab_plugin_query(void) {
    static const RtlabPluginRecord record = wrong_record();
    return &record;
}

RTLAB_PLUGIN_EXPORT int rtlab_plugin_register(const RtlabPluginRegistries*, char* error, size_t error_size) {
    // Reaching this is the bug under test: say so in a way the test recognises.
    std::snprintf(error, error_size, "REGISTER CALLED DESPITE A WRONG RECORD");
    return 1;
}
