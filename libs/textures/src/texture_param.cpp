#include <rtlab/core/param_checks.hpp>
#include <rtlab/textures/texture_param.hpp>

#include "texture_params.hpp"

#include <any>
#include <string>
#include <variant>

namespace rtlab {

std::shared_ptr<const Texture> make_constant_texture(const RGB& colour) { return detail::make_solid(colour); }

namespace {
std::string describe(const Params::Value& v) {
    if (std::holds_alternative<bool>(v)) return "a boolean";
    if (std::holds_alternative<std::string>(v)) return "a string";
    if (const auto* l = std::get_if<Params::List>(&v)) return "a list of " + std::to_string(l->size()) + " numbers";
    return "an object of another type";
}
}  // namespace

std::shared_ptr<const Texture> texture_param(const Params& params, std::string_view name, const RGB& fallback) {
    const Params::Value* v = params.get_value(name);
    if (!v) return make_constant_texture(fallback);
    if (const auto* any = std::get_if<std::any>(v)) {
        std::shared_ptr<const Texture> texture;
        if (const auto* t = std::any_cast<std::shared_ptr<Texture>>(any))
            texture = *t;
        else if (const auto* ct = std::any_cast<std::shared_ptr<const Texture>>(any))
            texture = *ct;
        else
            fail_param(params, name, "must be a colour (one number or a list of 3) or a texture, not " + describe(*v));
        if (!texture) fail_param(params, name, "is a null texture");
        return texture;
    }
    RGB colour;
    if (const auto* n = std::get_if<Params::Number>(v))
        colour = RGB(static_cast<float>(*n));
    else if (const auto* l = std::get_if<Params::List>(v); l && l->size() == 3)
        colour = RGB(static_cast<float>((*l)[0]), static_cast<float>((*l)[1]), static_cast<float>((*l)[2]));
    else
        fail_param(params, name, "must be a colour (one number or a list of 3) or a texture, not " + describe(*v));
    if (!colour.is_finite()) fail_param(params, name, "must be finite");
    return make_constant_texture(colour);
}

std::shared_ptr<const Texture> texture_param(const Params& params, std::string_view name, float fallback) {
    return texture_param(params, name, RGB(fallback));
}

}  // namespace rtlab
