#pragma once
// The replay file layout shared by ReplayWriter and the reader. All integers little-endian.
//
//   header : magic[8] version:u32 header_size:u32            (header_size counts the whole header)
//            level_id:str level_hash:u64 seed:u64 tick_rate_hz:u32 sim_signature:u64
//            frame_width:u32 frame_height:u32
//            checkpoint_count:u32 checkpoint:u32[count]
//            camera_shot_count:u32 camera_shot[count]         (ascending ticks, see CameraShot.h)
//              tick:u32 kind:u8 point:f32[3] target:f32[3] radius:f32 height:f32
//              deg_per_s:f32 start_deg:f32 fov_deg:f32       (f32 = IEEE 754 binary32)
//            subsystem_count:u32 subsystem_name:str[count]
//            sim_params:str                                   (str = length:u32 + bytes)
//            crc32 of all the header bytes before it
//   chunk  : "CHNK" first_tick:u32 tick_count:u32 part_count:u32 crc32(tag and these fields)
//            input[tick_count]                           input applied at each tick:
//              held:u16 throttle:u8 brake:u8 steer:i8      (sim::TickInput, 5 bytes)
//            world_hash:u64[tick_count]                  world hash after each tick
//            fingerprint:u8[tick_count][part_count]      low byte of each subsystem hash after each tick
//            part_hash:u64[part_count]                   full subsystem hashes after the chunk's last tick
//            crc32(that payload)
//            Per-tick hashes let a checker name the first diverging tick; the fingerprints name
//            its subsystem (a one-byte fingerprint misses a difference with probability 1/256).
//            The chunk-end world hash is the last world_hash entry: it is not stored twice.
//   end    : "END!" total_ticks:u32 chunk_count:u32 crc32(tag and these fields)
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "game/replay/CameraShot.h"

namespace game {

inline constexpr std::array<uint8_t, 8> kReplayMagic = {'S', 'P', 'D', 'R', 'I', 'F', 'T', 0x1A};
// 4: the scripted camera shots in the header (version 3 had none). 3: analog throttle,
// brake and steering beside the held controls (version 2 had the held controls alone).
// The reader refuses older versions with a note to re-record them from their scripts.
inline constexpr uint32_t kReplayVersion = 4;

inline constexpr uint32_t kChunkTicks = 60;        // the writer's chunk length: one second
inline constexpr uint32_t kMaxChunkTicks = 600;    // the reader accepts chunks up to this length
inline constexpr uint32_t kMaxReplayTicks = 60u * 60u * 60u * 4u;  // four hours at 60 Hz
inline constexpr uint64_t kMaxReplayFileBytes = 256ull << 20;

inline constexpr size_t kMaxLevelIdBytes = 64;
inline constexpr size_t kMaxCheckpoints = 1024;
inline constexpr size_t kMaxCameraShots = 1024;
inline constexpr size_t kCameraShotBytes = 4 + 1 + 11 * 4;  // tick, kind, 11 floats
inline constexpr size_t kMaxSubsystems = 32;
inline constexpr size_t kMaxSubsystemNameBytes = 32;
inline constexpr size_t kMaxSimParamsBytes = 64u << 10;
inline constexpr uint32_t kMinFrameSide = 16, kMaxFrameSide = 4096;
inline constexpr uint32_t kMaxTickRateHz = 1000;

inline constexpr std::array<uint8_t, 4> kChunkTag = {'C', 'H', 'N', 'K'};
inline constexpr std::array<uint8_t, 4> kEndTag = {'E', 'N', 'D', '!'};
inline constexpr size_t kCrcBytes = 4;
inline constexpr size_t kHeaderPrefixBytes = 16;   // magic, version, header_size
inline constexpr size_t kChunkHeaderBytes = 20;    // tag, 3 fields, crc
inline constexpr size_t kEndRecordBytes = 16;      // tag, 2 fields, crc
inline constexpr size_t kInputBytes = 5;           // held:u16 throttle:u8 brake:u8 steer:i8

// Bytes of a chunk's payload (without its CRC): per tick an input, a world hash and one
// fingerprint byte per subsystem, then the full subsystem hashes after the last tick.
inline constexpr size_t chunk_payload_bytes(size_t tick_count, size_t part_count) {
    return tick_count * (kInputBytes + 8 + part_count) + 8 * part_count;
}
// The fingerprint stored per tick and subsystem: enough to name which subsystem differs.
inline constexpr uint8_t part_fingerprint(uint64_t part_hash) { return uint8_t(part_hash); }

// Smallest and largest header any valid ReplayHeader encodes to: the reader checks the
// declared header_size against these before reading further.
inline constexpr size_t kMinHeaderBytes =
    kHeaderPrefixBytes + (4 + 1) + 8 + 8 + 4 + 8 + 4 + 4 + 4 + 4 + (4 + 4 + 1) + 4 + kCrcBytes;
inline constexpr size_t kMaxHeaderBytes =
    kHeaderPrefixBytes + (4 + kMaxLevelIdBytes) + 8 + 8 + 4 + 8 + 4 + 4 + (4 + 4 * kMaxCheckpoints) +
    (4 + kCameraShotBytes * kMaxCameraShots) +
    (4 + kMaxSubsystems * (4 + kMaxSubsystemNameBytes)) + (4 + kMaxSimParamsBytes) + kCrcBytes;

struct ReplayHeader {
    std::string level_id;               // 1..64 bytes
    uint64_t level_hash = 0;            // content hash of the level files
    uint64_t seed = 0;
    uint32_t tick_rate_hz = 60;         // 1..1000
    uint64_t sim_signature = 0;         // World::sim_signature(): sim version and subsystems; a mismatch refuses the replay
    uint32_t frame_width = 480, frame_height = 270;  // checkpoint frame size, each 16..4096
    std::vector<uint32_t> checkpoints;  // ticks whose frames are checked: ascending, unique, <= 1024
    std::vector<CameraShot> camera_shots;  // the script's cameras: ascending ticks, <= 1024
    std::vector<std::string> subsystem_names;  // order of per-subsystem hashes: 1..32 names of 1..32 bytes
    std::string sim_params;             // opaque text of the sim parameters, <= 64 KiB

    bool operator==(const ReplayHeader&) const = default;
};

// Why `h` cannot be stored in a replay, or "" if it can. Shared by writer and reader so
// that whatever one writes the other accepts.
inline std::string replay_header_problem(const ReplayHeader& h) {
    using std::to_string;
    if (h.level_id.empty()) return "the level id is empty";
    if (h.level_id.size() > kMaxLevelIdBytes)
        return "the level id is " + to_string(h.level_id.size()) + " bytes, more than " +
               to_string(kMaxLevelIdBytes);
    if (h.tick_rate_hz == 0 || h.tick_rate_hz > kMaxTickRateHz)
        return "the tick rate " + to_string(h.tick_rate_hz) + " Hz is outside 1.." +
               to_string(kMaxTickRateHz);
    if (h.frame_width < kMinFrameSide || h.frame_width > kMaxFrameSide || h.frame_height < kMinFrameSide ||
        h.frame_height > kMaxFrameSide)
        return "the frame size " + to_string(h.frame_width) + "x" + to_string(h.frame_height) +
               " is outside " + to_string(kMinFrameSide) + ".." + to_string(kMaxFrameSide) + " per side";
    if (h.checkpoints.size() > kMaxCheckpoints)
        return to_string(h.checkpoints.size()) + " checkpoints, more than " + to_string(kMaxCheckpoints);
    for (size_t i = 0; i < h.checkpoints.size(); ++i) {
        if (h.checkpoints[i] >= kMaxReplayTicks)
            return "checkpoint tick " + to_string(h.checkpoints[i]) + " is beyond the " +
                   to_string(kMaxReplayTicks) + "-tick limit";
        if (i > 0 && h.checkpoints[i] <= h.checkpoints[i - 1])
            return "checkpoints are not ascending and unique (" + to_string(h.checkpoints[i]) + " follows " +
                   to_string(h.checkpoints[i - 1]) + ")";
    }
    if (h.camera_shots.size() > kMaxCameraShots)
        return to_string(h.camera_shots.size()) + " camera shots, more than " + to_string(kMaxCameraShots);
    for (size_t i = 0; i < h.camera_shots.size(); ++i) {
        const uint32_t tick = h.camera_shots[i].tick;
        if (tick >= kMaxReplayTicks)
            return "camera shot tick " + to_string(tick) + " is beyond the " + to_string(kMaxReplayTicks) +
                   "-tick limit";
        if (i > 0 && tick <= h.camera_shots[i - 1].tick)
            return "camera shots are not in ascending tick order (" + to_string(tick) + " follows " +
                   to_string(h.camera_shots[i - 1].tick) + ")";
        if (std::string problem = camera_shot_problem(h.camera_shots[i]); !problem.empty())
            return "camera shot at tick " + to_string(tick) + ": " + problem;
    }
    if (h.subsystem_names.empty() || h.subsystem_names.size() > kMaxSubsystems)
        return to_string(h.subsystem_names.size()) + " subsystem names, expected 1.." +
               to_string(kMaxSubsystems);
    for (const std::string& name : h.subsystem_names)
        if (name.empty() || name.size() > kMaxSubsystemNameBytes)
            return "subsystem name '" + name.substr(0, kMaxSubsystemNameBytes) + "' is " +
                   to_string(name.size()) + " bytes, expected 1.." + to_string(kMaxSubsystemNameBytes);
    if (h.sim_params.size() > kMaxSimParamsBytes)
        return "the sim parameters are " + to_string(h.sim_params.size()) + " bytes, more than " +
               to_string(kMaxSimParamsBytes);
    return {};
}

// Little-endian encoding, independent of the host byte order.
namespace replay_bytes {

inline void put_u16(std::vector<uint8_t>& out, uint16_t v) {
    out.push_back(uint8_t(v));
    out.push_back(uint8_t(v >> 8));
}
inline void put_u32(std::vector<uint8_t>& out, uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(uint8_t(v >> (8 * i)));
}
inline void put_u64(std::vector<uint8_t>& out, uint64_t v) {
    for (int i = 0; i < 8; ++i) out.push_back(uint8_t(v >> (8 * i)));
}
inline uint16_t get_u16(const uint8_t* p) { return uint16_t(p[0] | (p[1] << 8)); }
inline uint32_t get_u32(const uint8_t* p) {
    return uint32_t(p[0]) | (uint32_t(p[1]) << 8) | (uint32_t(p[2]) << 16) | (uint32_t(p[3]) << 24);
}
inline uint64_t get_u64(const uint8_t* p) { return uint64_t(get_u32(p)) | (uint64_t(get_u32(p + 4)) << 32); }
inline void put_f32(std::vector<uint8_t>& out, float v) { put_u32(out, std::bit_cast<uint32_t>(v)); }
inline float get_f32(const uint8_t* p) { return std::bit_cast<float>(get_u32(p)); }

}  // namespace replay_bytes
}  // namespace game
