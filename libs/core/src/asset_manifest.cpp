#include "rtlab/core/asset_manifest.hpp"

#include "rtlab/core/error.hpp"

namespace rtlab {

// The text of data/assets.tsv, generated into the build tree (libs/core/CMakeLists.txt).
extern const char* const kEmbeddedAssetManifest;

std::vector<AssetEntry> parse_asset_manifest(std::string_view text, std::string_view origin) {
    std::vector<AssetEntry> entries;
    int line_number = 0;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        const std::string_view line = text.substr(start, end - start);
        start = end + 1;
        ++line_number;
        if (line.empty() || line.front() == '#') continue;
        std::vector<std::string> columns;
        std::size_t from = 0;
        while (true) {
            const std::size_t tab = line.find('\t', from);
            columns.emplace_back(line.substr(from, tab == std::string_view::npos ? line.size() - from : tab - from));
            if (tab == std::string_view::npos) break;
            from = tab + 1;
        }
        const std::string where = std::string(origin) + ":" + std::to_string(line_number) + ": ";
        if (columns.size() != 5)
            throw Error(where + "expected 5 tab-separated columns (name, source, file, expected, credit), found " +
                        std::to_string(columns.size()));
        for (const auto& c : columns)
            if (c.empty()) throw Error(where + "an empty column");
        AssetEntry e{columns[0], columns[1], columns[2], columns[3], columns[4]};
        if (e.from_package() != e.file.is_absolute())
            throw Error(where + "'" + e.file.string() + "': a package's file must be an absolute path, a shared one " +
                        "relative to the folder");
        entries.push_back(std::move(e));
    }
    return entries;
}

const std::vector<AssetEntry>& asset_manifest() {
    static const std::vector<AssetEntry> kManifest = parse_asset_manifest(kEmbeddedAssetManifest, "data/assets.tsv");
    return kManifest;
}

}  // namespace rtlab
