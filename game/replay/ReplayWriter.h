#pragma once
// Records a session to a replay file a chunk at a time, so that a killed process leaves a
// readable prefix of whole chunks (see ReplayFormat.h for the layout). The chunks go to
// "<path>.partial", renamed to `path` by finish(): `path` only ever holds a finished
// recording (an older one stays whole until the new one replaces it), and a killed or
// abandoned recording is left as the .partial file, replayable up to its last whole chunk.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "game/replay/ReplayError.h"
#include "game/replay/ReplayFormat.h"
#include "sim/core/TickInput.h"
#include "sim/world/WorldHash.h"

namespace game {

// Where a recording to `path` is written until it is finished.
std::filesystem::path partial_replay_path(const std::filesystem::path& path);

class ReplayWriter {
public:
    // Creates or truncates partial_replay_path(path) and writes the header at once. Throws
    // ReplayError if `header` breaks a format limit, ReplayWriteError if the file cannot
    // be written.
    static ReplayWriter create(const std::filesystem::path& path, const ReplayHeader& header);

    ReplayWriter(ReplayWriter&& other) noexcept;
    ReplayWriter& operator=(ReplayWriter&& other) noexcept;
    ReplayWriter(const ReplayWriter&) = delete;
    ReplayWriter& operator=(const ReplayWriter&) = delete;
    // An unfinished recording keeps its buffered ticks as a last short chunk but gets no END
    // record, so the reader reports it as cut.
    ~ReplayWriter();

    // Records the input applied at the next tick and the world hash after that tick (its
    // world hash and subsystem fingerprints for every tick, its full subsystem hashes at a
    // chunk's last tick); every kChunkTicks ticks the chunk goes to the file in one write(2).
    // `input` must already be quantised and `after` must have one part per header subsystem
    // (else std::logic_error).
    void append(sim::TickInput input, const sim::WorldHash& after);
    // Writes the last partial chunk and the END record, flushes the file to disk and
    // renames it to path(). append() and finish() throw std::logic_error afterwards.
    void finish();
    // Closes and deletes the unfinished recording (after a failure, so that nothing is
    // left to be mistaken for a cut recording). The writer is finished afterwards.
    void discard() noexcept;

    uint32_t ticks() const { return ticks_; }
    const std::filesystem::path& path() const { return path_; }
    const std::filesystem::path& partial_path() const { return partial_path_; }

private:
    ReplayWriter(std::filesystem::path path, int fd, size_t part_count);
    void write_pending_chunk();
    void clear_pending() noexcept;
    void write_record(const std::vector<uint8_t>& bytes);
    [[noreturn]] void fail_write(const std::string& what);  // marks the writer failed, names errno
    void abandon() noexcept;  // flushes buffered ticks (best effort) and closes

    std::filesystem::path path_;
    std::filesystem::path partial_path_;  // where the chunks go until finish()
    int fd_ = -1;
    size_t part_count_ = 0;
    uint32_t ticks_ = 0;        // ticks appended so far
    uint32_t chunks_ = 0;       // chunks written so far
    std::vector<sim::TickInput> pending_inputs_;  // ticks not yet written
    std::vector<uint64_t> pending_world_hashes_;  // world hash after each pending tick
    std::vector<uint8_t> pending_fingerprints_;   // part_count_ fingerprints per pending tick
    std::vector<uint64_t> pending_parts_;         // subsystem hashes after the last pending tick
    bool finished_ = false;
    bool failed_ = false;       // a write failed: the file no longer matches our counters
};

}  // namespace game
