#include <rtlab/render/exr.hpp>
#include <rtlab/render/image_input.hpp>

#include <fstream>

namespace rtlab {

bool is_exr_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    unsigned char magic[4] = {0, 0, 0, 0};
    if (!in.read(reinterpret_cast<char*>(magic), 4)) return false;
    return magic[0] == 0x76 && magic[1] == 0x2f && magic[2] == 0x31 && magic[3] == 0x01;
}

Image read_image_file(const std::filesystem::path& path, ColorEncoding encoding) {
    if (is_exr_file(path)) return read_exr(path);
    return read_image(path, encoding);
}

}  // namespace rtlab
