#include "texture_params.hpp"

#include <rtlab/core/error.hpp>

namespace rtlab::detail {

ColorEncoding get_encoding(const Params& params) {
    return one_of(params, "encoding", "srgb", {"srgb", "linear"}) == "srgb" ? ColorEncoding::srgb
                                                                            : ColorEncoding::linear;
}

std::shared_ptr<const Texture> colour_or_texture(const Params& params, std::string_view colour_name,
                                                 std::string_view texture_name, const RGB& fallback) {
    auto texture = params.get_object<Texture>(texture_name);
    if (texture && params.has(colour_name))
        fail_param(params, colour_name, "and '" + std::string(texture_name) + "' are both given; give one");
    if (texture) return texture;
    return make_constant(finite_rgb(params, colour_name, fallback));
}

}  // namespace rtlab::detail
