#pragma once
// How much smaller the Monte Carlo tests make their sample counts in this build.

namespace rtlab::test {

/// Fewer samples under the sanitizers, where every evaluation costs ten times as much; the statistics stay
/// valid (only their power drops).
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_UNDEFINED__)
inline constexpr int kSampleScale = 5;
#else
inline constexpr int kSampleScale = 1;
#endif

}  // namespace rtlab::test
