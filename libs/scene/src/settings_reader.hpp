#pragma once
// Private to the scene loader: /camera and /render, with the command line's overrides.
#include <rtlab/render/thin_lens_camera.hpp>

#include "load_context.hpp"

#include <optional>

namespace rtlab::scene_detail {

/// The camera's placement and lens (its image size comes from /render); nullopt when missing or wrong.
struct CameraRead {
    CameraSpec spec;
    bool thin_lens = false;
    LensSpec lens;
};
std::optional<CameraRead> read_camera(LoadContext& ctx, const Json& doc);

/// /render: image size, sampling, depth, background or skybox, tone operator, output; then builds the camera
/// with the final size into ctx.out.job.camera and ctx.camera.
void read_render(LoadContext& ctx, const Json& doc, const std::optional<CameraRead>& camera);

}  // namespace rtlab::scene_detail
