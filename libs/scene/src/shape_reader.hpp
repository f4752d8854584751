#pragma once
// Private to the scene loader: the shapes list — each shape with its material, placement and flags — and
// the materials it names or writes inline.
#include <rtlab/render/scene.hpp>

#include "load_context.hpp"

#include <memory>
#include <string>
#include <vector>

namespace rtlab::scene_detail {

/// A material with the textures it uses (their own textures included); nullptr when it cannot be built.
std::shared_ptr<const Material> read_material(LoadContext& ctx, const Json& m, const std::string& p, bool named);

/// One element of /shapes: appended to `objects` when it is visible and built; named shapes are kept in
/// ctx.shapes for instances.
void read_shape(LoadContext& ctx, const Json& s, const std::string& p, std::vector<SceneObject>& objects);

/// A "transform": {"translate", "rotate", "scale"}, {"matrix"}, or a list of them (the first applied first).
std::optional<Mat4> read_transform(LoadContext& ctx, const Json& v, const std::string& p);

}  // namespace rtlab::scene_detail
