// Crash safety of every file the program writes. A recording killed at any moment
// leaves a file the reader accepts up to its last whole chunk; a PNG (goldens,
// screenshots, actual and difference frames), an EXR, a bench report or a recording
// that fails or is killed while being written never leaves a half-written file under
// its final name, and an older file of that name survives whole.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "game/bench/BenchReport.h"
#include "game/capture/ExrWriter.h"
#include "game/capture/ImageFiles.h"
#include "game/replay/ReplayReader.h"
#include "game/replay/ReplayWriter.h"

namespace fs = std::filesystem;

namespace {

class CrashSafety : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("spindrift_crash_" + std::to_string(::getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    // Names in the test folder other than `keep`: temporaries a writer left behind.
    std::vector<std::string> leftovers(const std::vector<std::string>& keep) const {
        std::vector<std::string> names;
        for (const auto& e : fs::directory_iterator(dir_)) {
            const std::string name = e.path().filename().string();
            if (std::find(keep.begin(), keep.end(), name) == keep.end()) names.push_back(name);
        }
        return names;
    }
    fs::path dir_;
};

std::string read_file(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

game::ReplayHeader header() {
    game::ReplayHeader h;
    h.level_id = "harbour";
    h.seed = 7;
    h.sim_signature = 0x5EED;
    h.subsystem_names = {"car", "boat", "water"};
    return h;
}
sim::TickInput input_at(uint32_t t) {
    const uint32_t m = t * 2654435761u;
    return sim::TickInput{uint16_t((m >> 7) & sim::kAllControls), uint8_t(m >> 3), uint8_t(m >> 11),
                          int8_t(int((m >> 19) % 255) - sim::kSteerFullScale)};
}
sim::WorldHash hash_after(uint32_t t) {
    return sim::WorldHash{t * 0x9E3779B97F4A7C15ull + 1, {t * 31ull + 2, t * 37ull + 3, t * 41ull + 4}};
}

// Records `ticks` ticks to `out`, pausing now and then like a live session; a failed
// recording is discarded, as `spindrift record` does.
void record_slowly(const fs::path& out, uint32_t ticks) {
    game::ReplayWriter writer = game::ReplayWriter::create(out, header());
    try {
        for (uint32_t t = 0; t < ticks; ++t) {
            writer.append(input_at(t), hash_after(t + 1));
            if (t % 8 == 0) ::usleep(200);
        }
        writer.finish();
    } catch (...) {
        writer.discard();
        throw;
    }
}

// Forks a child that runs `body` and exits 0, or 3 if it threw.
pid_t start_child(const std::function<void()>& body) {
    const pid_t child = ::fork();
    if (child == 0) {
        try {
            body();
        } catch (...) {
            ::_exit(3);
        }
        ::_exit(0);
    }
    return child;
}

int wait_status(pid_t child) {
    int status = 0;
    ::waitpid(child, &status, 0);
    return status;
}

// Runs `body` in a child process; returns its wait status.
int run_child(const std::function<void()>& body) { return wait_status(start_child(body)); }

// Starts `body` in a child, SIGKILLs it after `delay` (unless it ended first); returns
// whether the kill landed.
bool kill_child_after(const std::function<void()>& body, std::chrono::microseconds delay) {
    const pid_t child = start_child(body);
    std::this_thread::sleep_for(delay);
    ::kill(child, SIGKILL);
    return WIFSIGNALED(wait_status(child));
}

// In a child whose files may not grow past `limit_bytes` (writes fail with EFBIG): runs
// `body`, which must throw; returns the wait status (exit 3 when it threw).
int run_with_file_size_limit(uint64_t limit_bytes, const std::function<void()>& body) {
    return run_child([&] {
        ::signal(SIGXFSZ, SIG_IGN);
        const rlimit limit{limit_bytes, limit_bytes};
        if (::setrlimit(RLIMIT_FSIZE, &limit) != 0) ::_exit(4);
        body();
    });
}

game::ImageRGBA8 noise_image(int side, uint32_t seed) {  // incompressible: the PNG is large
    game::ImageRGBA8 image{side, side, std::vector<uint8_t>(size_t(side) * size_t(side) * 4)};
    std::mt19937 rng(seed);
    for (uint8_t& v : image.pixels) v = uint8_t(rng());
    return image;
}

}  // namespace

// Many recorders, each SIGKILLed at a random moment of its life (before its header, in
// the middle of a chunk, around finish()). Whatever it leaves must be: nothing yet, a
// finished recording under the final name, or a .partial file holding exactly the
// whole chunks written so far.
TEST_F(CrashSafety, RecordingsKilledAtRandomMomentsLeaveTheirWholeChunks) {
    constexpr uint32_t kTicks = 1500;
    const fs::path out = dir_ / "r.replay", partial = game::partial_replay_path(out);
    // How long an unkilled recording takes here (the quickest of three): the kills are
    // spread over it.
    auto lifetime = std::chrono::microseconds::max();
    for (int i = 0; i < 3; ++i) {
        const auto start = std::chrono::steady_clock::now();
        ASSERT_EQ(run_child([&] { record_slowly(out, kTicks); }), 0);
        lifetime = std::min(lifetime, std::chrono::duration_cast<std::chrono::microseconds>(
                                          std::chrono::steady_clock::now() - start));
    }
    ASSERT_EQ(game::read_replay(out).inputs.size(), kTicks);

    std::mt19937 rng(20261122);
    int before_header = 0, cut = 0, finished = 0;
    for (int trial = 0; trial < 60; ++trial) {
        SCOPED_TRACE("trial " + std::to_string(trial));
        fs::remove(out);
        fs::remove(partial);
        const auto delay = std::chrono::microseconds(rng() % uint64_t(lifetime.count() + 1));
        kill_child_after([&] { record_slowly(out, kTicks); }, delay);
        if (fs::exists(out)) {
            ++finished;
            EXPECT_FALSE(fs::exists(partial));
            EXPECT_EQ(game::read_replay(out).inputs.size(), kTicks);
            continue;
        }
        if (!fs::exists(partial) || fs::file_size(partial) == 0) {
            ++before_header;  // killed before the header's single write(2)
            continue;
        }
        const game::Replay r = game::read_replay(partial);
        ++cut;
        // Killed between finish()'s END record and its rename: whole, under the .partial name.
        if (r.complete) EXPECT_EQ(r.inputs.size(), kTicks);
        else EXPECT_EQ(r.inputs.size() % game::kChunkTicks, 0u);
        ASSERT_EQ(r.tick_world_hashes.size(), r.inputs.size());
        for (uint32_t t = 0; t < r.inputs.size(); ++t) {
            ASSERT_EQ(r.inputs[t], input_at(t)) << t;
            ASSERT_EQ(r.tick_world_hashes[t], hash_after(t + 1).world) << t;
        }
        for (const game::ReplayCheckpointHash& h : r.hashes) ASSERT_EQ(h.hash, hash_after(h.tick));
    }
    std::printf("60 kills: %d before the header, %d cut recordings, %d finished\n", before_header, cut, finished);
    EXPECT_GE(cut, 20) << "the kills should mostly land while chunks are being written";
}

// A golden or screenshot being rewritten when the process dies: the final name holds
// the old image or the new one, whole, never a torn file.
TEST_F(CrashSafety, PngsKilledWhileWritingAreWholeUnderTheirName) {
    const fs::path png = dir_ / "tick_000090.png";
    const game::ImageRGBA8 a = noise_image(192, 1), b = noise_image(192, 2);
    game::write_png(png, a);
    std::mt19937 rng(7);
    for (int trial = 0; trial < 20; ++trial) {
        SCOPED_TRACE("trial " + std::to_string(trial));
        kill_child_after(
            [&] {
                for (int i = 0;; ++i) game::write_png(png, i % 2 ? a : b);
            },
            std::chrono::microseconds(2000 + rng() % 30000));
        const game::ImageRGBA8 got = game::read_png(png);
        EXPECT_TRUE(got.pixels == a.pixels || got.pixels == b.pixels);
    }
    // A killed writer may leave its hidden temporary behind, and nothing else.
    for (const std::string& name : leftovers({png.filename().string()}))
        EXPECT_EQ(name.rfind(".tick_000090.png.tmp-", 0), 0u) << name;
}

// Each writer, made to fail part-way by a file size limit, throws, leaves the older file
// of the same name byte for byte and cleans up its temporary.
TEST_F(CrashSafety, FailedWritesKeepTheOldFileAndLeaveNoTemporary) {
    struct Writer {
        const char* name;
        std::function<void(const fs::path&)> write;  // a large write of this kind of file
    };
    const Writer writers[] = {
        {"golden.png", [](const fs::path& p) { game::write_png(p, noise_image(256, 3)); }},
        {"frame.exr",
         [](const fs::path& p) {
             std::vector<float> rgba(256 * 256 * 4);
             std::mt19937 rng(4);
             for (float& v : rgba) v = float(rng() % 1000) / 7.0f;
             game::write_exr(p, 256, 256, {game::ExrLayer{"", 4, rgba}});
         }},
        {"bench.json",
         [](const fs::path& p) {
             game::BenchReport report;
             for (int i = 0; i < 400; ++i)
                 report.add(game::BenchCase{"sim", "case " + std::to_string(i), double(i), "ms", 1.0, false, "n"});
             report.write_json(p, "llvmpipe");
         }},
        {"session.replay", [](const fs::path& p) { record_slowly(p, 1200); }},
    };
    for (const Writer& w : writers) {
        SCOPED_TRACE(w.name);
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        const fs::path path = dir_ / w.name;
        const std::string old = "an older file that must survive";
        std::ofstream(path, std::ios::binary) << old;
        const int status = run_with_file_size_limit(4096, [&] { w.write(path); });
        ASSERT_TRUE(WIFEXITED(status));
        EXPECT_EQ(WEXITSTATUS(status), 3) << "the write should have failed and thrown";
        EXPECT_EQ(read_file(path), old);
        EXPECT_EQ(leftovers({w.name}), std::vector<std::string>{});
        // Without the limit the same write succeeds and replaces the old file.
        ASSERT_EQ(run_child([&] { w.write(path); }), 0);
        EXPECT_NE(read_file(path), old);
        EXPECT_EQ(leftovers({w.name}), std::vector<std::string>{});
    }
}

// `spindrift record` whose disk fills up mid-recording (a file size limit here): exit
// code 5 (output not writable), a message naming the file, and neither the recording
// nor its .partial left behind. An output folder that does not exist is the same.
TEST_F(CrashSafety, ARecordingThatCannotBeWrittenExitsWithTheIoCode) {
    const fs::path script = dir_ / "s.script", out = dir_ / "full.replay";
    std::ofstream(script) << "level harbour\n0 hold throttle\n1200 end\n";
    const std::string record = std::string(SPINDRIFT_BIN) + " record --script " + script.string() + " --out ";
    // The shell ignores SIGXFSZ (inherited by the program) so that writes fail with EFBIG.
    const std::string limited = "trap '' XFSZ; ulimit -f 4; exec " + record + out.string() + " 2>&1";
    FILE* p = ::popen(("sh -c \"" + limited + "\"").c_str(), "r");
    ASSERT_NE(p, nullptr);
    std::string output;
    char buf[512];
    for (size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) output.append(buf, n);
    const int status = ::pclose(p);
    ASSERT_TRUE(WIFEXITED(status)) << output;
    EXPECT_EQ(WEXITSTATUS(status), 5) << output;
    EXPECT_NE(output.find("cannot write replay"), std::string::npos) << output;
    EXPECT_NE(output.find("full.replay.partial"), std::string::npos) << output;
    EXPECT_EQ(leftovers({"s.script"}), std::vector<std::string>{});

    const std::string missing = record + (dir_ / "no" / "such" / "x.replay").string() + " > /dev/null 2>&1";
    const int missing_status = std::system(missing.c_str());
    ASSERT_TRUE(WIFEXITED(missing_status));
    EXPECT_EQ(WEXITSTATUS(missing_status), 5);
}
