#pragma once
/// \brief The 1980 Whitted scene built in code (rtlab-whitted), so that a test can build the same one.
#include <rtlab/render/render_job.hpp>

namespace rtlab::whitted {

/// The scene's fixed points, for tests that look at the image.
inline constexpr float kBoardHalfWidth = 4.0f;

/// The scene of Whitted's "An improved illumination model for shaded display" (1980) in the course's classic
/// convention: a mirror sphere and a hollow glass sphere (a shell of glass around air: an outer sphere with
/// index 1.5 inside, an inner one with index 1 inside and 1.5 outside) over a red and yellow checkerboard,
/// under a blue sky, lit by a point light and an ambient term. Shadows through the glass are transparent.
/// Renders with adaptive anti-aliasing (POV-Ray's default threshold 0.3, depth 3) and recursion depth 8.
RenderJob make_whitted_job(int width, int height);

}  // namespace rtlab::whitted
