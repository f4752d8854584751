#pragma once
/// \brief Whole-file reads and writes that fail with an rtlab::Error naming the file and the reason.
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace rtlab {

/// Reads the whole file. Errors: missing file, a directory, unreadable, or larger than max_bytes.
std::vector<unsigned char> read_binary_file(const std::filesystem::path& path,
                                            std::size_t max_bytes = std::size_t{1} << 32);
/// Writes bytes, replacing the file. Errors name the file and the operating system's reason.
void write_binary_file(const std::filesystem::path& path, std::span<const unsigned char> bytes);

/// "'path': reason" — the form every file error in rtlab takes.
std::string file_error_message(const std::filesystem::path& path, const std::string& reason);

}  // namespace rtlab
