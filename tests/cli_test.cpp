// The program as a user meets it: every kind of bad input gets one clear message, a
// non-zero exit code and no output file; good input round-trips.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "game/capture/ImageFiles.h"
#include "game/play/ResolutionController.h"
#include "game/replay/ReplayReader.h"
#include "game/replay/ReplayWriter.h"

namespace fs = std::filesystem;

namespace {

struct CommandResult {
    int code = -1;
    std::string output;  // stdout and stderr
};

// `env_prefix`, e.g. "env -u DISPLAY", runs the program without a display.
// A command's output (stdout and stderr) and exit code.
CommandResult run_command(const std::string& cmd) {
    CommandResult r;
    FILE* p = popen((cmd + " 2>&1").c_str(), "r");
    if (!p) return r;
    char buf[4096];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, p)) > 0) r.output.append(buf, n);
    int status = pclose(p);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return r;
}

CommandResult run(const std::string& args, const std::string& env_prefix = "") {
    return run_command(env_prefix + std::string(SPINDRIFT_BIN) + " " + args);
}

// The GL-free checker, spindrift-check, the same way.
CommandResult run_check(const std::string& args) { return run_command(std::string(SPINDRIFT_CHECK_BIN) + " " + args); }

std::string read_file(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

void write_file(const fs::path& p, const std::string& bytes) {
    std::ofstream out(p, std::ios::binary);
    out << bytes;
}

class Cli : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("spindrift_cli_" + std::to_string(::getpid()) + "_" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;

    // A short recording of the harbour level.
    fs::path record(const std::string& script_text, const std::string& name = "r.replay") {
        fs::path script = dir_ / "s.script", out = dir_ / name;
        write_file(script, script_text);
        CommandResult r = run("record --level harbour --script " + script.string() + " --out " + out.string());
        EXPECT_EQ(r.code, 0) << r.output;
        return out;
    }
    // The harbour level copied as levels/NAME.json into the test's folder (its assets
    // linked), with `from` replaced by `to` in the JSON; returns the JSON's path.
    fs::path harbour_variant(const std::string& name, const std::string& from, const std::string& to) {
        const fs::path data = fs::path(SPINDRIFT_TEST_DATA).parent_path().parent_path();
        std::string json = read_file(data / "levels" / "harbour.json");
        auto at = json.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        if (at != std::string::npos) json.replace(at, from.size(), to);
        fs::create_directories(dir_ / "levels");
        fs::create_directory_symlink(data / "levels" / "harbour", dir_ / "levels" / name);
        write_file(dir_ / "levels" / (name + ".json"), json);
        return dir_ / "levels" / (name + ".json");
    }
    static constexpr const char* kShortScript = "level harbour\n0 hold throttle\n100 tap throw_heavy\n150 hold\n200 end\n";
};

TEST_F(Cli, HelpNamesEveryCommandAndExitCode) {
    CommandResult r = run("--help");
    EXPECT_EQ(r.code, 0);
    for (const char* w : {"play", "record", "replay", "timedemo", "bench", "--quality", "exit codes",
                          "spindrift/settings.json", "F11", "Esc the menu"})
        EXPECT_NE(r.output.find(w), std::string::npos) << w;
    // auto's render scales as the resolution controller has them (0.35..1)
    char scales[32];
    const game::ResolutionController::Options auto_scales;
    std::snprintf(scales, sizeof scales, "(%g..%g)", double(auto_scales.min_scale), double(auto_scales.max_scale));
    EXPECT_NE(r.output.find(std::string("render scale ") + scales), std::string::npos) << r.output;
    EXPECT_EQ(run("--version").code, 0);
    EXPECT_EQ(run("fly").code, 2);
    EXPECT_EQ(run("play --fullscreen --windowed").code, 2);
    EXPECT_EQ(run("replay x.replay --fast").code, 2);
    EXPECT_EQ(run("replay x.replay --threads 0").code, 2);
    EXPECT_EQ(run("replay x.replay --frames 1,x").code, 2);
    CommandResult group = run("bench --only nope");
    EXPECT_EQ(group.code, 2);
    EXPECT_NE(group.output.find("rain, play, audio, video)"), std::string::npos) << group.output;
}

TEST_F(Cli, RecordedReplayChecksWithAnyThreadCount) {
    fs::path rep = record(kShortScript);
    CommandResult a = run("replay " + rep.string() + " --headless --check --frames none");
    EXPECT_EQ(a.code, 0) << a.output;
    EXPECT_NE(a.output.find("check passed"), std::string::npos) << a.output;
    CommandResult b = run("replay " + rep.string() + " --headless --check --frames none --threads 2");
    EXPECT_EQ(b.code, 0) << b.output;
}

TEST_F(Cli, AnAnalogRecordingStoresItsAxesAndReplaysExactly) {
    fs::path rep = record("level harbour\n0 hold throttle=0.6 steer=0.3\n90 tap steer=-1 brake=0.5\n120 end\n");
    const game::Replay r = game::read_replay(rep);
    ASSERT_EQ(r.inputs.size(), 120u);
    EXPECT_EQ(r.inputs[0], (sim::TickInput{0, 153, 0, 38}));
    EXPECT_EQ(r.inputs[90], (sim::TickInput{0, 153, 128, -127}));
    CommandResult check = run("replay " + rep.string() + " --headless --check --frames none --threads 2");
    EXPECT_EQ(check.code, 0) << check.output;
    EXPECT_EQ(run_check(rep.string()).code, 0);
}

TEST_F(Cli, TheGlFreeCheckerPassesARecordingAndNamesTheFirstTickOfADesync) {
    const fs::path rep = record(kShortScript);
    for (const char* threads : {"1", "2"}) {
        CommandResult r = run_check(rep.string() + " --threads " + threads);
        EXPECT_EQ(r.code, 0) << r.output;
        EXPECT_NE(r.output.find("200 ticks, 200 hash checks, check passed"), std::string::npos) << r.output;
    }
    // The objectives as the ticks left them, the same lines `replay` prints.
    auto objective_lines = [](const std::string& output) {
        std::string lines;
        std::istringstream in(output);
        for (std::string line; std::getline(in, line);)
            if (line.rfind("  course ", 0) == 0 || line.rfind("  targets hit ", 0) == 0) lines += line + "\n";
        return lines;
    };
    const std::string checked = objective_lines(run_check(rep.string()).output);
    EXPECT_NE(checked.find("  course quay (car): "), std::string::npos) << checked;
    EXPECT_NE(checked.find("  targets hit 0 of 6\n"), std::string::npos) << checked;
    EXPECT_EQ(checked, objective_lines(run("replay " + rep.string() + " --headless --frames none").output));
    // The same recording with steering held at tick 100 (index 99), its hashes kept: a
    // genuine desync there. The writer recomputes the CRCs; the fingerprint bytes of the
    // ticks between chunk ends are what append() keeps of the parts.
    const game::Replay replay = game::read_replay(rep);
    const size_t parts = replay.header.subsystem_names.size();
    const fs::path bad = dir_ / "steered.replay";
    game::ReplayWriter w = game::ReplayWriter::create(bad, replay.header);
    size_t chunk = 0;
    for (size_t i = 0; i < replay.inputs.size(); ++i) {
        const uint32_t tick = uint32_t(i + 1);
        while (chunk < replay.hashes.size() && replay.hashes[chunk].tick < tick) ++chunk;
        sim::WorldHash h;
        if (chunk < replay.hashes.size() && replay.hashes[chunk].tick == tick) {
            h = replay.hashes[chunk].hash;
        } else {
            h.world = replay.tick_world_hashes[i];
            for (size_t k = 0; k < parts; ++k) h.parts.push_back(replay.tick_fingerprints[i * parts + k]);
        }
        sim::TickInput input = replay.inputs[i];
        if (i == 99) input.set(sim::Control::SteerLeft, true);
        w.append(input, h);
    }
    w.finish();
    CommandResult r = run_check(bad.string());
    EXPECT_EQ(r.code, 1) << r.output;
    EXPECT_NE(r.output.find("DESYNC at tick 100: world hash"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("differs first"), std::string::npos) << r.output;
    // Another file that is no replay: reported, the others still checked, exit code 3.
    write_file(dir_ / "junk.replay", "JUNK");
    CommandResult mixed = run_check((dir_ / "junk.replay").string() + " " + rep.string());
    EXPECT_EQ(mixed.code, 3) << mixed.output;
    EXPECT_NE(mixed.output.find("check passed"), std::string::npos) << mixed.output;
    EXPECT_NE(mixed.output.find("1 could not be checked"), std::string::npos) << mixed.output;
    EXPECT_EQ(run_check("").code, 2);
    EXPECT_EQ(run_check(rep.string() + " --threads 0").code, 2);
}

TEST_F(Cli, BadScriptsAreRefusedBeforeAnyFileIsWritten) {
    struct Case {
        const char* text;
        const char* says;
    } cases[] = {
        {"level harbour\n0 hold throttle jump\n10 end\n", "unknown control"},
        {"level harbour\n20 hold throttle\n10 hold brake\n30 end\n", "before the previous tick"},
        {"level harbour\n0 hold throttle\n", "end"},
        {"level nowhere\n0 hold\n10 end\n", "nowhere"},
    };
    for (const Case& c : cases) {
        fs::path script = dir_ / "bad.script", out = dir_ / "bad.replay";
        write_file(script, c.text);
        std::string level = std::string(c.text).find("nowhere") != std::string::npos ? "nowhere" : "harbour";
        CommandResult r = run("record --level " + level + " --script " + script.string() + " --out " + out.string());
        EXPECT_EQ(r.code, 3) << c.text << r.output;
        EXPECT_NE(r.output.find(c.says), std::string::npos) << r.output;
        EXPECT_FALSE(fs::exists(out)) << c.text;
    }
}

TEST_F(Cli, BrokenLevelsAreRefused) {
    const fs::path levels = fs::path(SPINDRIFT_TEST_DATA) / "levels";
    write_file(dir_ / "s.script", "0 hold\n10 end\n");
    for (const char* name : {"bad_json", "wrong_type", "missing_key", "missing_asset", "garbage_gltf", "accessor_oob",
                             "out_of_range"}) {
        fs::path out = dir_ / "x.replay";
        CommandResult r = run("record --level " + (levels / (std::string(name) + ".json")).string() + " --script " +
                    (dir_ / "s.script").string() + " --out " + out.string());
        EXPECT_EQ(r.code, 3) << name << ": " << r.output;
        EXPECT_NE(r.output.find("error:"), std::string::npos) << r.output;
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << "one message: " << r.output;
        EXPECT_FALSE(fs::exists(out));
    }
}

TEST_F(Cli, AMistypedLevelNameSuggestsTheNearestAndListsTheLevels) {
    write_file(dir_ / "s.script", "0 hold\n10 end\n");
    const std::string script = (dir_ / "s.script").string(), out = (dir_ / "x.replay").string();
    CommandResult typo = run("record --level harbor --script " + script + " --out " + out);
    EXPECT_EQ(typo.code, 3) << typo.output;
    EXPECT_NE(typo.output.find("no level named 'harbor'"), std::string::npos) << typo.output;
    EXPECT_NE(typo.output.find("did you mean 'harbour'?"), std::string::npos) << typo.output;
    const size_t list = typo.output.find("The levels in ");
    ASSERT_NE(list, std::string::npos) << typo.output;
    EXPECT_NE(typo.output.find("harbour", list), std::string::npos) << typo.output;
    EXPECT_EQ(std::count(typo.output.begin(), typo.output.end(), '\n'), 1) << "one message: " << typo.output;
    // Nothing near: the list alone.
    CommandResult far = run("record --level lighthouse --script " + script + " --out " + out);
    EXPECT_EQ(far.code, 3) << far.output;
    EXPECT_EQ(far.output.find("did you mean"), std::string::npos) << far.output;
    EXPECT_NE(far.output.find("The levels in "), std::string::npos) << far.output;
    EXPECT_FALSE(fs::exists(out));
}

TEST_F(Cli, ALevelWithAnUnstableWaveGridIsRefused) {
    fs::path level = harbour_variant("harbour", "\"wave_speed_mps\": 2.5", "\"wave_speed_mps\": 50");
    write_file(dir_ / "s.script", "0 hold\n10 end\n");
    fs::path out = dir_ / "x.replay";
    CommandResult r = run("record --level " + level.string() + " --script " + (dir_ / "s.script").string() +
                          " --out " + out.string());
    EXPECT_EQ(r.code, 3) << r.output;
    EXPECT_NE(r.output.find("0.5"), std::string::npos) << "names the stability bound: " << r.output;
    EXPECT_FALSE(fs::exists(out));
}

TEST_F(Cli, CorruptReplaysAreRefusedWithOneMessage) {
    const std::string good = read_file(record(kShortScript, "good.replay"));
    ASSERT_GT(good.size(), 200u);
    struct Case {
        std::string name, bytes, says;
    };
    std::string flipped = good;
    flipped[flipped.size() * 3 / 4] = char(flipped[flipped.size() * 3 / 4] ^ 0x5a);
    std::string version = good;
    version[8] = char(version[8] + 1);
    std::vector<Case> cases = {
        {"cut_header", good.substr(0, 20), "cut inside its header"},
        {"magic", "JUNK" + good.substr(4), "not a Spindrift replay"},
        {"version", version, "version"},
        {"flipped", flipped, "CRC"},
        {"trailing", good + "garbage!", "trailing"},
        {"empty", "", "empty"},
    };
    for (const Case& c : cases) {
        fs::path p = dir_ / (c.name + ".replay");
        write_file(p, c.bytes);
        CommandResult r = run("replay " + p.string() + " --headless --check --frames none");
        EXPECT_EQ(r.code, 3) << c.name << ": " << r.output;
        EXPECT_NE(r.output.find(c.says), std::string::npos) << c.name << ": " << r.output;
    }
    CommandResult missing = run("replay " + (dir_ / "nope.replay").string() + " --headless");
    EXPECT_EQ(missing.code, 3) << missing.output;
}

TEST_F(Cli, AReplayOfAnotherLevelIsRefused) {
    // The same level under another name: its content differs.
    fs::path level = harbour_variant("harbour2", "\"id\": \"harbour\"", "\"id\": \"harbour2\"");
    write_file(dir_ / "s.script", "0 hold throttle\n60 end\n");
    fs::path rep = dir_ / "other.replay";
    CommandResult rec = run("record --level " + level.string() + " --script " + (dir_ / "s.script").string() +
                            " --out " + rep.string());
    ASSERT_EQ(rec.code, 0) << rec.output;
    // Named by its id, the level is not among the bundled ones.
    CommandResult by_id = run("replay " + rep.string() + " --headless --frames none");
    EXPECT_EQ(by_id.code, 3) << by_id.output;
    EXPECT_NE(by_id.output.find("harbour2"), std::string::npos) << by_id.output;
    // Forced onto the harbour level, the content hash tells them apart.
    CommandResult forced = run("replay " + rep.string() + " --headless --frames none --level harbour");
    EXPECT_EQ(forced.code, 3) << forced.output;
    EXPECT_NE(forced.output.find("content hash"), std::string::npos) << forced.output;
}

TEST_F(Cli, ACutRecordingReplaysItsPrefixUnlessStrict) {
    std::string bytes = read_file(record("level harbour\n0 hold throttle\n300 end\n"));
    fs::path cut = dir_ / "cut.replay";
    write_file(cut, bytes.substr(0, bytes.size() - 40));  // inside the last chunk and the end record
    CommandResult r = run("replay " + cut.string() + " --headless --check --frames none");
    EXPECT_EQ(r.code, 0) << r.output;
    EXPECT_NE(r.output.find("cut"), std::string::npos) << r.output;
    CommandResult strict = run("replay " + cut.string() + " --headless --check --frames none --strict");
    EXPECT_EQ(strict.code, 3) << strict.output;
}

TEST_F(Cli, ARecordingKilledMidwayReplaysUpToItsLastWholeChunk) {
    // Long enough that the kill lands while recording.
    fs::path script = dir_ / "long.script", out = dir_ / "killed.replay";
    write_file(script, "level harbour\n0 hold throttle steer_left\n400000 end\n");
    pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        int null = ::open("/dev/null", O_WRONLY);
        dup2(null, 1);
        dup2(null, 2);
        execl(SPINDRIFT_BIN, SPINDRIFT_BIN, "record", "--level", "harbour", "--script", script.c_str(), "--out",
              out.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    // Wait until a few chunks are on disk, then kill without warning.
    // Until it finishes, the recording is the .partial file beside --out.
    const fs::path partial = out.string() + ".partial";
    for (int i = 0; i < 600 && !(fs::exists(partial) && fs::file_size(partial) > 8000); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    kill(pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status));
    EXPECT_FALSE(fs::exists(out));
    ASSERT_TRUE(fs::exists(partial));
    CommandResult r = run("replay " + partial.string() + " --headless --check --frames none");
    EXPECT_EQ(r.code, 0) << r.output;
    EXPECT_NE(r.output.find("cut after tick"), std::string::npos) << r.output;
    EXPECT_EQ(run("replay " + partial.string() + " --headless --check --frames none --strict").code, 3);
    // Asked for the name it was recording to, the replay command points at the rest.
    CommandResult missing = run("replay " + out.string() + " --headless --check --frames none");
    EXPECT_EQ(missing.code, 3);
    EXPECT_NE(missing.output.find(partial.string()), std::string::npos) << missing.output;
}

TEST_F(Cli, FrameChecksCatchAWrongGoldenAndNameTheEvidence) {
    fs::path rep = record("level harbour\nframes 64x36\ncheckpoints 30\n0 hold throttle\n40 end\n");
    // No golden yet: the hashes pass, and the check says the frame went unchecked and
    // how to make its golden ...
    CommandResult none = run("replay " + rep.string() + " --headless --check --out " + (dir_ / "out").string());
    EXPECT_EQ(none.code, 0) << none.output;
    EXPECT_NE(none.output.find("no golden"), std::string::npos) << none.output;
    EXPECT_NE(none.output.find("frame not checked"), std::string::npos) << none.output;
    EXPECT_NE(none.output.find("--update-goldens"), std::string::npos) << none.output;
    EXPECT_NE(none.output.find("check passed (1 of 1 checkpoints have no golden"), std::string::npos) << none.output;
    EXPECT_EQ(none.output.find("FAILED"), std::string::npos) << none.output;
    // ... unless goldens are required, as for the bundled replays.
    CommandResult required =
        run("replay " + rep.string() + " --headless --check --require-goldens --out " + (dir_ / "out").string());
    EXPECT_EQ(required.code, 1) << required.output;
    EXPECT_NE(required.output.find("no golden"), std::string::npos) << required.output;
    EXPECT_NE(required.output.find("FAILED"), std::string::npos) << required.output;
    CommandResult update = run("replay " + rep.string() + " --headless --update-goldens");
    ASSERT_EQ(update.code, 0) << update.output;
    fs::path golden = dir_ / "r" / "tick_000030.png";
    ASSERT_TRUE(fs::exists(golden));
    CommandResult pass = run("replay " + rep.string() + " --headless --check --out " + (dir_ / "out").string());
    EXPECT_EQ(pass.code, 0) << pass.output;
    // Spoil the golden: the check fails and writes the actual frame and a difference.
    game::ImageRGBA8 img = game::read_png(golden);
    for (size_t i = 0; i < img.pixels.size() / 2; i += 4) img.pixels[i] = uint8_t(255 - img.pixels[i]);
    game::write_png(golden, img);
    CommandResult fail = run("replay " + rep.string() + " --headless --check --out " + (dir_ / "out").string());
    EXPECT_EQ(fail.code, 1) << fail.output;
    EXPECT_TRUE(fs::exists(dir_ / "out" / "tick_000030.actual.png"));
    EXPECT_TRUE(fs::exists(dir_ / "out" / "tick_000030.diff.png"));
    EXPECT_NE(fail.output.find("tick_000030.diff.png"), std::string::npos) << fail.output;
}

TEST_F(Cli, FramesAndExrGoWhereAsked) {
    fs::path rep = record("level harbour\nframes 64x36\n0 hold throttle\n20 end\n");
    CommandResult r = run("replay " + rep.string() + " --headless --frames 5,20 --out " + (dir_ / "f").string() + " --exr");
    ASSERT_EQ(r.code, 0) << r.output;
    for (const char* f : {"tick_000005.png", "tick_000020.png", "tick_000005.exr", "tick_000020.exr"})
        EXPECT_TRUE(fs::exists(dir_ / "f" / f)) << f;
    EXPECT_EQ(run("replay " + rep.string() + " --headless --frames 21").code, 2);
}

}  // namespace

namespace {
constexpr const char* kNoDisplay = "env -u DISPLAY -u WAYLAND_DISPLAY ";
}

TEST_F(Cli, TimedemoHeadlessReportsItsNumbersAsJson) {
    const fs::path replay = fs::path(SPINDRIFT_TEST_DATA).parent_path().parent_path() / "replays" / "harbour_energy.replay";
    const fs::path json = dir_ / "td.json";
    CommandResult r = run("timedemo " + replay.string() + " --size 320x180 --json " + json.string(), kNoDisplay);
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_NE(r.output.find("p95"), std::string::npos) << r.output;
    std::ifstream in(json);
    const nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_EQ(j["width"], 320);
    EXPECT_EQ(j["height"], 180);
    EXPECT_EQ(j["quality"], "auto");
    EXPECT_GT(j["frames"].get<int>(), 0);
    const nlohmann::json& ms = j["frame_ms"];
    EXPECT_GT(ms["p50"].get<double>(), 0.0);
    EXPECT_LE(ms["p50"].get<double>(), ms["p95"].get<double>());
    EXPECT_LE(ms["p95"].get<double>(), ms["p99"].get<double>());
    EXPECT_LE(ms["p99"].get<double>(), ms["worst"].get<double>());
    EXPECT_GT(j["fill_ms"].get<double>(), 0.0);
    EXPECT_GT(j["frame_fills"]["p50"].get<double>(), 0.0);
    EXPECT_GT(j["game_over_wall"].get<double>(), 0.0);
    EXPECT_GT(j["average_fps"].get<double>(), 0.0);
    EXPECT_EQ(j["ticks"], j["replay_ticks"]);  // it played to the end
    EXPECT_EQ(j["hashes_checked"], j["replay_ticks"]);
    EXPECT_TRUE(j["desync"].is_null());
    EXPECT_FALSE(j["passes"].empty());
    for (const auto& p : j["passes"]) EXPECT_GE(p["ms"].get<double>(), 0.0) << p["name"];
    // The opaque pass draws (the scene's meshes), and the frame's total holds it.
    bool opaque_drew = false;
    for (const auto& d : j["draws"])
        if (d["name"] == "opaque") opaque_drew = d["draws"].get<double>() > 0.0 && d["triangles"].get<double>() > 0.0;
    EXPECT_TRUE(opaque_drew) << j["draws"].dump();
    EXPECT_GT(j["frame_draws"]["triangles"].get<double>(), 0.0);
    double seconds = 0.0;
    for (const auto& s : j["seconds_at_scale"]) {
        EXPECT_GE(s["scale"].get<double>(), game::ResolutionController::Options{}.min_scale - 1e-6);
        EXPECT_LE(s["scale"].get<double>(), 1.0 + 1e-6);
        seconds += s["seconds"].get<double>();
    }
    EXPECT_NEAR(seconds, j["wall_s"].get<double>(), 1e-6);
}

TEST_F(Cli, TimedemoRefusesBadInputClearly) {
    const fs::path replay = fs::path(SPINDRIFT_TEST_DATA).parent_path().parent_path() / "replays" / "harbour_energy.replay";
    const fs::path corrupt = dir_ / "corrupt.replay";
    write_file(corrupt, "JUNK not a replay at all");
    struct Case {
        std::string args;
        int code;
        std::string says;
    };
    const std::vector<Case> cases = {
        {"", 2, "one replay file"},
        {(dir_ / "nope.replay").string(), 3, "nope.replay"},
        {corrupt.string(), 3, "not a Spindrift replay"},
        {replay.string() + " --size 0x0", 2, "--size"},
        {replay.string() + " --size 99999x5", 2, "--size"},
        {replay.string() + " --size 640", 2, "--size"},
        {replay.string() + " --size 640x360x2", 2, "--size"},
        {replay.string() + " --quality ultra", 2, "--quality must be low, medium, high or auto"},
        {replay.string() + " --json", 2, "--json needs a value"},
        {replay.string() + " --scale 2", 2, "--scale takes a render scale from 0.25 to 1"},
        {replay.string() + " --scale half", 2, "--scale takes a render scale from 0.25 to 1"},
    };
    for (const Case& c : cases) {
        CommandResult r = run("timedemo " + c.args, kNoDisplay);
        EXPECT_EQ(r.code, c.code) << c.args << ": " << r.output;
        EXPECT_NE(r.output.find(c.says), std::string::npos) << c.args << ": " << r.output;
        EXPECT_EQ(r.output.find("terminate"), std::string::npos) << c.args << ": " << r.output;
    }
}

TEST_F(Cli, PlayAndReplayRefuseABadQuality) {
    CommandResult play = run("play --quality ultra", kNoDisplay);
    EXPECT_EQ(play.code, 2) << play.output;
    EXPECT_NE(play.output.find("--quality must be"), std::string::npos) << play.output;
    CommandResult replay = run("replay x.replay --quality 3");
    EXPECT_EQ(replay.code, 2) << replay.output;
    EXPECT_NE(replay.output.find("--quality must be"), std::string::npos) << replay.output;
}
