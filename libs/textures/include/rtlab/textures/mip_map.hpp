#pragma once
/// \brief Image pyramids for textures filtered to their size on screen, and baking a texture into an image.
///
/// A texture seen from far away covers many texels per pixel; point-sampling it then aliases (a planet a
/// few pixels wide shimmers from frame to frame). The textures that know their texel grid (image, cubemap)
/// keep a box-filtered pyramid and are looked up at a level of detail (lod) set before rendering: level k is
/// 2^k times coarser than level 0, and a fractional lod blends the two levels around it (trilinear).
/// The renderer traces rays without differentials, so the level is one per texture, worked out from the
/// camera and the objects that use it (rtlab/render/texture_level.hpp, and "lod": "auto" in scene files).
#include <rtlab/core/image.hpp>
#include <rtlab/textures/texture.hpp>

#include <array>
#include <memory>
#include <vector>

namespace rtlab {

/// Half the width and height (at least 1), each output texel the mean of the 2 x 2 (at an odd edge, fewer
/// distinct) texels it covers, alpha included. Linear values in, linear values out.
Image downsample(const Image& image);

/// Level 0 and its downsampled levels down to 1 x 1: level k is 2^k times smaller in each direction.
std::vector<std::shared_ptr<const Image>> mip_levels(std::shared_ptr<const Image> level0);

/// \brief A texture whose level of detail is chosen from outside: image and cubemap textures made with
/// a "lod". set_lod is not thread-safe: call it before rendering, never during.
class LevelOfDetail {
public:
    virtual ~LevelOfDetail() = default;
    /// lod >= 0, clamped to the coarsest level; non-finite or negative values are taken as 0.
    virtual void set_lod(float lod) = 0;
    virtual float lod() const = 0;
    /// Texels of level 0 along u (an image's width, a cube face's side): what the level is worked out from.
    virtual int texels_u() const = 0;
};

/// The two levels a lod falls between and the blend weight of the finer one's neighbour:
/// value = level[first] * (1 - blend) + level[second] * blend.
struct LevelBlend {
    int first = 0, second = 0;
    float blend = 0.0f;
};
LevelBlend level_blend(float lod, int level_count);

/// An image of `width` x `height` of a texture evaluated at texel centres, for a texture that should
/// behave like an image file (filtered by levels, wrapped, tiled). Each lookup carries uv (v up, v = 0 the
/// bottom row) and, for solid textures, point = direction = the point of the unit sphere with that
/// longitude and latitude in rtlab::Sphere's own uv mapping, so a solid texture baked for a sphere has no
/// seam at u = 0.
Image bake_texture(const Texture& texture, int width, int height);

/// Six square faces of `size` (px nx py ny pz nz) of a texture evaluated by direction at the texel
/// centres, in CubeMapTexture's face convention.
std::array<Image, 6> bake_cube_faces(const Texture& texture, int size);

}  // namespace rtlab
