#include "game/replay/ReplayReader.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <utility>

#include "game/replay/Crc32.h"

namespace game {
namespace {

using namespace replay_bytes;
using std::to_string;

std::string hex32(uint32_t v) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%08X", v);
    return buf;
}

// Walks the header fields; every read is bounded by the declared header size.
class HeaderCursor {
public:
    HeaderCursor(const uint8_t* begin, size_t size, const std::string& name)
        : p_(begin), left_(size), name_(name) {}

    uint8_t u8(const char* field) { return *take(1, field); }
    uint32_t u32(const char* field) { return get_u32(take(4, field)); }
    float f32(const char* field) { return get_f32(take(4, field)); }
    uint64_t u64(const char* field) { return get_u64(take(8, field)); }
    // A length-prefixed string, its length checked against `max` before it is copied.
    std::string str(const char* field, size_t max) {
        const uint32_t len = u32(field);
        if (len > max)
            throw ReplayError(name_ + ": header field '" + field + "' is " + to_string(len) +
                              " bytes long, more than the " + to_string(max) + " allowed");
        const uint8_t* s = take(len, field);
        return std::string(reinterpret_cast<const char*>(s), len);
    }
    // A count, checked against `max` before anything is reserved for it.
    uint32_t count(const char* field, size_t max) {
        const uint32_t n = u32(field);
        if (n > max)
            throw ReplayError(name_ + ": header field '" + field + "' counts " + to_string(n) +
                              ", more than the " + to_string(max) + " allowed");
        return n;
    }
    size_t left() const { return left_; }

private:
    const uint8_t* take(size_t n, const char* field) {
        if (n > left_)
            throw ReplayError(name_ + ": header field '" + field + "' runs past the end of the header");
        const uint8_t* at = p_;
        p_ += n;
        left_ -= n;
        return at;
    }

    const uint8_t* p_;
    size_t left_;
    const std::string& name_;
};

class ReplayParser {
public:
    ReplayParser(std::span<const uint8_t> bytes, std::string_view name, const ReadOptions& options)
        : bytes_(bytes), name_(name), options_(options) {}

    Replay parse() {
        Replay replay;
        const size_t header_size = parse_header(replay.header);
        parse_records(replay, header_size);
        return replay;
    }

private:
    [[noreturn]] void fail(const std::string& message) const { throw ReplayError(message); }

    uint32_t crc_of(size_t from, size_t size) const { return crc32(bytes_.subspan(from, size)); }

    // Returns the header's size in bytes.
    size_t parse_header(ReplayHeader& h) const {
        const size_t n = bytes_.size();
        if (n == 0) fail(name_ + " is empty (0 bytes): not a Spindrift replay");
        if (std::memcmp(bytes_.data(), kReplayMagic.data(), std::min(n, kReplayMagic.size())) != 0)
            fail(name_ + " is not a Spindrift replay (it does not start with the replay magic)");
        if (n >= 12) {
            const uint32_t version = get_u32(&bytes_[8]);
            if (version != kReplayVersion)
                fail(name_ + " is replay format version " + to_string(version) + "; this build reads version " +
                     to_string(kReplayVersion) +
                     (version < kReplayVersion ? " (re-record it from its .script, or with the build that made it)"
                                               : ""));
        }
        if (n < kHeaderPrefixBytes)
            fail(name_ + " is cut inside its header (" + to_string(n) + " of at least " +
                 to_string(kMinHeaderBytes) + " bytes)");
        const uint32_t header_size = get_u32(&bytes_[12]);
        if (header_size < kMinHeaderBytes || header_size > kMaxHeaderBytes)
            fail(name_ + " declares a header of " + to_string(header_size) + " bytes; a version " +
                 to_string(kReplayVersion) + " header is " + to_string(kMinHeaderBytes) + ".." +
                 to_string(kMaxHeaderBytes) + " bytes");
        if (n < header_size)
            fail(name_ + " is cut inside its header (" + to_string(n) + " of " + to_string(header_size) +
                 " bytes)");
        const size_t fields_end = header_size - kCrcBytes;
        const uint32_t stored = get_u32(&bytes_[fields_end]);
        const uint32_t computed = crc_of(0, fields_end);
        if (stored != computed)
            fail(name_ + ": the header fails its CRC (stored " + hex32(stored) + ", computed " + hex32(computed) +
                 ")");

        HeaderCursor in(&bytes_[kHeaderPrefixBytes], fields_end - kHeaderPrefixBytes, name_);
        h.level_id = in.str("level_id", kMaxLevelIdBytes);
        h.level_hash = in.u64("level_hash");
        h.seed = in.u64("seed");
        h.tick_rate_hz = in.u32("tick_rate_hz");
        h.sim_signature = in.u64("sim_signature");
        h.frame_width = in.u32("frame_width");
        h.frame_height = in.u32("frame_height");
        const uint32_t checkpoint_count = in.count("checkpoints", kMaxCheckpoints);
        h.checkpoints.reserve(checkpoint_count);
        for (uint32_t i = 0; i < checkpoint_count; ++i) h.checkpoints.push_back(in.u32("checkpoints"));
        const uint32_t shot_count = in.count("camera_shots", kMaxCameraShots);
        h.camera_shots.reserve(shot_count);
        for (uint32_t i = 0; i < shot_count; ++i) {
            CameraShot& s = h.camera_shots.emplace_back();
            s.tick = in.u32("camera_shots");
            s.kind = CameraShotKind(in.u8("camera_shots"));  // checked with the rest below
            for (float* v : {&s.point.x, &s.point.y, &s.point.z, &s.target.x, &s.target.y, &s.target.z,
                             &s.radius_m, &s.height_m, &s.deg_per_s, &s.start_deg, &s.fov_deg})
                *v = in.f32("camera_shots");
        }
        const uint32_t subsystem_count = in.count("subsystem_names", kMaxSubsystems);
        h.subsystem_names.reserve(subsystem_count);
        for (uint32_t i = 0; i < subsystem_count; ++i)
            h.subsystem_names.push_back(in.str("subsystem_names", kMaxSubsystemNameBytes));
        h.sim_params = in.str("sim_params", kMaxSimParamsBytes);
        if (in.left() != 0)
            fail(name_ + ": the header has " + to_string(in.left()) + " unexplained bytes after its fields");
        if (std::string problem = replay_header_problem(h); !problem.empty())
            fail(name_ + ": invalid header: " + problem);
        return header_size;
    }

    static bool is_prefix_of(std::span<const uint8_t> part, const std::array<uint8_t, 4>& tag) {
        return std::equal(part.begin(), part.end(), tag.begin());
    }

    static std::string chunk_label(uint32_t index, uint32_t first, uint32_t count) {
        const uint64_t last = uint64_t(first) + count - 1;  // 64-bit: a forged first tick must not wrap
        return "chunk " + to_string(index) + " (ticks " + to_string(first) + ".." + to_string(last) + ")";
    }

    void parse_records(Replay& replay, size_t pos) const {
        const size_t n = bytes_.size();
        const size_t part_count = replay.header.subsystem_names.size();
        uint32_t ticks = 0, chunks = 0;
        // The last record is incomplete (or missing): keep the whole chunks read so far.
        auto cut = [&](const std::string& where) {
            if (options_.strict)
                fail(name_ + " was cut after tick " + to_string(ticks) + " (byte " + to_string(pos) + " of " +
                     to_string(n) + ", " + where + "); --strict refuses it");
            replay.complete = false;
            replay.cut_note = "recording was cut after tick " + to_string(ticks) + " (byte " +
                              to_string(pos) + " of " + to_string(n) + ", " + where + "): replaying the " +
                              to_string(ticks) + " ticks of its " + to_string(chunks) + " complete chunks";
        };
        for (;;) {
            const size_t left = n - pos;
            if (left == 0) return cut("no end record");
            const std::span<const uint8_t> tag = bytes_.subspan(pos, std::min<size_t>(left, 4));
            if (is_prefix_of(tag, kChunkTag)) {
                if (left < kChunkHeaderBytes) return cut("inside chunk " + to_string(chunks));
                const uint32_t stored = get_u32(&bytes_[pos + 16]);
                if (stored != crc_of(pos, 16))
                    fail(name_ + ": chunk " + to_string(chunks) + " (from tick " + to_string(ticks) + ", at byte " +
                         to_string(pos) + ") fails its CRC (chunk header)");
                const uint32_t first = get_u32(&bytes_[pos + 4]);
                const uint32_t count = get_u32(&bytes_[pos + 8]);
                const uint32_t parts = get_u32(&bytes_[pos + 12]);
                if (count == 0 || count > kMaxChunkTicks)
                    fail(name_ + ": chunk " + to_string(chunks) + " at byte " + to_string(pos) + " holds " +
                         to_string(count) + " ticks; a chunk holds 1.." + to_string(kMaxChunkTicks));
                if (first != ticks)
                    fail(name_ + ": " + chunk_label(chunks, first, count) + " does not follow on: the previous chunks end at tick " +
                         to_string(ticks));
                if (parts != part_count)
                    fail(name_ + ": " + chunk_label(chunks, first, count) + " has " + to_string(parts) +
                         " subsystem hashes; the header names " + to_string(part_count) + " subsystems");
                if (uint64_t(ticks) + count > kMaxReplayTicks)
                    fail(name_ + ": " + chunk_label(chunks, first, count) + " goes past the " + to_string(kMaxReplayTicks) +
                         "-tick limit of a replay");
                const size_t payload = chunk_payload_bytes(count, parts);
                if (left < kChunkHeaderBytes + payload + kCrcBytes)
                    return cut("inside " + chunk_label(chunks, first, count));
                const size_t at = pos + kChunkHeaderBytes;
                if (get_u32(&bytes_[at + payload]) != crc_of(at, payload))
                    fail(name_ + ": " + chunk_label(chunks, first, count) + " fails its CRC (payload at byte " + to_string(at) + ")");
                for (uint32_t i = 0; i < count; ++i) {
                    const uint8_t* p = &bytes_[at + kInputBytes * i];
                    const sim::TickInput input{get_u16(p), p[2], p[3], int8_t(p[4])};
                    if (sim::quantise(input).held != input.held)
                        fail(name_ + ": " + chunk_label(chunks, first, count) + ": the input of tick " + to_string(first + i) +
                             " has unknown control bits (" + hex32(input.held) + ")");
                    if (sim::quantise(input) != input)
                        fail(name_ + ": " + chunk_label(chunks, first, count) + ": the input of tick " + to_string(first + i) +
                             " steers " + to_string(int(input.steer)) + ", beyond full scale (" +
                             to_string(sim::kSteerFullScale) + ")");
                    replay.inputs.push_back(input);
                }
                const size_t world_at = at + kInputBytes * size_t(count);
                for (uint32_t i = 0; i < count; ++i)
                    replay.tick_world_hashes.push_back(get_u64(&bytes_[world_at + 8 * i]));
                const size_t fingerprints_at = world_at + 8 * size_t(count);
                const size_t parts_at = fingerprints_at + size_t(count) * parts;
                const std::span<const uint8_t> fingerprints =
                    bytes_.subspan(fingerprints_at, parts_at - fingerprints_at);
                replay.tick_fingerprints.insert(replay.tick_fingerprints.end(), fingerprints.begin(),
                                                fingerprints.end());
                ReplayCheckpointHash& h = replay.hashes.emplace_back();
                h.tick = first + count;
                h.hash.world = replay.tick_world_hashes.back();  // stored once, as the last tick's
                h.hash.parts.reserve(parts);
                const uint8_t* last_fingerprints = &fingerprints[fingerprints.size() - parts];
                for (uint32_t i = 0; i < parts; ++i) {
                    h.hash.parts.push_back(get_u64(&bytes_[parts_at + 8 * i]));
                    // Both were written from one hash: a mismatch is a forged or broken writer.
                    if (part_fingerprint(h.hash.parts.back()) != last_fingerprints[i])
                        fail(name_ + ": " + chunk_label(chunks, first, count) + ": the fingerprint of subsystem '" +
                             replay.header.subsystem_names[i] + "' at its last tick does not match its stored hash");
                }
                pos += kChunkHeaderBytes + payload + kCrcBytes;
                ticks += count;
                ++chunks;
            } else if (is_prefix_of(tag, kEndTag)) {
                if (left < kEndRecordBytes) return cut("inside the end record");
                if (get_u32(&bytes_[pos + 12]) != crc_of(pos, 12))
                    fail(name_ + ": the end record at byte " + to_string(pos) + " fails its CRC");
                const uint32_t end_ticks = get_u32(&bytes_[pos + 4]);
                const uint32_t end_chunks = get_u32(&bytes_[pos + 8]);
                if (end_ticks != ticks || end_chunks != chunks)
                    fail(name_ + ": the end record counts " + to_string(end_ticks) + " ticks in " +
                         to_string(end_chunks) + " chunks, but the file holds " + to_string(ticks) + " ticks in " +
                         to_string(chunks) + " chunks");
                if (left > kEndRecordBytes)
                    fail(name_ + ": trailing garbage after the end record (" + to_string(left - kEndRecordBytes) +
                         " bytes)");
                return;
            } else {
                fail(name_ + ": unexpected bytes at offset " + to_string(pos) + ": not a chunk (after tick " +
                     to_string(ticks) + ")");
            }
        }
    }

    std::span<const uint8_t> bytes_;
    std::string name_;
    ReadOptions options_;
};

// Closes the descriptor on every exit path.
struct FdCloser {
    int fd;
    ~FdCloser() { ::close(fd); }
};

}  // namespace

Replay parse_replay(std::span<const uint8_t> bytes, std::string_view name, const ReadOptions& options) {
    return ReplayParser(bytes, name, options).parse();
}

Replay read_replay(const std::filesystem::path& path, const ReadOptions& options) {
    const std::string name = path.string();
    // O_NONBLOCK so that opening a FIFO cannot hang; anything but a regular file is refused.
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) {
        const int err = errno;
        std::error_code ec;
        // A recording that was killed or failed keeps what it had under NAME.partial.
        const std::string hint = err == ENOENT && std::filesystem::is_regular_file(name + ".partial", ec)
                                     ? " (a recording cut short is at " + name + ".partial: replay that)"
                                     : "";
        throw ReplayError("cannot open replay " + name + ": " + std::strerror(err) + hint);
    }
    FdCloser closer{fd};
    struct stat st {};
    if (::fstat(fd, &st) != 0) throw ReplayError("cannot read replay " + name + ": " + std::strerror(errno));
    if (!S_ISREG(st.st_mode)) throw ReplayError("cannot read replay " + name + ": not a regular file");
    const uint64_t size = uint64_t(st.st_size);
    if (size > kMaxReplayFileBytes)
        throw ReplayError(name + " is " + to_string(size) + " bytes, more than the " +
                          to_string(kMaxReplayFileBytes >> 20) + " MiB a replay may be");
    std::vector<uint8_t> bytes(size);
    size_t got = 0;
    while (got < bytes.size()) {
        const ssize_t r = ::read(fd, bytes.data() + got, bytes.size() - got);
        if (r < 0 && errno == EINTR) continue;
        if (r < 0) throw ReplayError("cannot read replay " + name + ": " + std::strerror(errno));
        if (r == 0) break;  // the file shrank meanwhile: parse what is there
        got += size_t(r);
    }
    bytes.resize(got);
    return parse_replay(bytes, name, options);
}

}  // namespace game
