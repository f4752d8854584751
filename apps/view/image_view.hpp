#pragma once
// Draws the render with OpenGL 3.3: linear float textures, exposure, tone operator and the exact piecewise sRGB
// curve in a fragment shader, each screen pixel fetching its image pixel (nearest, 1:1 at zoom 1).
#include "display_tone.hpp"
#include "render_worker.hpp"

#include <rtlab/core/image.hpp>

namespace rtlab::view {

enum class ViewMode { image = 0, variance = 1, compare = 2 };

/// \brief Where and how the image is drawn. The image's top-left corner sits at `origin` (framebuffer pixels,
/// from the top-left of the window), each image pixel `zoom` framebuffer pixels wide.
struct ViewParams {
    ToneParams tone;
    ViewMode mode = ViewMode::image;
    float origin_x = 0.0f, origin_y = 0.0f;
    float zoom = 1.0f;
    float split = 0.5f;  ///< compare: the reference right of this fraction of the image's width
};

class ImageView {
public:
    /// Needs a current OpenGL 3.3 core context. Throws rtlab::Error when the shader does not compile.
    ImageView();
    ~ImageView();
    ImageView(const ImageView&) = delete;
    ImageView& operator=(const ImageView&) = delete;

    /// Uploads rows [first_row, last_row) of the pixels (all of them when the size changed).
    void upload(const DisplayBuffer& pixels, int first_row, int last_row);
    /// The A/B reference: drawn at the same pixels as the render (cropped or padded with black).
    void set_reference(const Image& reference);
    bool has_reference() const { return m_has_reference; }

    /// Fills framebuffer columns [region_x0, region_x1) over the whole height.
    void draw(int framebuffer_width, int framebuffer_height, int region_x0, int region_x1, const ViewParams& params);

private:
    unsigned m_program = 0, m_vao = 0;
    unsigned m_textures[3] = {0, 0, 0};  // mean, variance, reference
    int m_width = 0, m_height = 0;
    bool m_has_reference = false;
};

}  // namespace rtlab::view
