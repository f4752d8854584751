#pragma once
/// \brief Photons and the photon map: photons stored where light paths meet non-specular surfaces, found again by
/// their k nearest neighbours (rtlab::PointKdTree) for a density estimate of the light they carry.
#include <rtlab/accel/point_kd_tree.hpp>
#include <rtlab/core/color.hpp>
#include <rtlab/core/math.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace rtlab {

/// \brief What a photon's path did between the light and the surface it is stored on, by its scattering events:
/// P (pass-through) where it drew a delta lobe, or any lobe at a surface without a diffuse term (glossy only: rough
/// glass, a metal), D (diffuse) where it drew a non-delta lobe at a surface with one: direct = L x (straight from the
/// light), caustic = L P+ x, indirect = L (P|D)* D (P|D)* x. Photons are stored only on surfaces with a diffuse
/// term, where a camera path gathers them (rtlab/render/photon_integrator.hpp).
enum class PhotonPath : std::uint8_t { direct, caustic, indirect };

/// \brief A photon stored at a surface.
struct Photon {
    Point3 position{0.0f};
    Vec3 wi{0.0f, 0.0f, 1.0f};  ///< unit, back towards where the photon came from
    /// The flux it stands for as one sample of the light's whole power: a density estimate divides its sum by the
    /// number of photons shot.
    RGB power;
    std::uint16_t bounces = 0;  ///< scattering events between the light and here (0: direct)
    PhotonPath path = PhotonPath::direct;
};

/// \brief The kernel a density estimate weighs photons by, at distance d within radius r: box 1, cone 1 - d / r
/// (Jensen's cone filter with k = 1), epanechnikov 1 - d^2 / r^2; each normalised over the disk of radius r.
enum class PhotonFilter { box, cone, epanechnikov };
std::optional<PhotonFilter> parse_photon_filter(std::string_view name);
std::string_view photon_filter_name(PhotonFilter filter);

/// The kernel's weight at squared distance d2 within squared radius r2 (0 beyond it).
float photon_filter_weight(PhotonFilter filter, float d2, float r2);
/// The kernel's integral over the disk of squared radius r2: pi r2 (box), pi r2 / 3 (cone), pi r2 / 2 (epanechnikov).
float photon_filter_area(PhotonFilter filter, float r2);

/// \brief Photons with a kd-tree over their positions. Photon i of the list is point i of the tree, so the nearest
/// neighbours are the same photons for any thread count (ties break by index).
class PhotonMap {
public:
    PhotonMap() = default;
    /// Builds the tree on `threads` threads (0: oneTBB's choice; the tree does not depend on it).
    explicit PhotonMap(std::vector<Photon> photons, int threads = 0);

    const std::vector<Photon>& photons() const { return m_photons; }
    const PointKdTree& tree() const { return m_tree; }
    std::size_t size() const { return m_photons.size(); }
    bool empty() const { return m_photons.empty(); }

    /// The density estimate at p from the k = scratch.size() nearest photons within max_radius2: the sum of
    /// weight(photon) times the kernel, over the kernel's area at radius r, where r is the distance of the k-th
    /// photon, or the maximum radius when fewer are found. (The k-th photon gets kernel weight 0 under cone and
    /// epanechnikov: k - 1 photons over the disk, the unbiased count for a uniform density.) weight(photon) is the
    /// photon's contribution, e.g. f(wo, photon.wi) photon.power, black to leave it out. Black without photons.
    template <class Weight>
    RGB estimate(const Point3& p, float max_radius2, PhotonFilter filter, std::span<PointNeighbor> scratch,
                 Weight&& weight) const {
        if (m_photons.empty() || scratch.empty()) return {};
        const std::size_t n = m_tree.nearest(p, max_radius2, scratch);
        if (n == 0) return {};
        const float r2 = n == scratch.size() ? scratch[n - 1].distance2 : max_radius2;
        if (!(r2 > 0.0f)) return {};
        RGB sum;
        for (std::size_t i = 0; i < n; ++i) {
            const float w = photon_filter_weight(filter, scratch[i].distance2, r2);
            if (w > 0.0f) sum += w * weight(m_photons[scratch[i].index]);
        }
        return sum * (1.0f / photon_filter_area(filter, r2));
    }

private:
    std::vector<Photon> m_photons;
    PointKdTree m_tree;
};

}  // namespace rtlab
