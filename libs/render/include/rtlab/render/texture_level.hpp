#pragma once
/// \brief The level of detail of a filtered texture (rtlab/textures/mip_map.hpp), worked out from the camera
/// and the objects that use it. The renderer traces rays without differentials, so a texture has one level
/// per picture: the one at which a texel of the map covers about one pixel where the object's centre is
/// seen. This is what rtlab-solar-system uses for its planets and what "lod": "auto" means in a scene file,
/// so that the two pick the same levels. What
/// a shape's footprint is (UvFootprint) is the geometry library's: each shape gives its own.
#include <rtlab/core/math.hpp>
#include <rtlab/geometry/uv_footprint.hpp>
#include <rtlab/render/camera.hpp>
#include <rtlab/render/renderer.hpp>

namespace rtlab {

/// The samples per pixel that average texels together: pattern_sample_count for the fixed patterns, 4 for
/// adaptive (its first corners; it refines only at edges).
float filtering_samples(const RenderSettings& settings);

/// The lod of a map `texels_u` texels wide on an object seen by a pinhole `camera`: log2 of the texels one
/// pixel covers at the object's centre (whose distance d gives r / sqrt(d^2 - r^2) as the tangent of the
/// sphere's angular radius), less half of log2(samples) (n samples average n times the texels), at least
/// 0. A camera inside the bounding sphere gives 0.
float surface_texture_lod(const CameraSpec& camera, const UvFootprint& footprint, int texels_u, float samples);

/// The lod of an environment cube map with faces `face_texels` wide: the texels one pixel covers at the
/// centre of the view (a face spans 90 degrees), less half of log2(samples), at least 0.
float environment_texture_lod(const CameraSpec& camera, int face_texels, float samples);

}  // namespace rtlab
