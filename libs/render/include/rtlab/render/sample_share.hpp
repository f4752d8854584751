#pragma once
/// \brief Sample shares: one frame rendered over many processes or machines, each rendering samples [A, B) of
/// every pixel (`rtlab-render --sample-range A:B`) into a share file of per-pixel sums, which `rtlab-merge` adds in
/// sample order into the bytes one process would have made. The file format is docs/sample-shares.md.
///
/// Byte identity comes from the block accumulation of the sums (PixelSums): a share starts on a block boundary and
/// stores each of its blocks' sums apart, and the merge adds them block after block (SampleBuffer::add_block), the
/// additions one render of all the samples makes.
#include <rtlab/core/sample_stream.hpp>
#include <rtlab/render/progressive.hpp>
#include <rtlab/render/sample_buffer.hpp>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace rtlab {

inline constexpr std::uint32_t kShareVersion = 1;
inline constexpr std::uint32_t kShareHeaderBytes = 64;
inline constexpr std::uint32_t kShareRecordBytes = 80;  ///< one pixel's SampleSums of one block

/// \brief What a share file says about itself: the frame it belongs to and the samples it holds.
struct ShareHeader {
    std::uint64_t seed = 0;
    std::uint64_t scene_hash = 0;  ///< whatever identifies the frame's scene and settings (the program decides)
    int width = 0, height = 0;
    std::uint32_t first = 0, end = 0;  ///< samples [first, end) of every pixel
    std::uint32_t block_samples = kDefaultBlockSamples;
    SampleSequence sequence = SampleSequence::sobol;

    /// Blocks of the share: [first, end) cut at the multiples of block_samples.
    std::uint64_t block_count() const;
};

/// \brief Writes a share file block by block: under a temporary name in the target's folder, renamed to the
/// target by finish(); destroyed unfinished, it removes the temporary file, so no half-written share is ever left
/// under the target's name. Errors (rtlab::Error) name the target.
class ShareWriter {
public:
    /// Checks the header (size, block alignment of `first`) and opens the temporary file.
    ShareWriter(std::filesystem::path path, const ShareHeader& header);
    ShareWriter(const ShareWriter&) = delete;
    ShareWriter& operator=(const ShareWriter&) = delete;
    ~ShareWriter();

    /// Writes each pixel's current block (PixelSums::block) of `buffer`, which must hold exactly the samples of the
    /// share's next block in every pixel: call it after rendering each block's samples and before the next one's.
    void append_block(const SampleBuffer& buffer);
    /// The end of the blocks appended so far.
    std::uint32_t end() const { return m_end; }
    /// Writes the header with end() as the share's end and renames the file to its target. At least one block.
    void finish();

private:
    std::filesystem::path m_path, m_tmp;
    ShareHeader m_header;
    std::ofstream m_out;
    std::uint32_t m_end;
    bool m_finished = false;
};

/// \brief Reads a share file, validating everything before the data is read: magic, version, a size of at most
/// kMaxImageSide a side and kMaxImagePixels, a non-empty range starting on a block boundary, the file's length
/// against the header (truncated or trailing bytes), and each record's counts against its block. Errors
/// (rtlab::Error) name the file. Memory stays one row of records whatever the header says.
class ShareReader {
public:
    explicit ShareReader(std::filesystem::path path);
    const ShareHeader& header() const { return m_header; }
    const std::filesystem::path& path() const { return m_path; }
    /// Adds the share's blocks, in order, to `buffer` (SampleBuffer::add_block), which must be the share's size and
    /// block size and hold every pixel's samples up to the share's first.
    void add_to(SampleBuffer& buffer);

private:
    std::filesystem::path m_path;
    ShareHeader m_header;
};

/// Reads every share and adds them in sample order: the buffer one render of their samples makes, the same bytes.
/// Refuses (rtlab::Error naming the files) shares of different seeds, scene hashes, sizes, block sizes or
/// sequences, overlapping ranges, samples no share holds (from 0 to the last end), and a share other than the last
/// that ends inside a block. `header` receives the merged frame's (first 0, end the last end).
SampleBuffer merge_shares(const std::vector<std::filesystem::path>& files, ShareHeader* header = nullptr);

/// \brief What render_share did.
struct ShareRenderResult {
    RenderStats stats;
    std::uint32_t end = 0;  ///< the share holds [first, end): short of the range asked for when stopped
    bool written = false;   ///< false when stopped before the first block was complete (no file)
};

/// Renders samples [settings.first_sample, settings.first_sample + settings.spp) of every pixel block by block and
/// writes them to `path` as a share (header.seed, width, height, first, block size and sequence come from the
/// settings and camera; scene_hash from `scene_hash`). When the stop flag ends it early, the blocks finished so far
/// are written as a shorter share. Throws rtlab::Error for a first sample off a block boundary or a failed write.
ShareRenderResult render_share(const Camera& camera, const RadianceSource& radiance,
                               const ProgressiveSettings& settings, std::uint64_t scene_hash,
                               const std::filesystem::path& path, const ProgressiveCallbacks& callbacks = {});

}  // namespace rtlab
