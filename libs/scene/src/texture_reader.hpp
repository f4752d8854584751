#pragma once
// Private to the scene loader: textures, named in /textures or written inline where a colour may be, with
// the two things the loader adds to any texture type: a "fallback" baked in place of files that are not
// found, and "lod": "auto" for textures with levels of detail.
#include "load_context.hpp"

#include <memory>
#include <string>

namespace rtlab::scene_detail {

/// A texture object (named: it has a "name" key, read by the caller). The textures it uses are noted in
/// ctx.texture_uses. nullptr when it cannot be built (reported).
std::shared_ptr<Texture> read_texture(LoadContext& ctx, const Json& v, const std::string& p, bool named);

/// Sets the level of every "lod": "auto" texture: the finest any shape using it (or the sky) asks for.
void set_auto_levels(LoadContext& ctx);

}  // namespace rtlab::scene_detail
