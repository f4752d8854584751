#pragma once
/// \brief The data manifest (data/assets.tsv, embedded at build time): for each logical data name
/// ("models/stanford-bunny.obj", "textures/earth.jpg") the files Debian packages install for it, what they
/// should hold, and the credit each source asks for. One place says where every asset comes from.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace rtlab {

/// The source word of a manifest row that credits the file of that name in a folder laid out like ../shared.
inline constexpr std::string_view kSharedLayoutSource = "shared";

/// \brief One row of the manifest.
struct AssetEntry {
    std::string name;            ///< logical name, relative to a data root
    std::string source;          ///< a Debian package ("glmark2-data"), or kSharedLayoutSource
    std::filesystem::path file;  ///< the package's file (absolute); relative to the folder for "shared"
    std::string expected;        ///< "69666 triangles" or "2048x1024", checked by the tests
    std::string credit;          ///< the credit line to print beside anything made from the file
    [[nodiscard]] bool from_package() const { return source != kSharedLayoutSource; }
};

/// Parses manifest text: '#' comments and blank lines skipped, else 5 tab-separated columns. Throws
/// rtlab::Error naming `origin`, the line and the problem.
std::vector<AssetEntry> parse_asset_manifest(std::string_view text, std::string_view origin);

/// The manifest built into the library (data/assets.tsv), parsed once.
const std::vector<AssetEntry>& asset_manifest();

}  // namespace rtlab
