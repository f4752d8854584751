// Texture "mandelbrot": the Mandelbrot set over a window of the complex plane, read from lookup.uv.
//
// c = center + (uv - 0.5) * 3 / zoom, so zoom 1 shows a 3 x 3 window (the whole set with the default
// centre); u runs along the real axis, v along the imaginary axis (up). Points whose orbit stays within
// escape_radius for `iterations` steps get `inside`. Escaping points are coloured by the continuous
// iteration count mu (see mandelbrot.hpp), t = ln(1 + mu) / ln(1 + iterations) in [0, 1], blended from
// `outside` (t = 0, fast escape) to `edge` (t = 1, next to the set). With smooth = false, mu is the
// integer count n, which gives the classic stepped bands.
//
// Parameters
//   iterations      iteration limit, 1 .. 1000000                 default 256
//   escape_radius   >= 2; large values make the smooth count closer to exact   default 256
//   center          [re, im]                                      default [-0.5, 0]
//   zoom            > 0                                           default 1
//   inside          colour inside the set                         default 0
//   outside         colour of points that escape at once          default [0.0, 0.02, 0.1]
//   edge            colour of points that escape last             default [1, 0.8, 0.3]
//   smooth          continuous colouring                          default true
#include <rtlab/textures/mandelbrot.hpp>

#include "texture_params.hpp"

#include <algorithm>
#include <cmath>

namespace rtlab {

MandelbrotEscape mandelbrot_escape(double c_re, double c_im, int max_iterations, double escape_radius) {
    const double r2 = escape_radius * escape_radius;
    double x = 0.0, y = 0.0;
    for (int n = 1; n <= max_iterations; ++n) {
        const double xn = x * x - y * y + c_re;
        y = 2.0 * x * y + c_im;
        x = xn;
        const double m2 = x * x + y * y;
        if (m2 > r2) {
            // ln|z| = ln(|z|^2) / 2; NaN-free since m2 > r2 >= 4.
            const double mu = n - std::log2(0.5 * std::log(m2) / std::log(escape_radius));
            return {false, n, mu};
        }
        if (!std::isfinite(m2)) return {false, n, static_cast<double>(n)};  // only for a non-finite c
    }
    return {true, max_iterations, static_cast<double>(max_iterations)};
}

namespace detail {

namespace {
class MandelbrotTexture final : public Texture {
public:
    struct Settings {
        int iterations;
        double escape_radius;
        Vec2 center;
        double zoom;
        RGB inside, outside, edge;
        bool smooth;
    };
    explicit MandelbrotTexture(const Settings& s) : m_s(s) {}

    RGB eval(const TextureLookup& q) const override {
        const double width = 3.0 / m_s.zoom;
        const double re = m_s.center.x + (static_cast<double>(q.uv.x) - 0.5) * width;
        const double im = m_s.center.y + (static_cast<double>(q.uv.y) - 0.5) * width;
        if (!std::isfinite(re) || !std::isfinite(im)) return m_s.outside;
        const MandelbrotEscape e = mandelbrot_escape(re, im, m_s.iterations, m_s.escape_radius);
        if (e.inside) return m_s.inside;
        const double mu = std::max(0.0, m_s.smooth ? e.smooth : e.iterations);
        const double t = std::log1p(mu) / std::log1p(static_cast<double>(m_s.iterations));
        return lerp(m_s.outside, m_s.edge, static_cast<float>(std::clamp(t, 0.0, 1.0)));
    }

private:
    Settings m_s;
};
}  // namespace

namespace {
TypeSpec mandelbrot_spec() {
    TypeSpec s("Mandelbrot set over uv, c = center + (uv - 0.5) 3 / zoom, smooth escape-count colouring");
    s.add("iterations", ParamKind::integer, "most iterations per point").defaults("256").range(1, 1000000);
    s.add("escape_radius", ParamKind::number, "|z| beyond which a point has escaped").defaults("256").at_least(2);
    s.add("center", ParamKind::numbers, "[re, im] at the middle of uv").defaults("[-0.5, 0]");
    s.add("zoom", ParamKind::number, "magnification (> 0)").defaults("1").at_least(0);
    s.add("inside", ParamKind::colour, "points that never escape").defaults("0");
    s.add("outside", ParamKind::colour, "points that escape at once").defaults("[0, 0.02, 0.1]");
    s.add("edge", ParamKind::colour, "points that escape last").defaults("[1, 0.8, 0.3]");
    s.add("smooth", ParamKind::boolean, "a continuous escape count instead of bands").defaults("true");
    return s;
}
}  // namespace

void register_mandelbrot(TextureRegistry& registry) {
    registry.add(
        "mandelbrot",
        [](const Params& p) -> std::shared_ptr<Texture> {
            MandelbrotTexture::Settings s{};
            s.iterations = bounded_int(p, "iterations", 256, 1, 1000000);
            s.escape_radius = positive_float(p, "escape_radius", 256.0f);
            if (s.escape_radius < 2.0) fail_param(p, "escape_radius", "must be >= 2 (points would escape too early)");
            s.center = get_vec2(p, "center", Vec2(-0.5f, 0.0f));
            s.zoom = positive_float(p, "zoom", 1.0f);
            s.inside = finite_rgb(p, "inside", RGB(0.0f));
            s.outside = finite_rgb(p, "outside", RGB(0.0f, 0.02f, 0.1f));
            s.edge = finite_rgb(p, "edge", RGB(1.0f, 0.8f, 0.3f));
            s.smooth = p.get_bool("smooth", true);
            return std::make_shared<MandelbrotTexture>(s);
        },
        mandelbrot_spec());
}

}  // namespace detail
}  // namespace rtlab
