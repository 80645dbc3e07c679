// Replay files: CRC, round trips, every kind of damage, fuzzed input, a recording
// killed mid-session (the checker's tests are in replay_check_test.cpp).
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <bit>
#include <chrono>
#include <limits>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "ReplayFile.h"
#include "SimTestLevel.h"
#include "game/replay/Crc32.h"
#include "game/replay/ReplayCheck.h"
#include "game/replay/ReplayReader.h"
#include "game/replay/ReplayWriter.h"

namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<uint8_t>;

using replay_test::ReplayFile;
using replay_test::test_camera_shots;
using replay_test::test_header;

// Where the header's camera shot count is (the first shot follows it), from the documented layout.
size_t camera_shots_offset(const game::ReplayHeader& h) {
    return 16 + 4 + h.level_id.size() + 8 + 8 + 4 + 8 + 4 + 4 + 4 + 4 * h.checkpoints.size();
}


uint64_t mix(uint64_t x) {  // splitmix64 finaliser: distinct, well-spread test values
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

// Held controls and analog axes over their whole ranges (steering -127..127).
sim::TickInput input_at(uint32_t tick) {
    const uint64_t m = mix(tick);
    return sim::TickInput{uint16_t(m & sim::kAllControls), uint8_t(m >> 16), uint8_t(m >> 24),
                          int8_t(int((m >> 32) % 255) - sim::kSteerFullScale)};
}

sim::WorldHash hash_after(uint32_t tick, size_t parts = 3) {
    sim::WorldHash h;
    h.world = mix(tick * 7919ull + 1);
    for (size_t i = 0; i < parts; ++i) h.parts.push_back(mix(tick * 7919ull + 2 + i));
    return h;
}

void write_replay(const fs::path& path, uint32_t ticks, bool finish = true, size_t parts = 3) {
    auto writer = game::ReplayWriter::create(path, test_header(parts));
    for (uint32_t t = 0; t < ticks; ++t) writer.append(input_at(t), hash_after(t + 1, parts));
    EXPECT_EQ(writer.ticks(), ticks);
    if (finish) writer.finish();
}

Bytes read_bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return Bytes(std::istreambuf_iterator<char>(in), {});
}

void write_bytes(const fs::path& path, const Bytes& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

uint32_t get_u32(const Bytes& b, size_t at) { return game::replay_bytes::get_u32(&b[at]); }
void set_u32(Bytes& b, size_t at, uint32_t v) {
    for (int i = 0; i < 4; ++i) b[at + i] = uint8_t(v >> (8 * i));
}
// Recomputes the CRC stored after bytes [from, to), as a deliberate forger would.
void fix_crc(Bytes& b, size_t from, size_t to) {
    set_u32(b, to, game::crc32(std::span<const uint8_t>(b.data() + from, to - from)));
}

size_t header_size(const Bytes& b) { return get_u32(b, 12); }
// The on-disk size of a chunk record, straight from the documented layout: header, per tick
// an input, a world hash and a fingerprint per part, the last tick's full parts, CRC.
size_t chunk_record_size(uint32_t ticks, size_t parts = 3) { return 20 + ticks * (5 + 8 + parts) + 8 * parts + 4; }

// Every per-tick hash and fingerprint of `r` is the one write_replay() stored.
void expect_tick_hashes(const game::Replay& r, size_t parts = 3) {
    ASSERT_EQ(r.tick_world_hashes.size(), r.inputs.size());
    ASSERT_EQ(r.tick_fingerprints.size(), r.inputs.size() * parts);
    for (uint32_t t = 0; t < r.inputs.size(); ++t) {
        const sim::WorldHash want = hash_after(t + 1, parts);
        ASSERT_EQ(r.tick_world_hashes[t], want.world) << t;
        for (size_t p = 0; p < parts; ++p) ASSERT_EQ(r.tick_fingerprints[t * parts + p], uint8_t(want.parts[p])) << t;
    }
}

// Runs `f`, which must throw ReplayError whose message holds every one of `words`.
void expect_replay_error(const std::function<void()>& f, std::initializer_list<std::string> words) {
    try {
        f();
        ADD_FAILURE() << "no ReplayError thrown; expected one mentioning " << *words.begin();
    } catch (const game::ReplayError& e) {
        const std::string message = e.what();
        for (const std::string& w : words) EXPECT_NE(message.find(w), std::string::npos) << message << "\nlacks: " << w;
    }
}

game::Replay parse(const Bytes& b, bool strict = false) {
    return game::parse_replay(b, "test.replay", game::ReadOptions{strict});
}

TEST(ReplayCrc32, MatchesTheStandardCheckValue) {
    const std::string check = "123456789";
    EXPECT_EQ(game::crc32(std::span(reinterpret_cast<const uint8_t*>(check.data()), check.size())), 0xCBF43926u);
    EXPECT_EQ(game::crc32({}), 0u);
    const uint8_t zero = 0;
    EXPECT_EQ(game::crc32(std::span(&zero, 1)), 0xD202EF8Du);
}

TEST_F(ReplayFile, RoundTripsHeaderInputsAndHashes) {
    for (uint32_t ticks : {0u, 1u, 59u, 60u, 61u, 137u, 600u}) {
        SCOPED_TRACE(ticks);
        const fs::path path = file("round.replay");
        write_replay(path, ticks);
        const game::Replay r = game::read_replay(path);
        EXPECT_TRUE(r.complete);
        EXPECT_TRUE(r.cut_note.empty());
        EXPECT_EQ(r.header, test_header());
        ASSERT_EQ(r.inputs.size(), ticks);
        for (uint32_t t = 0; t < ticks; ++t) ASSERT_EQ(r.inputs[t], input_at(t)) << t;
        expect_tick_hashes(r);
        ASSERT_EQ(r.hashes.size(), (ticks + 59) / 60);
        for (size_t c = 0; c < r.hashes.size(); ++c) {
            const uint32_t end = std::min<uint32_t>(uint32_t(c + 1) * 60, ticks);
            EXPECT_EQ(r.hashes[c].tick, end);
            EXPECT_EQ(r.hashes[c].hash, hash_after(end));
        }
        const Bytes bytes = read_bytes(path);
        size_t expected = header_size(bytes) + 16;
        for (uint32_t done = 0; done < ticks; done += 60) expected += chunk_record_size(std::min(60u, ticks - done));
        EXPECT_EQ(bytes.size(), expected);
    }
}

TEST_F(ReplayFile, RoundTripsAHeaderAtEveryLimit) {
    game::ReplayHeader h = test_header();
    h.level_id = std::string(64, 'L');
    h.checkpoints.clear();
    for (uint32_t i = 0; i < 1024; ++i) h.checkpoints.push_back(i * 3);
    h.camera_shots.clear();
    for (uint32_t i = 0; i < 1024; ++i) {
        game::CameraShot shot = test_camera_shots()[i % 3];
        shot.tick = i;
        h.camera_shots.push_back(shot);
    }
    h.subsystem_names.clear();
    for (int i = 0; i < 32; ++i) h.subsystem_names.push_back(std::string(31, 'a') + char('A' + i % 26));
    h.sim_params = std::string(64 << 10, 'p');
    h.frame_width = 4096;
    h.frame_height = 16;
    const fs::path path = file("big.replay");
    auto writer = game::ReplayWriter::create(path, h);
    for (uint32_t t = 0; t < 70; ++t) writer.append(input_at(t), hash_after(t + 1, 32));
    writer.finish();
    const game::Replay r = game::read_replay(path);
    EXPECT_EQ(r.header, h);
    EXPECT_EQ(r.inputs.size(), 70u);
    expect_tick_hashes(r, 32);
    EXPECT_EQ(read_bytes(path).size(),
              game::kMaxHeaderBytes + chunk_record_size(60, 32) + chunk_record_size(10, 32) + 16);
    EXPECT_EQ(header_size(read_bytes(path)), game::kMaxHeaderBytes);
}

TEST_F(ReplayFile, WriterRefusesBadHeadersAndMisuse) {
    game::ReplayHeader h = test_header();
    h.level_id.clear();
    expect_replay_error([&] { game::ReplayWriter::create(file("a.replay"), h); }, {"a.replay", "level id"});
    h = test_header();
    h.checkpoints = {300, 90};
    expect_replay_error([&] { game::ReplayWriter::create(file("a.replay"), h); }, {"ascending"});
    h = test_header();
    h.frame_width = 8;
    expect_replay_error([&] { game::ReplayWriter::create(file("a.replay"), h); }, {"frame size"});
    expect_replay_error([&] { game::ReplayWriter::create(file("no/such/dir.replay"), test_header()); },
                        {"no/such/dir.replay", "cannot create"});

    auto writer = game::ReplayWriter::create(file("b.replay"), test_header());
    EXPECT_THROW(writer.append(input_at(0), hash_after(1, 2)), std::logic_error);
    EXPECT_THROW(writer.append(sim::TickInput{0x8000}, hash_after(1)), std::logic_error);
    EXPECT_THROW(writer.append(sim::TickInput{0, 0, 0, -128}, hash_after(1)), std::logic_error);
    writer.append(input_at(0), hash_after(1));
    game::ReplayWriter moved = std::move(writer);
    moved.finish();
    EXPECT_THROW(moved.append(input_at(1), hash_after(2)), std::logic_error);
    EXPECT_THROW(moved.finish(), std::logic_error);
    EXPECT_EQ(game::read_replay(file("b.replay")).inputs.size(), 1u);
}

TEST_F(ReplayFile, UnfinishedWriterKeepsItsTicksAsACutRecording) {
    write_replay(file("u.replay"), 130, /*finish=*/false);
    EXPECT_FALSE(fs::exists(file("u.replay")));  // only a finished recording gets the final name
    const fs::path partial = game::partial_replay_path(file("u.replay"));
    const game::Replay r = game::read_replay(partial);
    EXPECT_FALSE(r.complete);
    EXPECT_EQ(r.inputs.size(), 130u);
    EXPECT_NE(r.cut_note.find("cut after tick 130"), std::string::npos) << r.cut_note;
    EXPECT_NE(r.cut_note.find("no end record"), std::string::npos) << r.cut_note;
    expect_replay_error([&] { game::read_replay(partial, {.strict = true}); }, {"--strict", "130"});
}

TEST_F(ReplayFile, CutInsideTheHeaderIsRefusedAtEveryByte) {
    write_replay(file("h.replay"), 10);
    const Bytes full = read_bytes(file("h.replay"));
    const size_t size = header_size(full);
    expect_replay_error([&] { parse(Bytes{}); }, {"test.replay", "empty"});
    for (size_t cut = 1; cut < size; ++cut) {
        SCOPED_TRACE(cut);
        const Bytes prefix(full.begin(), full.begin() + ptrdiff_t(cut));
        const std::string of = cut < 16 ? "(" + std::to_string(cut) + " of at least"
                                        : "(" + std::to_string(cut) + " of " + std::to_string(size) + " bytes)";
        expect_replay_error([&] { parse(prefix); }, {"test.replay", "cut inside its header", of});
    }
}

TEST_F(ReplayFile, CutInsideRecordsKeepsTheWholeChunks) {
    write_replay(file("c.replay"), 137);  // chunks of 60, 60 and 17 ticks, then END
    const Bytes full = read_bytes(file("c.replay"));
    const size_t h = header_size(full);
    const size_t ends[] = {h + chunk_record_size(60), h + 2 * chunk_record_size(60),
                           h + 2 * chunk_record_size(60) + chunk_record_size(17)};
    ASSERT_EQ(ends[2] + 16, full.size());
    for (size_t cut = h; cut < full.size(); ++cut) {
        SCOPED_TRACE(cut);
        const Bytes prefix(full.begin(), full.begin() + ptrdiff_t(cut));
        const size_t whole = size_t(std::count_if(std::begin(ends), std::end(ends), [&](size_t e) { return e <= cut; }));
        const uint32_t ticks = whole == 3 ? 137 : uint32_t(whole * 60);
        const game::Replay r = parse(prefix);
        EXPECT_FALSE(r.complete);
        ASSERT_EQ(r.inputs.size(), ticks);
        ASSERT_EQ(r.hashes.size(), whole);
        for (uint32_t t = 0; t < ticks; ++t) ASSERT_EQ(r.inputs[t], input_at(t));
        expect_tick_hashes(r);
        EXPECT_NE(r.cut_note.find("cut after tick " + std::to_string(ticks)), std::string::npos) << r.cut_note;
        EXPECT_NE(r.cut_note.find("of " + std::to_string(cut)), std::string::npos) << r.cut_note;
        expect_replay_error([&] { parse(prefix, /*strict=*/true); }, {"test.replay", "was cut", "--strict refuses it"});
    }
    EXPECT_TRUE(parse(full, /*strict=*/true).complete);
    const Bytes in_chunk2(full.begin(), full.begin() + ptrdiff_t(ends[1] + 25));
    EXPECT_EQ(parse(in_chunk2).cut_note,
              "recording was cut after tick 120 (byte " + std::to_string(ends[1]) + " of " +
                  std::to_string(ends[1] + 25) +
                  ", inside chunk 2 (ticks 120..136)): replaying the 120 ticks of its 2 complete chunks");
}

TEST_F(ReplayFile, FlippedBytesFailTheirCrc) {
    write_replay(file("f.replay"), 137);
    const Bytes full = read_bytes(file("f.replay"));
    const size_t h = header_size(full);
    const size_t chunk1 = h + chunk_record_size(60);

    Bytes b = full;
    b[chunk1 + 20 + 7] ^= 0x04;  // an input of chunk 1
    expect_replay_error([&] { parse(b); }, {"test.replay", "chunk 1 (ticks 60..119) fails its CRC"});
    b = full;
    b[chunk1 + chunk_record_size(60) - 6] ^= 0x80;  // its last part hash
    expect_replay_error([&] { parse(b); }, {"chunk 1 (ticks 60..119) fails its CRC"});
    b = full;
    b[chunk1 + 20 + 2 * 60 + 8 * 17 + 3] ^= 0x20;  // the world hash after its 18th tick
    expect_replay_error([&] { parse(b); }, {"chunk 1 (ticks 60..119) fails its CRC"});
    b = full;
    b[chunk1 + 20 + 10 * 60 + 3 * 41 + 2] ^= 0x01;  // a fingerprint of its 42nd tick
    expect_replay_error([&] { parse(b); }, {"chunk 1 (ticks 60..119) fails its CRC"});
    b = full;
    b[chunk1 + 9] ^= 0x01;  // its tick count
    expect_replay_error([&] { parse(b); }, {"chunk 1", "tick 60", "fails its CRC"});
    b = full;
    b[30] ^= 0x10;  // inside the header's level id
    expect_replay_error([&] { parse(b); }, {"test.replay", "header fails its CRC"});
    b = full;
    b[full.size() - 10] ^= 0x01;  // the END record's tick count
    expect_replay_error([&] { parse(b); }, {"end record", "CRC"});
}

TEST_F(ReplayFile, RefusesWrongMagicVersionAndTrailingBytes) {
    write_replay(file("m.replay"), 61);
    const Bytes full = read_bytes(file("m.replay"));
    Bytes b = full;
    b[0] = 'X';
    expect_replay_error([&] { parse(b); }, {"test.replay", "not a Spindrift replay"});
    expect_replay_error([&] { parse(Bytes{'G', 'I', 'F'}); }, {"not a Spindrift replay"});
    b = full;
    set_u32(b, 8, 2);  // the format before analog inputs
    expect_replay_error([&] { parse(b); },
                        {"test.replay", "is replay format version 2", "reads version 4", "re-record it"});
    set_u32(b, 8, 3);  // the format before the camera shots
    expect_replay_error([&] { parse(b); },
                        {"test.replay", "is replay format version 3", "reads version 4", "re-record it from its .script"});
    set_u32(b, 8, 5);  // a newer build's
    expect_replay_error([&] { parse(b); }, {"is replay format version 5", "reads version 4"});
    b = full;
    b.insert(b.end(), {1, 2, 3, 4, 5});
    expect_replay_error([&] { parse(b); }, {"test.replay", "trailing garbage after the end record (5 bytes)"});
    b = full;
    b.push_back('C');  // even a plausible tag start after END is garbage
    expect_replay_error([&] { parse(b); }, {"trailing garbage after the end record (1 bytes)"});
    b = full;
    const size_t h = header_size(b);
    std::memcpy(&b[h], "XHNK", 4);
    expect_replay_error([&] { parse(b); }, {"unexpected bytes at offset " + std::to_string(h), "not a chunk"});
}

// A forged camera shot that passes the header's CRC is still refused, field by field.
TEST_F(ReplayFile, RefusesCameraShotsItCannotShow) {
    write_replay(file("k.replay"), 61);
    const Bytes full = read_bytes(file("k.replay"));
    const size_t h = header_size(full);
    const size_t count_at = camera_shots_offset(test_header());
    ASSERT_EQ(get_u32(full, count_at), 3u);
    const size_t look_at = count_at + 4, orbit_at = look_at + game::kCameraShotBytes;
    auto forged = [&](size_t at, uint32_t value) {
        Bytes b = full;
        set_u32(b, at, value);
        fix_crc(b, 0, h - 4);
        return b;
    };
    auto f32 = [](float v) { return std::bit_cast<uint32_t>(v); };
    const struct {
        size_t at;
        uint32_t value;
        std::string says;
    } cases[] = {
        {count_at, 1025, "'camera_shots' counts 1025"},
        {count_at, 1000, "runs past the end of the header"},
        {orbit_at, 100, "camera shots are not in ascending tick order (100 follows 100)"},
        {look_at, 864000, "camera shot tick 864000 is beyond"},
        {look_at + 5, f32(std::numeric_limits<float>::quiet_NaN()), "not a finite number"},
        {look_at + 5, f32(std::numeric_limits<float>::infinity()), "not a finite number"},
        {look_at + 5 + 4 * 10, f32(0.0f), "field of view"},  // the look's fov
        {look_at + 5 + 4 * 4, f32(99999.0f), "straight up or down"},  // the look's target high above its eye
        {orbit_at + 5 + 4 * 6, f32(-1.0f), "orbit radius"},
        {orbit_at + 5 + 4 * 8, f32(1e6f), "faster than 3600"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.says);
        expect_replay_error([&] { parse(forged(c.at, c.value)); }, {"test.replay", c.says});
    }
    Bytes kind = full;
    kind[look_at + 4] = 7;
    fix_crc(kind, 0, h - 4);
    expect_replay_error([&] { parse(kind); }, {"camera shot at tick 100", "unknown camera kind 7"});
}

TEST_F(ReplayFile, RefusesStructuralLiesThatPassTheCrc) {
    write_replay(file("s.replay"), 137);
    const Bytes full = read_bytes(file("s.replay"));
    const size_t h = header_size(full);
    const size_t c60 = chunk_record_size(60);

    Bytes swapped = full;  // chunks 0 and 1 in the wrong order
    std::copy(full.begin() + ptrdiff_t(h + c60), full.begin() + ptrdiff_t(h + 2 * c60), swapped.begin() + ptrdiff_t(h));
    std::copy(full.begin() + ptrdiff_t(h), full.begin() + ptrdiff_t(h + c60), swapped.begin() + ptrdiff_t(h + c60));
    expect_replay_error([&] { parse(swapped); }, {"chunk 0 (ticks 60..119)", "does not follow on", "tick 0"});

    Bytes b = full;  // END record that lies about the tick count
    set_u32(b, full.size() - 12, 136);
    fix_crc(b, full.size() - 16, full.size() - 4);
    expect_replay_error([&] { parse(b); }, {"end record counts 136 ticks", "137 ticks"});

    b = full;  // a chunk claiming too many ticks
    set_u32(b, h + 8, 601);
    fix_crc(b, h, h + 16);
    expect_replay_error([&] { parse(b); }, {"chunk 0", "601 ticks", "1..600"});

    // Chunks carrying 2 subsystem hashes under a header naming 3.
    write_replay(file("two.replay"), 60, true, 2);
    const Bytes two = read_bytes(file("two.replay"));
    b.assign(full.begin(), full.begin() + ptrdiff_t(h));
    b.insert(b.end(), two.begin() + ptrdiff_t(header_size(two)), two.end());
    expect_replay_error([&] { parse(b); }, {"chunk 0 (ticks 0..59) has 2 subsystem hashes", "names 3"});

    b = full;  // the last tick's fingerprint of 'water' disagrees with its full hash
    const size_t chunk2 = h + 2 * c60, payload = (5 + 8 + 3) * 17 + 8 * 3;
    b[chunk2 + 20 + (5 + 8) * 17 + 3 * 16 + 1] ^= 0x01;
    fix_crc(b, chunk2 + 20, chunk2 + 20 + payload);
    expect_replay_error([&] { parse(b); }, {"chunk 2 (ticks 120..136)", "fingerprint of subsystem 'water'",
                                            "does not match its stored hash"});

    // Inputs no writer stores: an unknown control bit, steering past full scale (-128).
    const size_t chunk0_payload = (5 + 8 + 3) * 60 + 8 * 3;
    b = full;
    b[h + 20 + 5 * 7 + 1] |= 0x80;  // tick 7's held bits
    fix_crc(b, h + 20, h + 20 + chunk0_payload);
    expect_replay_error([&] { parse(b); }, {"chunk 0 (ticks 0..59)", "input of tick 7", "unknown control bits"});
    b = full;
    b[h + 20 + 5 * 9 + 4] = 0x80;  // tick 9's steering
    fix_crc(b, h + 20, h + 20 + chunk0_payload);
    expect_replay_error([&] { parse(b); }, {"input of tick 9", "steers -128", "beyond full scale"});
}

TEST_F(ReplayFile, RefusesOutOfBoundsHeaderFieldsBeforeAllocating) {
    write_replay(file("o.replay"), 5);
    const Bytes full = read_bytes(file("o.replay"));
    const size_t h = header_size(full);
    Bytes b = full;
    set_u32(b, 12, 0xFFFFFFF0u);
    expect_replay_error([&] { parse(b); }, {"declares a header of 4294967280 bytes"});

    b = full;  // level id length
    set_u32(b, 16, 0xFFFFFFFFu);
    fix_crc(b, 0, h - 4);
    expect_replay_error([&] { parse(b); }, {"level_id", "4294967295 bytes long", "64"});

    const size_t checkpoint_count_at = 16 + 4 + 7 + 8 + 8 + 4 + 8 + 4 + 4;
    ASSERT_EQ(get_u32(full, checkpoint_count_at), 3u);
    b = full;
    set_u32(b, checkpoint_count_at, 0x7FFFFFFFu);
    fix_crc(b, 0, h - 4);
    expect_replay_error([&] { parse(b); }, {"checkpoints", "2147483647", "1024"});

    b = full;  // a valid count that runs past the header's end
    set_u32(b, checkpoint_count_at, 1000);
    fix_crc(b, 0, h - 4);
    expect_replay_error([&] { parse(b); }, {"runs past the end of the header"});

    b = full;  // checkpoints out of order, CRC intact
    set_u32(b, checkpoint_count_at + 4, 5000);
    fix_crc(b, 0, h - 4);
    expect_replay_error([&] { parse(b); }, {"invalid header", "ascending"});
}

TEST_F(ReplayFile, OpeningFailuresNameTheFile) {
    expect_replay_error([&] { game::read_replay(file("missing.replay")); }, {"missing.replay", "No such file"});
    expect_replay_error([&] { game::read_replay(dir_); }, {dir_.string(), "not a regular file"});
    write_bytes(file("empty.replay"), {});
    expect_replay_error([&] { game::read_replay(file("empty.replay")); }, {"empty.replay", "empty"});
    {
        std::ofstream huge(file("huge.replay"));
    }
    fs::resize_file(file("huge.replay"), (256u << 20) + 1);  // sparse: costs no disk
    expect_replay_error([&] { game::read_replay(file("huge.replay")); }, {"huge.replay", "256 MiB"});
}

// Every input either parses or throws ReplayError: nothing else, never a crash or hang.
void parse_or_replay_error(const Bytes& b) {
    try {
        const game::Replay r = parse(b);
        ASSERT_EQ(r.hashes.empty(), r.inputs.empty());
        ASSERT_EQ(r.tick_world_hashes.size(), r.inputs.size());
        ASSERT_EQ(r.tick_fingerprints.size(), r.inputs.size() * r.header.subsystem_names.size());
    } catch (const game::ReplayError&) {
    }
}

TEST_F(ReplayFile, SurvivesRandomAndMutatedInput) {
    std::mt19937 rng(12345);
    auto below = [&](size_t n) { return size_t(rng() % n); };
    for (int i = 0; i < 2000; ++i) {  // random bytes, some behind a valid magic and version
        Bytes b(below(400));
        for (uint8_t& x : b) x = uint8_t(rng());
        if (i % 2 && b.size() >= 16) {
            std::copy(game::kReplayMagic.begin(), game::kReplayMagic.end(), b.begin());
            set_u32(b, 8, game::kReplayVersion);
            set_u32(b, 12, uint32_t(game::kMinHeaderBytes + below(200)));
        }
        parse_or_replay_error(b);
    }
    write_replay(file("z.replay"), 250);
    const Bytes full = read_bytes(file("z.replay"));
    const size_t h = header_size(full);
    int parsed = 0;
    for (int i = 0; i < 2000; ++i) {
        Bytes b = full;
        switch (i % 5) {
            case 0:  // flip a few bits anywhere
                for (int k = 0; k < 1 + i % 3; ++k) b[below(b.size())] ^= uint8_t(1u << below(8));
                break;
            case 1:  // cut anywhere
                b.resize(below(b.size() + 1));
                break;
            case 2:  // insert or remove a run of bytes
                if (i % 2) {
                    b.insert(b.begin() + ptrdiff_t(below(b.size())), 1 + below(40), uint8_t(rng()));
                } else {
                    const size_t at = below(b.size());
                    b.erase(b.begin() + ptrdiff_t(at), b.begin() + ptrdiff_t(std::min(b.size(), at + 1 + below(40))));
                }
                break;
            case 3:  // damage a header word and forge its CRC, to reach the field checks
                set_u32(b, 16 + 4 * below((h - 20) / 4), uint32_t(rng()) >> below(32));
                fix_crc(b, 0, h - 4);
                break;
            case 4:  // damage a chunk header field and forge its CRC
                set_u32(b, h + 4 + 4 * below(3), uint32_t(rng()) >> below(32));
                fix_crc(b, h, h + 16);
                break;
        }
        try {
            parse(b);
            ++parsed;
        } catch (const game::ReplayError&) {
        }
    }
    EXPECT_GT(parsed, 0);  // the cuts at record boundaries, at least, still parse
}

// A recorder child is SIGKILLed at several moments; what it leaves must read back as whole
// chunks holding exactly what it wrote.
TEST_F(ReplayFile, KilledRecordingLeavesAReplayablePrefix) {
    const size_t header_bytes = [&] {
        write_replay(file("probe.replay"), 0);
        return header_size(read_bytes(file("probe.replay")));
    }();
    for (size_t kill_after_chunks : {1u, 4u, 15u}) {
        SCOPED_TRACE(kill_after_chunks);
        const fs::path out = file("killed.replay"), path = game::partial_replay_path(out);
        int ready[2];
        ASSERT_EQ(::pipe(ready), 0);
        const pid_t child = ::fork();
        ASSERT_GE(child, 0);
        if (child == 0) {
            int status = 0;
            try {
                auto writer = game::ReplayWriter::create(out, test_header());
                const char byte = 1;
                if (::write(ready[1], &byte, 1) != 1) ::_exit(2);
                for (uint32_t t = 0; t < 100000; ++t) {
                    writer.append(input_at(t), hash_after(t + 1));
                    if (t % 20 == 0) ::usleep(100);
                }
                writer.finish();
            } catch (...) {
                status = 3;
            }
            ::_exit(status);
        }
        ::close(ready[1]);
        char byte = 0;
        ASSERT_EQ(::read(ready[0], &byte, 1), 1);
        ::close(ready[0]);
        // Wait until the child has written the chunks, then kill it wherever it is.
        const uintmax_t target = header_bytes + kill_after_chunks * chunk_record_size(60);
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
        std::error_code ec;
        while (fs::file_size(path, ec) < target && std::chrono::steady_clock::now() < deadline)
            std::this_thread::sleep_for(std::chrono::microseconds(50));
        ::kill(child, SIGKILL);
        int status = 0;
        ASSERT_EQ(::waitpid(child, &status, 0), child);
        ASSERT_TRUE(WIFSIGNALED(status)) << "the recorder finished before it was killed";
        EXPECT_FALSE(fs::exists(out));

        const game::Replay r = game::read_replay(path);
        EXPECT_FALSE(r.complete);
        EXPECT_GE(r.inputs.size(), kill_after_chunks * 60);
        EXPECT_EQ(r.inputs.size() % 60, 0u);
        EXPECT_EQ(r.hashes.size(), r.inputs.size() / 60);
        for (uint32_t t = 0; t < r.inputs.size(); ++t) ASSERT_EQ(r.inputs[t], input_at(t)) << t;
        expect_tick_hashes(r);
        for (const game::ReplayCheckpointHash& h : r.hashes) ASSERT_EQ(h.hash, hash_after(h.tick));
        expect_replay_error([&] { game::read_replay(path, {.strict = true}); }, {"--strict"});
    }
}

}  // namespace
