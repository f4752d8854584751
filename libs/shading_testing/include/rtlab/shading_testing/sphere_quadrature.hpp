#pragma once
/// \brief Adaptive quadrature of a density over the sphere of directions, in (cos theta, phi) rectangles.
#include <rtlab/core/math.hpp>

#include <functional>
#include <vector>

namespace rtlab::shading_testing {

/// The unit direction with cos(theta) = c and azimuth phi (theta from +z).
Vec3 direction_at(double c, double phi);

/// \brief Integrates a density over solid angle on a rectangle of (cos theta, phi), where d omega = d cos d phi
/// (no Jacobian).
///
/// Globally adaptive: each piece is integrated by 5 x 5 Gauss-Legendre on each of its halves (split along its
/// longer side in angle), the difference from the rule on the whole being its error estimate, and the piece
/// with the largest error is split next until the errors sum below the tolerance (absolute, or relative to the
/// value). A lobe narrower than the first nodes' spacing would fall between them, so pieces near a "hint" (a
/// direction where a narrow lobe peaks: the mirror and refracted directions) are first split into a mesh graded
/// towards it, down to hint_size radians across: lobes of roughness 1e-3 and exponents of 1e4 are then found,
/// whichever cell they peak in. A kink or a jump inside a piece (the rim of a lobe that ends within the cell: a
/// cone, a rough dielectric's microfacets turning away from the viewer) can fool the error estimate, the rules
/// on the whole and on the halves erring alike; a piece whose nodes show one is given at least the error the
/// rule can make of it, so that it is split until that is small. A jump converges slowly (the error falls as
/// the piece's width, not a power of it): a density that jumps by J along a rim of length L radians costs about
/// J L / tolerance rules, up to a budget of 40000 rules a call, where the value is good to about 1e-5 of J L.
class SphereQuadrature {
public:
    using Density = std::function<double(const Vec3&)>;

    /// tolerance is absolute, relative_tolerance of the value: either suffices.
    SphereQuadrature(Density f, std::vector<Vec3> hints, double tolerance = 1e-7, double relative_tolerance = 1e-5,
                     double hint_size = 1e-5);

    /// The integral over c0 <= cos theta <= c1, phi0 <= phi <= phi1.
    double integrate(double c0, double c1, double phi0, double phi1) const;
    /// The integral over the whole sphere, on a grid of n_c x n_phi starting rectangles.
    double integrate_sphere(int n_c = 8, int n_phi = 16) const;

private:
    struct Rect {
        double c0, c1, phi0, phi1;
    };
    struct Piece;
    struct Rule {
        double value = 0.0;
        double feature = 0.0;  // a kink's or a jump's size times the area where the nodes show one, else 0
    };
    Piece make_piece(const Rect& r, const Rule& whole) const;
    Rule rule(const Rect& r) const;
    double hint_distance(const Rect& r) const;

    Density m_f;
    std::vector<Vec3> m_hints;
    double m_tolerance, m_relative_tolerance, m_hint_size;
};

}  // namespace rtlab::shading_testing
