#pragma once
// What the photon-mapping benchmarks measure between an image and a reference: block means and RMSE.
#include <rtlab/core/color.hpp>
#include <rtlab/core/image.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace rtlab::bench {

/// The mean over the block x block tiles of the image (whole tiles only) of each tile's channel mean.
inline std::vector<double> block_means(const Image& image, int block) {
    std::vector<double> out;
    for (int by = 0; by + block <= image.height(); by += block)
        for (int bx = 0; bx + block <= image.width(); bx += block) {
            double sum = 0.0;
            for (int y = by; y < by + block; ++y)
                for (int x = bx; x < bx + block; ++x) {
                    const RGB& c = image.at(x, y);
                    sum += (static_cast<double>(c.r) + c.g + c.b) / 3.0;
                }
            out.push_back(sum / (block * block));
        }
    return out;
}

/// Mean and largest of |a - r| / r over the blocks.
struct BlockDifference {
    double mean = 0.0, largest = 0.0;
};
inline BlockDifference block_difference(const Image& image, const Image& reference, int block) {
    const std::vector<double> a = block_means(image, block), r = block_means(reference, block);
    BlockDifference d;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const double rel = std::abs(a[i] - r[i]) / std::max(r[i], 1e-12);
        d.mean += rel / static_cast<double>(a.size());
        d.largest = std::max(d.largest, rel);
    }
    return d;
}

/// Root-mean-square difference over every pixel and channel.
inline double rmse(const Image& image, const Image& reference) {
    double sum = 0.0;
    for (std::size_t i = 0; i < image.pixel_count(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double d = static_cast<double>(image.pixels()[i][c]) - static_cast<double>(reference.pixels()[i][c]);
            sum += d * d;
        }
    return std::sqrt(sum / (3.0 * static_cast<double>(image.pixel_count())));
}

}  // namespace rtlab::bench
