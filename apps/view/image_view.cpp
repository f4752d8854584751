#include "image_view.hpp"

#include <rtlab/core/error.hpp>

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <string>
#include <vector>

namespace rtlab::view {

namespace {

const char* const kVertexShader = R"(#version 330 core
void main() {
    // One triangle covering the viewport.
    vec2 p = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);
    gl_Position = vec4(p, 0.0, 1.0);
}
)";

// Mirrors display_tone.cpp (tone_map) and rtlab's tone operators; sRGB by IEC 61966-2-1's piecewise curve.
const char* const kFragmentShader = R"(#version 330 core
uniform sampler2D u_image;
uniform sampler2D u_variance;
uniform sampler2D u_reference;
uniform ivec2 u_size;
uniform vec2 u_origin;
uniform float u_zoom;
uniform float u_framebuffer_height;
uniform int u_operator;
uniform float u_scale;
uniform float u_inv_white2;
uniform int u_mode;
uniform float u_split;
out vec4 frag_color;

float aces_fit(float x) { return x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14); }

vec3 tone(vec3 c) {
    vec3 o;
    if (u_operator == 1) {
        float lw = dot(c, vec3(0.2126, 0.7152, 0.0722));
        if (!(lw > 0.0)) return vec3(0.0);
        float l = u_scale * lw;
        float ld = l * (1.0 + l * u_inv_white2) / (1.0 + l);
        o = c * (ld / lw);
    } else if (u_operator == 3) {
        vec3 x = min(c * u_scale, vec3(1e18));
        o = vec3(aces_fit(x.r), aces_fit(x.g), aces_fit(x.b));
    } else {
        o = c * u_scale;
    }
    return clamp(o, 0.0, 1.0);
}

float srgb(float c) { return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055; }

void main() {
    vec2 p = vec2(gl_FragCoord.x, u_framebuffer_height - gl_FragCoord.y);
    vec2 q = (p - u_origin) / u_zoom;
    ivec2 t = ivec2(floor(q));
    if (any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, u_size))) {
        frag_color = vec4(0.16, 0.16, 0.18, 1.0);
        return;
    }
    vec3 c;
    if (u_mode == 1) {
        // The standard deviation of each pixel's mean, through the same exposure and operator.
        c = sqrt(max(texelFetch(u_variance, t, 0).rgb, vec3(0.0)));
    } else if (u_mode == 2 && q.x >= u_split * float(u_size.x)) {
        c = texelFetch(u_reference, t, 0).rgb;
    } else {
        c = texelFetch(u_image, t, 0).rgb;
    }
    vec3 d = tone(c);
    if (u_mode == 2 && abs(q.x - u_split * float(u_size.x)) * u_zoom < 0.5) d = vec3(1.0, 1.0, 0.0);
    frag_color = vec4(srgb(d.r), srgb(d.g), srgb(d.b), 1.0);
}
)";

unsigned compile(GLenum kind, const char* source) {
    const GLuint shader = glCreateShader(kind);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048];
        glGetShaderInfoLog(shader, sizeof log, nullptr, log);
        throw Error(std::string("rtlab-view: shader: ") + log);
    }
    return shader;
}

void allocate(unsigned texture, int width, int height, const float* rgb) {
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, width, height, 0, GL_RGB, GL_FLOAT, rgb);
}

}  // namespace

ImageView::ImageView() {
    const GLuint vs = compile(GL_VERTEX_SHADER, kVertexShader);
    const GLuint fs = compile(GL_FRAGMENT_SHADER, kFragmentShader);
    m_program = glCreateProgram();
    glAttachShader(m_program, vs);
    glAttachShader(m_program, fs);
    glLinkProgram(m_program);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(m_program, GL_LINK_STATUS, &ok);
    if (!ok) throw Error("rtlab-view: the display shader does not link");
    glGenVertexArrays(1, &m_vao);
    glGenTextures(3, m_textures);
    const float black[3] = {0.0f, 0.0f, 0.0f};
    for (unsigned t : m_textures) allocate(t, 1, 1, black);
}

ImageView::~ImageView() {
    glDeleteTextures(3, m_textures);
    glDeleteVertexArrays(1, &m_vao);
    glDeleteProgram(m_program);
}

void ImageView::upload(const DisplayBuffer& pixels, int first_row, int last_row) {
    if (pixels.width <= 0 || pixels.height <= 0) return;
    if (pixels.width != m_width || pixels.height != m_height) {
        m_width = pixels.width;
        m_height = pixels.height;
        allocate(m_textures[0], m_width, m_height, pixels.mean.data());
        allocate(m_textures[1], m_width, m_height, pixels.variance.data());
        return;
    }
    const std::size_t offset = 3 * static_cast<std::size_t>(first_row) * static_cast<std::size_t>(m_width);
    glBindTexture(GL_TEXTURE_2D, m_textures[0]);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, first_row, m_width, last_row - first_row, GL_RGB, GL_FLOAT,
                    pixels.mean.data() + offset);
    glBindTexture(GL_TEXTURE_2D, m_textures[1]);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, first_row, m_width, last_row - first_row, GL_RGB, GL_FLOAT,
                    pixels.variance.data() + offset);
}

void ImageView::set_reference(const Image& reference) {
    allocate(m_textures[2], reference.width(), reference.height(),
             reinterpret_cast<const float*>(reference.pixels().data()));
    m_has_reference = true;
}

void ImageView::draw(int framebuffer_width, int framebuffer_height, int region_x0, int region_x1,
                     const ViewParams& params) {
    (void)framebuffer_width;
    if (region_x1 <= region_x0 || framebuffer_height <= 0) return;
    glViewport(region_x0, 0, region_x1 - region_x0, framebuffer_height);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glUseProgram(m_program);
    for (int i = 0; i < 3; ++i) {
        glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + i));
        glBindTexture(GL_TEXTURE_2D, m_textures[i]);
    }
    glUniform1i(glGetUniformLocation(m_program, "u_image"), 0);
    glUniform1i(glGetUniformLocation(m_program, "u_variance"), 1);
    glUniform1i(glGetUniformLocation(m_program, "u_reference"), 2);
    glUniform2i(glGetUniformLocation(m_program, "u_size"), m_width, m_height);
    glUniform2f(glGetUniformLocation(m_program, "u_origin"), params.origin_x, params.origin_y);
    glUniform1f(glGetUniformLocation(m_program, "u_zoom"), params.zoom);
    glUniform1f(glGetUniformLocation(m_program, "u_framebuffer_height"), static_cast<float>(framebuffer_height));
    glUniform1i(glGetUniformLocation(m_program, "u_operator"), static_cast<int>(params.tone.op));
    glUniform1f(glGetUniformLocation(m_program, "u_scale"), params.tone.scale);
    glUniform1f(glGetUniformLocation(m_program, "u_inv_white2"), params.tone.inv_white2);
    const ViewMode mode = params.mode == ViewMode::compare && !m_has_reference ? ViewMode::image : params.mode;
    glUniform1i(glGetUniformLocation(m_program, "u_mode"), static_cast<int>(mode));
    glUniform1f(glGetUniformLocation(m_program, "u_split"), params.split);
    glBindVertexArray(m_vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glActiveTexture(GL_TEXTURE0);
    glUseProgram(0);
}

}  // namespace rtlab::view
