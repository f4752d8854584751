#pragma once
// Test helpers: a camera whose rays carry their image position, and analytic images defined on it.
#include <rtlab/render/camera.hpp>
#include <rtlab/render/radiance_source.hpp>

#include <algorithm>
#include <cmath>

namespace rtlab::test {

/// Rays start at (x, y, 0) for image position (x, y), so a radiance function sees the image position
/// exactly (no projection rounding); the lens sample goes into the direction's x, y for tests that
/// check it.
class ImagePlaneCamera final : public Camera {
public:
    ImagePlaneCamera(int w, int h) : m_w(w), m_h(h) {}
    Ray generate_ray(Vec2 image, Vec2 lens) const override {
        return Ray{Point3(image.x, image.y, 0.0f), Vec3(lens, 1.0f)};
    }
    int width() const override { return m_w; }
    int height() const override { return m_h; }

private:
    int m_w, m_h;
};

/// The half-plane y < slope * x + offset, with an irrational slope so that no pixel row repeats.
struct HalfPlane {
    double slope = 1.0 / std::sqrt(2.0);
    double offset = 3.0 + 1.0 / std::sqrt(3.0);

    bool inside(double x, double y) const { return y < slope * x + offset; }

    /// Exact area of pixel [x0, x0 + 1] x [y0, y0 + 1] inside: the integral over x of
    /// clamp(slope x + offset - y0, 0, 1), piecewise linear, so the trapezoid rule is exact on each piece.
    double coverage(int x0, int y0) const {
        auto f = [&](double x) { return std::clamp(slope * x + offset - y0, 0.0, 1.0); };
        double cuts[4] = {double(x0), (y0 - offset) / slope, (y0 + 1 - offset) / slope, double(x0 + 1)};
        std::sort(cuts + 1, cuts + 3);
        double area = 0.0, prev = x0;
        for (double c : cuts) {
            c = std::clamp(c, double(x0), double(x0 + 1));
            area += 0.5 * (f(prev) + f(c)) * (c - prev);
            prev = c;
        }
        return area;
    }
};

}  // namespace rtlab::test
