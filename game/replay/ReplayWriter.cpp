#include "game/replay/ReplayWriter.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>

#include "game/replay/Crc32.h"
#include "game/replay/ReplayError.h"

namespace game {
namespace {

using namespace replay_bytes;

void put_str(std::vector<uint8_t>& out, const std::string& s) {
    put_u32(out, uint32_t(s.size()));
    out.insert(out.end(), s.begin(), s.end());
}

// CRC of bytes [from, end) appended to `out`.
void put_crc_since(std::vector<uint8_t>& out, size_t from) {
    put_u32(out, crc32(std::span<const uint8_t>(out.data() + from, out.size() - from)));
}

std::vector<uint8_t> encode_header(const ReplayHeader& h) {
    std::vector<uint8_t> out(kReplayMagic.begin(), kReplayMagic.end());
    put_u32(out, kReplayVersion);
    const size_t size_at = out.size();
    put_u32(out, 0);  // header_size, patched below
    put_str(out, h.level_id);
    put_u64(out, h.level_hash);
    put_u64(out, h.seed);
    put_u32(out, h.tick_rate_hz);
    put_u64(out, h.sim_signature);
    put_u32(out, h.frame_width);
    put_u32(out, h.frame_height);
    put_u32(out, uint32_t(h.checkpoints.size()));
    for (uint32_t tick : h.checkpoints) put_u32(out, tick);
    put_u32(out, uint32_t(h.camera_shots.size()));
    for (const CameraShot& shot : h.camera_shots) {
        put_u32(out, shot.tick);
        out.push_back(uint8_t(shot.kind));
        for (float v : {shot.point.x, shot.point.y, shot.point.z, shot.target.x, shot.target.y, shot.target.z,
                        shot.radius_m, shot.height_m, shot.deg_per_s, shot.start_deg, shot.fov_deg})
            put_f32(out, v);
    }
    put_u32(out, uint32_t(h.subsystem_names.size()));
    for (const std::string& name : h.subsystem_names) put_str(out, name);
    put_str(out, h.sim_params);
    const uint32_t header_size = uint32_t(out.size() + kCrcBytes);
    for (int i = 0; i < 4; ++i) out[size_at + i] = uint8_t(header_size >> (8 * i));
    put_crc_since(out, 0);
    return out;
}

}  // namespace

std::filesystem::path partial_replay_path(const std::filesystem::path& path) {
    std::filesystem::path partial = path;
    partial += ".partial";
    return partial;
}

ReplayWriter ReplayWriter::create(const std::filesystem::path& path, const ReplayHeader& header) {
    if (std::string problem = replay_header_problem(header); !problem.empty())
        throw ReplayError("cannot record replay " + path.string() + ": " + problem);
    const std::filesystem::path partial = partial_replay_path(path);
    const int fd = ::open(partial.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0)
        throw ReplayWriteError("cannot create replay " + partial.string() + ": " + std::strerror(errno));
    ReplayWriter writer(path, fd, header.subsystem_names.size());
    try {
        writer.write_record(encode_header(header));
    } catch (...) {
        writer.discard();
        throw;
    }
    return writer;
}

ReplayWriter::ReplayWriter(std::filesystem::path path, int fd, size_t part_count)
    : path_(std::move(path)), partial_path_(partial_replay_path(path_)), fd_(fd), part_count_(part_count) {
    pending_inputs_.reserve(kChunkTicks);
    pending_world_hashes_.reserve(kChunkTicks);
    pending_fingerprints_.reserve(kChunkTicks * part_count_);
}

ReplayWriter::ReplayWriter(ReplayWriter&& other) noexcept
    : path_(std::move(other.path_)),
      partial_path_(std::move(other.partial_path_)),
      fd_(std::exchange(other.fd_, -1)),
      part_count_(other.part_count_),
      ticks_(other.ticks_),
      chunks_(other.chunks_),
      pending_inputs_(std::move(other.pending_inputs_)),
      pending_world_hashes_(std::move(other.pending_world_hashes_)),
      pending_fingerprints_(std::move(other.pending_fingerprints_)),
      pending_parts_(std::move(other.pending_parts_)),
      finished_(std::exchange(other.finished_, true)),
      failed_(other.failed_) {
    other.clear_pending();
}

ReplayWriter& ReplayWriter::operator=(ReplayWriter&& other) noexcept {
    if (this != &other) {
        abandon();
        path_ = std::move(other.path_);
        partial_path_ = std::move(other.partial_path_);
        fd_ = std::exchange(other.fd_, -1);
        part_count_ = other.part_count_;
        ticks_ = other.ticks_;
        chunks_ = other.chunks_;
        pending_inputs_ = std::move(other.pending_inputs_);
        pending_world_hashes_ = std::move(other.pending_world_hashes_);
        pending_fingerprints_ = std::move(other.pending_fingerprints_);
        pending_parts_ = std::move(other.pending_parts_);
        finished_ = std::exchange(other.finished_, true);
        failed_ = other.failed_;
        other.clear_pending();
    }
    return *this;
}

ReplayWriter::~ReplayWriter() { abandon(); }

void ReplayWriter::abandon() noexcept {
    if (fd_ >= 0 && !finished_ && !failed_ && !pending_inputs_.empty()) {
        try {
            write_pending_chunk();
        } catch (...) {
            // Nothing to report to from a destructor; the file stays a readable cut prefix.
        }
    }
    if (fd_ >= 0) ::close(std::exchange(fd_, -1));
}

void ReplayWriter::append(sim::TickInput input, const sim::WorldHash& after) {
    if (finished_) throw std::logic_error("replay " + path_.string() + ": append() after finish()");
    if (failed_) throw ReplayWriteError("replay " + path_.string() + ": an earlier write failed");
    if (sim::quantise(input) != input)
        throw std::logic_error("replay " + path_.string() + ": input has unknown control bits or steering beyond full scale");
    if (after.parts.size() != part_count_)
        throw std::logic_error("replay " + path_.string() + ": world hash has " +
                               std::to_string(after.parts.size()) + " parts, the header names " +
                               std::to_string(part_count_) + " subsystems");
    if (ticks_ >= kMaxReplayTicks)
        throw ReplayError("replay " + path_.string() + ": recording reached the " +
                          std::to_string(kMaxReplayTicks) + "-tick limit");
    pending_inputs_.push_back(input);
    pending_world_hashes_.push_back(after.world);
    for (uint64_t part : after.parts) pending_fingerprints_.push_back(part_fingerprint(part));
    pending_parts_ = after.parts;
    ++ticks_;
    if (pending_inputs_.size() == kChunkTicks) write_pending_chunk();
}

void ReplayWriter::finish() {
    if (finished_) throw std::logic_error("replay " + path_.string() + ": finish() called twice");
    if (failed_) throw ReplayWriteError("replay " + path_.string() + ": an earlier write failed");
    if (!pending_inputs_.empty()) write_pending_chunk();
    std::vector<uint8_t> end(kEndTag.begin(), kEndTag.end());
    put_u32(end, ticks_);
    put_u32(end, chunks_);
    put_crc_since(end, 0);
    write_record(end);
    // On disk before the rename, so that `path` never names a file the kernel had not written.
    if (::fsync(fd_) != 0) fail_write("cannot finish replay " + partial_path_.string());
    finished_ = true;
    const int fd = std::exchange(fd_, -1);
    if (::close(fd) != 0) fail_write("cannot finish replay " + partial_path_.string());
    std::error_code ec;
    std::filesystem::rename(partial_path_, path_, ec);
    if (ec)
        throw ReplayWriteError("cannot finish replay " + path_.string() + ": renaming " + partial_path_.string() +
                               " failed: " + ec.message());
}

void ReplayWriter::discard() noexcept {
    finished_ = true;
    clear_pending();
    if (fd_ >= 0) ::close(std::exchange(fd_, -1));
    if (!partial_path_.empty()) ::unlink(partial_path_.c_str());
}

void ReplayWriter::fail_write(const std::string& what) {
    const int error = errno;
    failed_ = true;
    throw ReplayWriteError(what + ": " + std::strerror(error));
}

void ReplayWriter::write_pending_chunk() {
    const uint32_t count = uint32_t(pending_inputs_.size());
    std::vector<uint8_t> chunk;
    chunk.reserve(kChunkHeaderBytes + chunk_payload_bytes(count, part_count_) + kCrcBytes);
    chunk.insert(chunk.end(), kChunkTag.begin(), kChunkTag.end());
    put_u32(chunk, ticks_ - count);
    put_u32(chunk, count);
    put_u32(chunk, uint32_t(part_count_));
    put_crc_since(chunk, 0);
    for (sim::TickInput in : pending_inputs_) {
        put_u16(chunk, in.held);
        chunk.push_back(in.throttle);
        chunk.push_back(in.brake);
        chunk.push_back(uint8_t(in.steer));
    }
    for (uint64_t world : pending_world_hashes_) put_u64(chunk, world);
    chunk.insert(chunk.end(), pending_fingerprints_.begin(), pending_fingerprints_.end());
    for (uint64_t part : pending_parts_) put_u64(chunk, part);
    put_crc_since(chunk, kChunkHeaderBytes);
    write_record(chunk);
    clear_pending();
    ++chunks_;
}

void ReplayWriter::clear_pending() noexcept {
    pending_inputs_.clear();
    pending_world_hashes_.clear();
    pending_fingerprints_.clear();
    pending_parts_.clear();
}

// One write(2) per record, straight to the kernel: a SIGKILL can then cut at most the
// record being written. The loop only continues after a short write or EINTR.
void ReplayWriter::write_record(const std::vector<uint8_t>& bytes) {
    size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd_, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) fail_write("cannot write replay " + partial_path_.string());
        if (n == 0) {
            failed_ = true;
            throw ReplayWriteError("cannot write replay " + partial_path_.string() + ": nothing written");
        }
        done += size_t(n);
    }
}

}  // namespace game
