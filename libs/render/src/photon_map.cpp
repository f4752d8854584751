#include <rtlab/render/photon_map.hpp>

#include <cmath>

namespace rtlab {

std::optional<PhotonFilter> parse_photon_filter(std::string_view name) {
    if (name == "box") return PhotonFilter::box;
    if (name == "cone") return PhotonFilter::cone;
    if (name == "epanechnikov") return PhotonFilter::epanechnikov;
    return std::nullopt;
}

std::string_view photon_filter_name(PhotonFilter filter) {
    switch (filter) {
        case PhotonFilter::box:
            return "box";
        case PhotonFilter::cone:
            return "cone";
        case PhotonFilter::epanechnikov:
            return "epanechnikov";
    }
    return "box";
}

float photon_filter_weight(PhotonFilter filter, float d2, float r2) {
    if (!(d2 <= r2) || !(r2 > 0.0f)) return 0.0f;
    switch (filter) {
        case PhotonFilter::box:
            return 1.0f;
        case PhotonFilter::cone:
            return std::max(0.0f, 1.0f - std::sqrt(d2 / r2));
        case PhotonFilter::epanechnikov:
            return std::max(0.0f, 1.0f - d2 / r2);
    }
    return 0.0f;
}

float photon_filter_area(PhotonFilter filter, float r2) {
    switch (filter) {
        case PhotonFilter::box:
            return kPi * r2;
        case PhotonFilter::cone:
            return kPi * r2 * (1.0f / 3.0f);
        case PhotonFilter::epanechnikov:
            return kPi * r2 * 0.5f;
    }
    return kPi * r2;
}

namespace {
std::vector<Point3> positions(const std::vector<Photon>& photons) {
    std::vector<Point3> out;
    out.reserve(photons.size());
    for (const Photon& p : photons) out.push_back(p.position);
    return out;
}
}  // namespace

PhotonMap::PhotonMap(std::vector<Photon> photons, int threads)
    : m_photons(std::move(photons)), m_tree(positions(m_photons), threads) {}

}  // namespace rtlab
