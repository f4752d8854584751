// Adaptive quadrature over (cos theta, phi) rectangles, graded towards hinted directions, kinks and jumps.
#include <rtlab/shading_testing/sphere_quadrature.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>

namespace rtlab::shading_testing {

namespace {

constexpr double kNegligible = 1e-10;  // a probability below which a kink or jump is not worth finding
// A jump along a long rim costs many rules to meet a tolerance (the error falls only as the pieces' width); the
// budget keeps it from hanging a test.
constexpr long kBudget = 40000;      // rules per starting rectangle
constexpr double kHintReach = 0.05;  // radians
constexpr double kGrading = 0.25;
// A change of slope across the nodes (times their spacing) above this fraction of the largest value is taken for
// a kink or a jump inside the piece; the rule may then err by up to kStepError of it times the area (the 5-point
// rule's largest outer weight, what it can miss of a step).
constexpr double kBend = 0.05;
constexpr double kStepError = 0.12;

}  // namespace

Vec3 direction_at(double c, double phi) {
    const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
    return {static_cast<float>(s * std::cos(phi)), static_cast<float>(s * std::sin(phi)), static_cast<float>(c)};
}

/// A rectangle, its halves, the rule on each half, and the error estimate.
struct SphereQuadrature::Piece {
    Rect r, a, b;
    Rule rule_a, rule_b;
    double value = 0.0, error = 0.0;
};

namespace {

// Angular extents: along theta, and along phi at the widest circle of latitude in the rectangle.
template <class R>
double theta_extent(const R& r) {
    return std::acos(std::clamp(r.c0, -1.0, 1.0)) - std::acos(r.c1);
}
template <class R>
double phi_extent(const R& r) {
    const double c_min = (r.c0 <= 0.0 && r.c1 >= 0.0) ? 0.0 : std::min(std::abs(r.c0), std::abs(r.c1));
    return (r.phi1 - r.phi0) * std::sqrt(std::max(0.0, 1.0 - c_min * c_min));
}

/// A number in [0, 1) from two coordinates: deterministic, so every run integrates alike.
double unit_hash(double x, double y) {
    std::uint64_t a, b;
    std::memcpy(&a, &x, sizeof a);
    std::memcpy(&b, &y, sizeof b);
    std::uint64_t h = a * 0x9e3779b97f4a7c15ULL ^ (b + 0x632be59bd9b4e019ULL);
    h ^= h >> 31;
    h *= 0xbf58476d1ce4e5b9ULL;
    h ^= h >> 29;
    return static_cast<double>(h >> 11) * 0x1p-53;
}

}  // namespace

SphereQuadrature::SphereQuadrature(Density f, std::vector<Vec3> hints, double tolerance, double relative_tolerance,
                                   double hint_size)
    : m_f(std::move(f)),
      m_hints(std::move(hints)),
      m_tolerance(tolerance),
      m_relative_tolerance(relative_tolerance),
      m_hint_size(hint_size) {}

double SphereQuadrature::integrate(double c0, double c1, double phi0, double phi1) const {
    std::vector<Piece> heap;
    std::vector<Piece> hinted{make_piece({c0, c1, phi0, phi1}, rule({c0, c1, phi0, phi1}))};
    long budget = kBudget;
    // First resolve the hints, whatever the error estimates say (they cannot see a lobe between nodes).
    while (!hinted.empty()) {
        const Piece p = hinted.back();
        hinted.pop_back();
        const double size = std::max(theta_extent(p.r), phi_extent(p.r));
        // Graded around the hints: a piece may be at most a quarter of its distance from one across (within
        // kHintReach of it), so a lobe of any width centred there, even one stretched a hundredfold at grazing
        // incidence, is crossed by several nodes.
        const double d = hint_distance(p.r);
        const bool split = d < kHintReach && size > std::max(m_hint_size, kGrading * d);
        if (!split || (budget -= 4) <= 0) {
            heap.push_back(p);
            continue;
        }
        hinted.push_back(make_piece(p.a, p.rule_a));
        hinted.push_back(make_piece(p.b, p.rule_b));
    }
    const auto by_error = [](const Piece& x, const Piece& y) { return x.error < y.error; };
    std::make_heap(heap.begin(), heap.end(), by_error);
    double value = 0.0, error = 0.0;
    for (int step = 0;; ++step) {
        if (step % 256 == 0) {  // sums kept by updates, summed afresh now and then against drift
            value = error = 0.0;
            for (const Piece& p : heap) {
                value += p.value;
                error += p.error;
            }
        }
        if (error <= std::max(m_tolerance, m_relative_tolerance * std::abs(value)) || (budget -= 4) <= 0) return value;
        std::pop_heap(heap.begin(), heap.end(), by_error);
        const Piece worst = heap.back();
        heap.pop_back();
        value -= worst.value;
        error -= worst.error;
        for (const Piece& child : {make_piece(worst.a, worst.rule_a), make_piece(worst.b, worst.rule_b)}) {
            value += child.value;
            error += child.error;
            heap.push_back(child);
            std::push_heap(heap.begin(), heap.end(), by_error);
        }
    }
}

double SphereQuadrature::integrate_sphere(int n_c, int n_phi) const {
    double sum = 0.0;
    for (int i = 0; i < n_c; ++i)
        for (int j = 0; j < n_phi; ++j)
            sum += integrate(-1.0 + 2.0 * i / n_c, -1.0 + 2.0 * (i + 1) / n_c, 2.0 * std::numbers::pi * j / n_phi,
                             2.0 * std::numbers::pi * (j + 1) / n_phi);
    return sum;
}

SphereQuadrature::Piece SphereQuadrature::make_piece(const Rect& r, const Rule& whole) const {
    Piece p{r, r, r, {}, {}};
    // Split near the middle, at 0.4 to 0.6 of the way by a hash of the piece: halving exactly would put a feature
    // at constant cos theta or phi (the rim of a lobe centred on the normal) at the same place in every piece
    // along it, where the rules on the whole and the halves may err alike, every piece fooling its error
    // estimate the same way. Spread over places, the estimates are right on the whole.
    const double t = 0.4 + 0.2 * unit_hash(r.c0 + 3.0 * r.c1, r.phi0 + 5.0 * r.phi1);
    if (theta_extent(r) >= phi_extent(r)) {
        p.a.c1 = p.b.c0 = r.c0 + t * (r.c1 - r.c0);
    } else {
        p.a.phi1 = p.b.phi0 = r.phi0 + t * (r.phi1 - r.phi0);
    }
    p.rule_a = rule(p.a);
    p.rule_b = rule(p.b);
    p.value = p.rule_a.value + p.rule_b.value;
    // Where a half holds a kink or a jump, the rules on the whole and on the halves can err alike, and their
    // difference says little: the error is then taken as at least what the 5-point rule can miss of it.
    p.error = std::max(std::abs(p.value - whole.value), kStepError * (p.rule_a.feature + p.rule_b.feature));
    return p;
}

SphereQuadrature::Rule SphereQuadrature::rule(const Rect& r) const {
    // 5-point Gauss-Legendre nodes and weights on [-1, 1].
    static constexpr double kX[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                                     0.9061798459386640};
    static constexpr double kW[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                                     0.2369268850561891};
    const double hc = 0.5 * (r.c1 - r.c0), mc = 0.5 * (r.c1 + r.c0);
    const double hp = 0.5 * (r.phi1 - r.phi0), mp = 0.5 * (r.phi1 + r.phi0);
    double v[5][5];
    double sum = 0.0;
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j) {
            v[i][j] = m_f(direction_at(mc + hc * kX[i], mp + hp * kX[j]));
            sum += kW[i] * kW[j] * v[i][j];
        }
    // Kinks and jumps, which the error estimate can miss (the rules on the whole and on the halves may err
    // alike): the largest change of slope along the rows and columns of nodes, times the spacing, is the size of
    // a jump between two nodes or of a kink's change of slope across the piece, and about f'' h^2 for a smooth
    // density (small once the piece resolves it). The nodes leave a margin of 4.7% of the piece along each side,
    // where a rim parallel to the side (a lobe's rim at constant cos theta when it is centred on the normal) would
    // hide from every piece that holds it; points beside the midpoints of the four sides narrow it to 0.5% along
    // the middle row and column. Not on the sides themselves: a density may jump exactly there (at the horizon,
    // cos theta = 0, a side of every cell), which is no feature inside the piece.
    constexpr double kSide = 0.99;
    const double below_c = m_f(direction_at(mc - hc * kSide, mp)), above_c = m_f(direction_at(mc + hc * kSide, mp));
    const double below_phi = m_f(direction_at(mc, mp - hp * kSide)), above_phi = m_f(direction_at(mc, mp + hp * kSide));
    double largest = std::max({below_c, above_c, below_phi, above_phi});
    for (const auto& row : v)
        for (double x : row) largest = std::max(largest, x);
    double bend = 0.0;
    const auto line = [&](const double* x, const double* y, int n) {
        for (int k = 1; k + 1 < n; ++k) {
            const double slope_change = (y[k + 1] - y[k]) / (x[k + 1] - x[k]) - (y[k] - y[k - 1]) / (x[k] - x[k - 1]);
            bend = std::max(bend, std::abs(slope_change) * 0.5 * (x[k + 1] - x[k - 1]));
        }
    };
    static constexpr double kX7[7] = {-kSide, kX[0], kX[1], kX[2], kX[3], kX[4], kSide};
    for (int i = 0; i < 5; ++i) {
        const double column[5] = {v[0][i], v[1][i], v[2][i], v[3][i], v[4][i]};
        line(kX, v[i], 5);
        line(kX, column, 5);
    }
    const double middle_c[7] = {below_c, v[0][2], v[1][2], v[2][2], v[3][2], v[4][2], above_c};
    const double middle_phi[7] = {below_phi, v[2][0], v[2][1], v[2][2], v[2][3], v[2][4], above_phi};
    line(kX7, middle_c, 7);
    line(kX7, middle_phi, 7);
    const double area = 4.0 * hc * hp;
    const bool feature = bend > kBend * largest && bend * area > kNegligible;
    return {sum * hc * hp, feature ? bend * area : 0.0};
}

// The angle from the nearest hint to the rectangle (0 inside it), by clamping the hint's (cos, phi) into it.
double SphereQuadrature::hint_distance(const Rect& r) const {
    // In double, by atan2 of the cross and dot products: acos of a float dot product could not tell angles
    // below 3e-4 apart, and every piece near a hint would look as if it held it.
    const auto angle = [](const glm::dvec3& a, const glm::dvec3& b) {
        return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
    };
    const auto at = [](double c, double phi) {
        const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
        return glm::dvec3(s * std::cos(phi), s * std::sin(phi), c);
    };
    double best = std::numbers::pi;
    for (const Vec3& hint : m_hints) {
        const glm::dvec3 h = glm::normalize(glm::dvec3(hint));
        const double c = std::clamp(h.z, r.c0, r.c1);
        double phi = std::atan2(h.y, h.x);
        if (phi < 0.0) phi += 2.0 * std::numbers::pi;
        // Either way round in phi.
        best = std::min({best, angle(at(c, std::clamp(phi, r.phi0, r.phi1)), h),
                         angle(at(c, std::clamp(phi - 2.0 * std::numbers::pi, r.phi0, r.phi1)), h)});
    }
    return best;
}

}  // namespace rtlab::shading_testing
