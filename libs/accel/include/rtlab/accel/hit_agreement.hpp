#pragma once
/// \brief The one rule by which two closest-hit answers to the same ray count as the same hit (tests and
/// rtlab-accel's mismatch count alike).
#include <rtlab/accel/accelerator.hpp>

namespace rtlab {

/// Relative tolerance on t: far above the rounding of the library's triangle tests (a few ulps of float),
/// far below the relative depth between two surfaces of a mesh worth telling apart.
inline constexpr double kSameHitTolerance = 1e-4;

/// Whether answer a (hit_a, a) and answer b (hit_b, b) to one ray are the same hit:
/// - both miss (their records are not looked at), or
/// - both hit and |a.t - b.t| <= kSameHitTolerance * max(|a.t|, |b.t|), whatever their primitives;
/// a t that is not finite matches only an identical t, and NaN matches nothing.
///
/// The primitive is not compared on purpose: two triangles sharing an edge or lying on top of each other
/// are hit at one t, and either is a right answer; a wrong primitive at any other t fails the t test.
/// The tolerance is purely relative, with no absolute floor: the verdict then depends neither on the units
/// of the mesh nor on the length of the direction (scaling both leaves it unchanged), where a floor such as
/// max(1, |t|) accepts, for a mesh a thousandth of a unit across, hits a tenth of the mesh apart. Its limit:
/// for a ray that starts on a surface and hits within about 1e-3 of a triangle's size, two triangle tests
/// with different rounding (watertight against Moller-Trumbore) may differ by more than the tolerance.
bool same_hit(bool hit_a, const MeshHit& a, bool hit_b, const MeshHit& b);

}  // namespace rtlab
