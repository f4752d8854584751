#pragma once
/// \brief Escape-time iteration of the Mandelbrot set with the continuous (smooth) iteration count.

namespace rtlab {

/// \brief Result of iterating z <- z^2 + c from z_0 = 0.
struct MandelbrotEscape {
    bool inside = true;  ///< no z_n with |z_n| > escape radius for n <= max_iterations
    int iterations = 0;  ///< the first n with |z_n| > R, or max_iterations when inside
    /// Continuous count mu = n - log2(ln|z_n| / ln R), in (n - 1, n] for a large R: when |z_n| only just
    /// passes R, mu is n; when it only just misses, the next step gives |z_{n+1}| ~ R^2 and mu ~ n again,
    /// so mu has no steps where n does. Equal to max_iterations inside the set.
    double smooth = 0.0;
};

/// max_iterations >= 1 and escape_radius >= 2 (a smaller radius would call escaping points inside);
/// the texture checks both, this function assumes them.
MandelbrotEscape mandelbrot_escape(double c_re, double c_im, int max_iterations, double escape_radius);

}  // namespace rtlab
