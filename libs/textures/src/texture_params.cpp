#include "texture_params.hpp"

namespace rtlab::detail {

ColorEncoding get_encoding(const Params& params) {
    return one_of(params, "encoding", "srgb", {"srgb", "linear"}) == "srgb" ? ColorEncoding::srgb
                                                                            : ColorEncoding::linear;
}

void add_encoding(TypeSpec& spec) {
    spec.add("encoding", ParamKind::word, "how an 8-bit file's values are decoded")
        .defaults("srgb")
        .allow({"srgb", "linear"});
}

void add_two_colours(TypeSpec& spec, const std::string& what1, const std::string& default1, const std::string& what2,
                     const std::string& default2) {
    spec.add("color1", ParamKind::texture, what1).defaults(default1);
    spec.add("color2", ParamKind::texture, what2).defaults(default2);
}

void add_image_options(TypeSpec& spec, const std::string& bake_size_doc, const std::string& bake_size) {
    add_encoding(spec);
    spec.add("intensity", ParamKind::number, "multiplies every value").defaults("1").at_least(0);
    spec.add("lod", ParamKind::number,
             "a pyramid of box-filtered levels, looked up between the two around lod (default: none; \"auto\": "
             "from the size on screen)")
        .range(0, 64);
    spec.add("bake", ParamKind::texture, "a texture baked into an image instead of reading files");
    spec.add("bake_size", ParamKind::numbers, bake_size_doc).defaults(bake_size);
}

}  // namespace rtlab::detail
