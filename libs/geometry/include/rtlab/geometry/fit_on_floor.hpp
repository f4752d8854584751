#pragma once
/// \brief The transform that scales a model to a given size and stands it on the floor.
#include <rtlab/core/aabb.hpp>
#include <rtlab/core/math.hpp>

namespace rtlab {

/// Scales `box` uniformly so that its largest extent is `size`, centred over the origin in x and z, its
/// lowest point on y = 0 (a model of any units standing on a floor). Throws rtlab::Error for an empty or
/// flat-to-a-point box or a size that is not positive. Used by rtlab-bunny and by the scene loader's mesh key
/// "fit", so that both place a mesh with the very same matrix.
Mat4 fit_on_floor(const AABB& box, float size);

/// The uniform scale fit_on_floor applies: size / the largest extent of `box`.
float fit_scale(const AABB& box, float size);

}  // namespace rtlab
