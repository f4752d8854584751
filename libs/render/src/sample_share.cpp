#include <rtlab/core/error.hpp>
#include <rtlab/core/file.hpp>
#include <rtlab/render/image_limits.hpp>
#include <rtlab/render/sample_share.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cstring>
#include <system_error>

#include <unistd.h>

namespace rtlab {

namespace {

constexpr std::array<char, 8> kMagic{'R', 'T', 'L', 'S', 'H', 'A', 'R', 'E'};

// Little-endian fields, whatever the machine.
void put_u32(unsigned char* p, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) p[i] = static_cast<unsigned char>(v >> (8 * i));
}
void put_u64(unsigned char* p, std::uint64_t v) {
    for (int i = 0; i < 8; ++i) p[i] = static_cast<unsigned char>(v >> (8 * i));
}
std::uint32_t get_u32(const unsigned char* p) {
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i) v |= static_cast<std::uint32_t>(p[i]) << (8 * i);
    return v;
}
std::uint64_t get_u64(const unsigned char* p) {
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v |= static_cast<std::uint64_t>(p[i]) << (8 * i);
    return v;
}

std::uint32_t sequence_code(SampleSequence s) {
    switch (s) {
        case SampleSequence::independent:
            return 0;
        case SampleSequence::sobol:
            return 1;
        case SampleSequence::sobol_halves:
            return 2;
    }
    return 0xffffffffu;
}

const char* sequence_word(SampleSequence s) {
    switch (s) {
        case SampleSequence::independent:
            return "independent";
        case SampleSequence::sobol:
            return "sobol";
        case SampleSequence::sobol_halves:
            return "sobol_halves";
    }
    return "?";
}

std::array<unsigned char, kShareHeaderBytes> encode_header(const ShareHeader& h) {
    std::array<unsigned char, kShareHeaderBytes> b{};
    std::memcpy(b.data(), kMagic.data(), kMagic.size());
    put_u32(&b[8], kShareVersion);
    put_u32(&b[12], kShareHeaderBytes);
    put_u64(&b[16], h.seed);
    put_u64(&b[24], h.scene_hash);
    put_u32(&b[32], static_cast<std::uint32_t>(h.width));
    put_u32(&b[36], static_cast<std::uint32_t>(h.height));
    put_u32(&b[40], h.first);
    put_u32(&b[44], h.end);
    put_u32(&b[48], h.block_samples);
    put_u32(&b[52], sequence_code(h.sequence));
    return b;  // bytes 56 to 63 reserved, zero
}

void encode_record(unsigned char* p, const SampleSums& s) {
    for (std::size_t h = 0; h < 2; ++h)
        for (std::size_t c = 0; c < 3; ++c) put_u64(p + 8 * (3 * h + c), std::bit_cast<std::uint64_t>(s.sum[h][c]));
    for (std::size_t c = 0; c < 3; ++c) put_u64(p + 48 + 8 * c, std::bit_cast<std::uint64_t>(s.sum_squares[c]));
    put_u32(p + 72, s.count[0]);
    put_u32(p + 76, s.count[1]);
}

SampleSums decode_record(const unsigned char* p) {
    SampleSums s;
    for (std::size_t h = 0; h < 2; ++h)
        for (std::size_t c = 0; c < 3; ++c) s.sum[h][c] = std::bit_cast<double>(get_u64(p + 8 * (3 * h + c)));
    for (std::size_t c = 0; c < 3; ++c) s.sum_squares[c] = std::bit_cast<double>(get_u64(p + 48 + 8 * c));
    s.count[0] = get_u32(p + 72);
    s.count[1] = get_u32(p + 76);
    return s;
}

/// Block k of samples [first, end): [begin, stop).
std::pair<std::uint32_t, std::uint32_t> block_range(const ShareHeader& h, std::uint64_t k) {
    const std::uint64_t base = static_cast<std::uint64_t>(h.first) / h.block_samples * h.block_samples;
    const std::uint64_t begin = std::max<std::uint64_t>(h.first, base + k * h.block_samples);
    const std::uint64_t stop = std::min<std::uint64_t>(h.end, base + (k + 1) * h.block_samples);
    return {static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(stop)};
}

/// Even sample indices in [begin, stop).
std::uint32_t even_count(std::uint32_t begin, std::uint32_t stop) {
    auto evens_below = [](std::uint64_t n) { return (n + 1) / 2; };
    return static_cast<std::uint32_t>(evens_below(stop) - evens_below(begin));
}

/// Problems of a header, as the reader and the writer report them; empty when fine.
std::string header_problem(const ShareHeader& h) {
    if (h.width < 1 || h.height < 1 || h.width > kMaxImageSide || h.height > kMaxImageSide ||
        static_cast<std::int64_t>(h.width) * h.height > kMaxImagePixels)
        return "image size " + std::to_string(h.width) + "x" + std::to_string(h.height) + " is outside 1 to " +
               std::to_string(kMaxImageSide) + " a side and " + std::to_string(kMaxImagePixels) + " pixels";
    if (h.block_samples < 1) return "block size 0";
    if (h.first >= h.end) return "empty sample range " + std::to_string(h.first) + " to " + std::to_string(h.end);
    if (h.first % h.block_samples != 0)
        return "sample range starts at " + std::to_string(h.first) + ", not on a block boundary (blocks of " +
               std::to_string(h.block_samples) + ")";
    if (sequence_code(h.sequence) > 2) return "unknown sample sequence";
    return {};
}

std::filesystem::path temporary_path(const std::filesystem::path& path) {
    static std::atomic<unsigned> counter{0};
    std::filesystem::path tmp = path;
    tmp.replace_filename("." + path.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                         std::to_string(counter.fetch_add(1)));
    return tmp;
}

std::string hex(std::uint64_t v) {
    static const char* digits = "0123456789abcdef";
    std::string s = "0x";
    for (int i = 15; i >= 0; --i) s += digits[(v >> (4 * i)) & 0xfu];
    return s;
}

}  // namespace

std::uint64_t ShareHeader::block_count() const {
    if (end <= first || block_samples == 0) return 0;
    const std::uint64_t base = static_cast<std::uint64_t>(first) / block_samples;
    const std::uint64_t last = (static_cast<std::uint64_t>(end) - 1) / block_samples;
    return last - base + 1;
}

// ---- writing ----

ShareWriter::ShareWriter(std::filesystem::path path, const ShareHeader& header)
    : m_path(std::move(path)), m_header(header), m_end(header.first) {
    ShareHeader check = header;
    if (check.end <= check.first) check.end = check.first + 1;  // the end is known at finish()
    if (const std::string problem = header_problem(check); !problem.empty())
        throw Error(file_error_message(m_path, "cannot write a share: " + problem));
    m_tmp = temporary_path(m_path);
    m_out.open(m_tmp, std::ios::binary | std::ios::trunc);
    if (!m_out)
        throw Error(file_error_message(m_path, "cannot create the share file: " + std::string(std::strerror(errno))));
    const auto bytes = encode_header(m_header);  // rewritten by finish() with the end
    m_out.write(reinterpret_cast<const char*>(bytes.data()), bytes.size());
}

ShareWriter::~ShareWriter() {
    if (m_finished) return;
    m_out.close();
    std::error_code ignored;
    std::filesystem::remove(m_tmp, ignored);
}

void ShareWriter::append_block(const SampleBuffer& buffer) {
    if (buffer.width() != m_header.width || buffer.height() != m_header.height ||
        buffer.block_samples() != m_header.block_samples)
        throw Error(file_error_message(m_path, "share block of another size or block size"));
    const std::uint64_t base = static_cast<std::uint64_t>(m_end) / m_header.block_samples * m_header.block_samples;
    const std::uint32_t stop = static_cast<std::uint32_t>(base + m_header.block_samples);
    std::vector<unsigned char> row(static_cast<std::size_t>(m_header.width) * kShareRecordBytes);
    // Every pixel holds the block's samples [m_end, next), the same in all (the last block may be short).
    const std::uint32_t next = buffer.next_sample(0, 0);
    if (next <= m_end || next > stop)
        throw Error(file_error_message(m_path, "the render does not hold the share's next block"));
    for (int y = 0; y < m_header.height; ++y) {
        for (int x = 0; x < m_header.width; ++x) {
            const PixelSums& p = buffer.at(x, y);
            if (buffer.next_sample(x, y) != next || p.block.total_count() != next - m_end)
                throw Error(file_error_message(m_path, "pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                                           ") does not hold the share's next block"));
            encode_record(&row[static_cast<std::size_t>(x) * kShareRecordBytes], p.block);
        }
        m_out.write(reinterpret_cast<const char*>(row.data()), static_cast<std::streamsize>(row.size()));
    }
    m_end = buffer.next_sample(0, 0);
    if (!m_out) throw Error(file_error_message(m_path, "cannot write the share: " + std::string(std::strerror(errno))));
}

void ShareWriter::finish() {
    if (m_end == m_header.first) throw Error(file_error_message(m_path, "a share needs at least one block"));
    m_header.end = m_end;
    const auto bytes = encode_header(m_header);
    m_out.seekp(0);
    m_out.write(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    m_out.close();
    if (!m_out) throw Error(file_error_message(m_path, "cannot write the share: " + std::string(std::strerror(errno))));
    std::error_code ec;
    std::filesystem::rename(m_tmp, m_path, ec);
    if (ec) throw Error(file_error_message(m_path, "cannot replace it with the finished share: " + ec.message()));
    m_finished = true;
}

// ---- reading ----

ShareReader::ShareReader(std::filesystem::path path) : m_path(std::move(path)) {
    auto fail = [&](const std::string& why) { throw Error(file_error_message(m_path, why)); };
    std::error_code ec;
    if (std::filesystem::is_directory(m_path, ec)) fail("is a directory, not a share file");
    const std::uintmax_t size = std::filesystem::file_size(m_path, ec);
    if (ec) fail("cannot read: " + ec.message());
    std::ifstream in(m_path, std::ios::binary);
    if (!in) fail("cannot open: " + std::string(std::strerror(errno)));
    std::array<unsigned char, kShareHeaderBytes> b{};
    if (size < kMagic.size()) fail("not a share file (" + std::to_string(size) + " bytes, no magic)");
    in.read(reinterpret_cast<char*>(b.data()), static_cast<std::streamsize>(std::min<std::uintmax_t>(size, b.size())));
    if (!in && size >= b.size()) fail("cannot read the header");
    if (std::memcmp(b.data(), kMagic.data(), kMagic.size()) != 0)
        fail("not a share file (its first bytes are not RTLSHARE)");
    if (size < kShareHeaderBytes)
        fail("truncated: " + std::to_string(size) + " bytes, shorter than the " + std::to_string(kShareHeaderBytes) +
             "-byte header");
    const std::uint32_t version = get_u32(&b[8]);
    if (version != kShareVersion)
        fail("share format version " + std::to_string(version) + "; this program reads version " +
             std::to_string(kShareVersion));
    if (get_u32(&b[12]) != kShareHeaderBytes)
        fail("header size " + std::to_string(get_u32(&b[12])) + ", not " + std::to_string(kShareHeaderBytes));
    ShareHeader& h = m_header;
    h.seed = get_u64(&b[16]);
    h.scene_hash = get_u64(&b[24]);
    const std::uint32_t w = get_u32(&b[32]), ht = get_u32(&b[36]);
    // Compared as unsigned before the narrowing: a width of 2^31 must not become negative and pass.
    if (w > static_cast<std::uint32_t>(kMaxImageSide) || ht > static_cast<std::uint32_t>(kMaxImageSide))
        fail("image size " + std::to_string(w) + "x" + std::to_string(ht) + " is more than " +
             std::to_string(kMaxImageSide) + " a side");
    h.width = static_cast<int>(w);
    h.height = static_cast<int>(ht);
    h.first = get_u32(&b[40]);
    h.end = get_u32(&b[44]);
    h.block_samples = get_u32(&b[48]);
    const std::uint32_t sequence = get_u32(&b[52]);
    if (sequence > 2) fail("unknown sample sequence " + std::to_string(sequence));
    h.sequence = sequence == 0 ? SampleSequence::independent
                               : (sequence == 1 ? SampleSequence::sobol : SampleSequence::sobol_halves);
    if (const std::string problem = header_problem(h); !problem.empty()) fail(problem);
    const std::uint64_t block_bytes = static_cast<std::uint64_t>(h.width) * static_cast<std::uint64_t>(h.height) *
                                      kShareRecordBytes;  // below 2^33: the size checks above
    const std::uint64_t data = size - kShareHeaderBytes;
    const std::uint64_t blocks = h.block_count();
    // Divided, not multiplied: blocks * block_bytes may not fit 64 bits for an absurd header.
    if (data % block_bytes != 0 || data / block_bytes != blocks)
        fail("truncated or padded: " + std::to_string(size) + " bytes, but its header says " + std::to_string(blocks) +
             " blocks of " + std::to_string(h.width) + "x" + std::to_string(h.height) + " records of " +
             std::to_string(kShareRecordBytes) + " bytes after the " + std::to_string(kShareHeaderBytes) +
             "-byte header");
}

void ShareReader::add_to(SampleBuffer& buffer) {
    const ShareHeader& h = m_header;
    if (buffer.width() != h.width || buffer.height() != h.height || buffer.block_samples() != h.block_samples)
        throw Error(file_error_message(m_path, "share of another size or block size than the merge"));
    std::ifstream in(m_path, std::ios::binary);
    in.seekg(kShareHeaderBytes);
    std::vector<unsigned char> row(static_cast<std::size_t>(h.width) * kShareRecordBytes);
    for (std::uint64_t k = 0; k < h.block_count(); ++k) {
        const auto [begin, stop] = block_range(h, k);
        const std::uint32_t evens = even_count(begin, stop), odds = (stop - begin) - evens;
        for (int y = 0; y < h.height; ++y) {
            in.read(reinterpret_cast<char*>(row.data()), static_cast<std::streamsize>(row.size()));
            if (!in)
                throw Error(file_error_message(m_path, "cannot read block " + std::to_string(k) + " (truncated?)"));
            for (int x = 0; x < h.width; ++x) {
                const SampleSums s = decode_record(&row[static_cast<std::size_t>(x) * kShareRecordBytes]);
                if (s.count[0] != evens || s.count[1] != odds)
                    throw Error(file_error_message(
                        m_path, "corrupt: pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") of block " +
                                    std::to_string(k) + " holds " + std::to_string(s.count[0]) + " even and " +
                                    std::to_string(s.count[1]) + " odd samples, not the block's " +
                                    std::to_string(evens) + " and " + std::to_string(odds)));
                buffer.add_block(x, y, begin, s);
            }
        }
    }
}

SampleBuffer merge_shares(const std::vector<std::filesystem::path>& files, ShareHeader* merged_header) {
    if (files.empty()) throw Error("merge: no share files");
    std::vector<ShareReader> shares;
    shares.reserve(files.size());
    for (const auto& f : files) shares.emplace_back(f);
    const ShareReader& ref = shares.front();
    const ShareHeader& r = ref.header();
    auto name = [](const ShareReader& s) { return "'" + s.path().string() + "'"; };
    for (const ShareReader& s : shares) {
        const ShareHeader& h = s.header();
        auto differs = [&](const std::string& what, const std::string& mine, const std::string& theirs) {
            throw Error(name(s) + ": its " + what + " " + mine + " differs from " + theirs + " in " + name(ref) +
                        ": shares of one frame must agree");
        };
        if (h.seed != r.seed) differs("seed", std::to_string(h.seed), std::to_string(r.seed));
        if (h.scene_hash != r.scene_hash)
            differs("scene hash", hex(h.scene_hash) + " (another scene, or other settings)", hex(r.scene_hash));
        if (h.width != r.width || h.height != r.height)
            differs("image size", std::to_string(h.width) + "x" + std::to_string(h.height),
                    std::to_string(r.width) + "x" + std::to_string(r.height));
        if (h.block_samples != r.block_samples)
            differs("block size", std::to_string(h.block_samples), std::to_string(r.block_samples));
        if (h.sequence != r.sequence) differs("sample sequence", sequence_word(h.sequence), sequence_word(r.sequence));
    }
    std::vector<std::size_t> order(shares.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return shares[a].header().first < shares[b].header().first; });
    std::uint32_t covered = 0;  // samples [0, covered) are in the shares so far
    const ShareReader* previous = nullptr;
    auto samples = [](std::uint32_t a, std::uint32_t b) {  // [a, b]
        return a == b ? "sample " + std::to_string(a) : "samples " + std::to_string(a) + " to " + std::to_string(b);
    };
    for (const std::size_t i : order) {
        const ShareReader& s = shares[i];
        const ShareHeader& h = s.header();
        if (previous && previous->header().end % r.block_samples != 0)
            throw Error(name(*previous) + ": it ends at sample " + std::to_string(previous->header().end) +
                        ", inside a block of " + std::to_string(r.block_samples) + " samples, and " + name(s) +
                        " follows: only the last share may end off a block boundary");
        if (h.first > covered)
            throw Error("merge: " + samples(covered, h.first - 1) + " are in no share (" +
                        (previous ? "after " + name(*previous) + ", " : "") + "before " + name(s) + ")");
        if (h.first < covered)
            throw Error("merge: " + samples(h.first, std::min(covered, h.end) - 1) + " are in both " + name(*previous) +
                        " and " + name(s));
        covered = h.end;
        previous = &s;
    }
    SampleBuffer buffer(r.width, r.height, 0, r.block_samples);
    for (const std::size_t i : order) shares[i].add_to(buffer);
    if (merged_header) {
        *merged_header = r;
        merged_header->first = 0;
        merged_header->end = covered;
    }
    return buffer;
}

// ---- rendering ----

ShareRenderResult render_share(const Camera& camera, const RadianceSource& radiance,
                               const ProgressiveSettings& settings, std::uint64_t scene_hash,
                               const std::filesystem::path& path, const ProgressiveCallbacks& callbacks) {
    if (settings.spp < 1 ||
        static_cast<std::uint64_t>(settings.first_sample) + static_cast<std::uint64_t>(settings.spp) > 0xffffffffULL)
        throw Error("share render: samples per pixel must be >= 1 and first sample + spp below 2^32");
    ShareHeader header;
    header.seed = settings.seed;
    header.scene_hash = scene_hash;
    header.width = camera.width();
    header.height = camera.height();
    header.first = settings.first_sample;
    header.end = settings.first_sample + static_cast<std::uint32_t>(settings.spp);
    header.block_samples = settings.block_samples;
    header.sequence = settings.sequence;
    ShareWriter writer(path, header);
    ProgressiveRenderer renderer(camera, radiance, settings);
    const std::uint64_t blocks = header.block_count();
    renderer.plan_passes(static_cast<int>(std::min<std::uint64_t>(blocks, 1u << 30)));
    ShareRenderResult result;
    for (std::uint64_t k = 0; k < blocks; ++k) {
        const std::uint32_t stop = block_range(header, k).second;
        if (!renderer.render_to(stop, callbacks, static_cast<int>(k))) break;
        writer.append_block(renderer.buffer());
        if (callbacks.pass)
            callbacks.pass(PassUpdate{static_cast<int>(k), block_range(header, k).first, stop, renderer.buffer(),
                                      renderer.stats()});
    }
    result.stats = renderer.stats();
    result.end = writer.end();
    if (writer.end() > header.first) {
        writer.finish();
        result.written = true;
    }
    return result;
}

}  // namespace rtlab
