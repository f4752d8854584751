#pragma once
/// \brief The texture interface, the lookup it answers, and the registry that creates textures by name.
#include <rtlab/core/color.hpp>
#include <rtlab/core/math.hpp>
#include <rtlab/core/registry.hpp>

namespace rtlab {

/// \brief Everything a texture may look at: surface uv, the object-space point (solid textures) and
/// the direction (environment maps). A caller fills what it has; each texture documents what it reads.
struct TextureLookup {
    Vec2 uv{0.0f};                     ///< surface coordinates; u to the right, v up (v = 0 is an image's bottom row)
    Point3 point{0.0f};                ///< object-space point, for solid textures (checker3d, 3D noise)
    Vec3 direction{0.0f, 0.0f, 1.0f};  ///< lookup direction for environment maps (need not be unit length)
};

/// \brief A colour as a function of a TextureLookup. eval is const and thread-safe.
class Texture {
public:
    virtual ~Texture() = default;
    virtual RGB eval(const TextureLookup& lookup) const = 0;
    /// The colour of a texture that is the same everywhere, or nullptr: lets a caller read a constant
    /// once instead of calling eval at every hit.
    virtual const RGB* constant() const { return nullptr; }
    /// Whether alpha() carries information (an image file with an alpha channel); see opacity() in
    /// rtlab/textures/texture_param.hpp for how materials use it.
    virtual bool has_alpha() const { return false; }
    /// Coverage in [0, 1] at the lookup (straight, not premultiplied); 1 for textures without alpha.
    virtual float alpha(const TextureLookup&) const { return 1.0f; }
};

/// Nested textures travel inside Params as objects under the same key a constant colour would use:
/// params.set_object<Texture>("color1", t); see rtlab/textures/texture_param.hpp.
using TextureRegistry = Registry<Texture>;

/// Registers every built-in texture by name: solid, checker, checker3d, mandelbrot, perlin, simplex,
/// image, cubemap, stars. Each registration's doc() lists its parameters and their defaults. A plugin adds its
/// own textures to the same registry with TextureRegistry::add, without touching this library.
void register_builtins(TextureRegistry& registry);

/// A registry with category "texture" and every built-in registered.
TextureRegistry make_texture_registry();

}  // namespace rtlab
