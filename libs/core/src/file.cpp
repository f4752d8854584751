#include <rtlab/core/error.hpp>
#include <rtlab/core/file.hpp>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>

namespace rtlab {

std::string file_error_message(const std::filesystem::path& path, const std::string& reason) {
    return "'" + path.string() + "': " + reason;
}

std::vector<unsigned char> read_binary_file(const std::filesystem::path& path, std::size_t max_bytes) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw Error(file_error_message(path, "is a directory, not a file"));
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(file_error_message(path, std::strerror(errno)));
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size < 0) throw Error(file_error_message(path, "cannot determine the file size"));
    if (static_cast<std::size_t>(size) > max_bytes)
        throw Error(file_error_message(
            path, "file of " + std::to_string(size) + " bytes exceeds the limit of " + std::to_string(max_bytes)));
    in.seekg(0, std::ios::beg);
    std::vector<unsigned char> bytes(static_cast<std::size_t>(size));
    if (size > 0 && !in.read(reinterpret_cast<char*>(bytes.data()), size))
        throw Error(file_error_message(path, "read failed"));
    return bytes;
}

void write_binary_file(const std::filesystem::path& path, std::span<const unsigned char> bytes) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw Error(file_error_message(path, "is a directory, not a file"));
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) throw Error(file_error_message(path, std::string("cannot open for writing: ") + std::strerror(errno)));
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) throw Error(file_error_message(path, std::string("write failed: ") + std::strerror(errno)));
}

}  // namespace rtlab
