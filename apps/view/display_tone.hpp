#pragma once
// What the viewer's fragment shader does to a linear pixel, as numbers the CPU computes: the exposure, the tone
// operator's image statistics (over the rendered pixels only) and the same mapping on the CPU, which saves PNGs
// and which the tests compare with rtlab's own tone operators.
#include <rtlab/core/color.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace rtlab::view {

/// The operators the window offers, in the order of its list (the shader's `u_operator`).
enum class ToneChoice { none = 0, reinhard = 1, ward = 2, aces = 3 };
const std::vector<std::string>& tone_choice_names();
/// "none", "reinhard", "ward" or "aces" to the choice; false for another name.
bool parse_tone_choice(const std::string& name, ToneChoice& out);

/// The shader's uniforms: display = op(linear * 2^stops), sRGB-encoded by the exact piecewise curve.
struct ToneParams {
    ToneChoice op = ToneChoice::none;
    float scale = 1.0f;       ///< 2^stops times the operator's own scale (Reinhard key / L_avg, Ward's m)
    float inv_white2 = 0.0f;  ///< Reinhard: 1 / L_white^2 (0: infinite white)
};

/// Computes the parameters from the rendered pixels (`rgb`: 3 floats per pixel; pixels whose `rendered` entry is 0
/// are left out; an empty `rendered` takes every pixel), with rtlab's defaults: Reinhard key 0.18 and white the
/// largest scaled luminance, Ward ldmax 100. Exposure scales the image before the statistics are taken, so
/// Reinhard's and Ward's scale absorb it except through their delta and L_dmax terms.
ToneParams tone_params(ToneChoice op, float stops, const std::vector<float>& rgb,
                       const std::vector<std::uint8_t>& rendered = {});

/// The shader's mapping on the CPU: linear display value in [0, 1] before sRGB encoding.
RGB tone_map(const ToneParams& params, const RGB& linear);

}  // namespace rtlab::view
