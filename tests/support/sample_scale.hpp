#pragma once
// How much smaller the Monte Carlo tests make their sample counts, and the exactness tests their meshes, in this
// build.

namespace rtlab::test {

/// Fewer samples under the sanitizers, where every evaluation costs ten times as much; the statistics stay
/// valid (only their power drops).
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_UNDEFINED__)
inline constexpr int kSampleScale = 5;
inline constexpr bool kSanitized = true;
#else
inline constexpr int kSampleScale = 1;
inline constexpr bool kSanitized = false;
#endif

}  // namespace rtlab::test
