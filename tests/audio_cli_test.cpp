// `spindrift replay FILE --headless --audio OUT.wav` as a user meets it: the file
// appears under its name only when complete, an unwritable path is refused before
// anything renders, and --audio needs --headless.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "audio/WavFile.h"
#include "ProgramRun.h"

namespace fs = std::filesystem;

namespace {

const std::string kReplay = "replay " + std::string(SPINDRIFT_DATA_DIR) + "/replays/harbour_energy.replay";

TEST(AudioCli, WritesTheWholeReplaysSoundUnderItsNameAtTheEnd) {
    const fs::path dir = fs::temp_directory_path() / ("spindrift_audio_cli_" + std::to_string(getpid()));
    fs::create_directories(dir);
    const fs::path out = dir / "energy.wav";
    const ProgramRun r = run_spindrift(kReplay + " --headless --frames none --audio " + out.string());
    EXPECT_EQ(r.code, 0) << r.output;
    EXPECT_TRUE(fs::exists(out));
    EXPECT_FALSE(fs::exists(out.string() + ".partial"));
    int rate = 0;
    const std::vector<float> samples = audio::read_wav(out, &rate);
    EXPECT_EQ(rate, 48000);
    EXPECT_EQ(samples.size(), size_t(560 * 800 * 2)) << "one tick of stereo per tick of the replay";
    fs::remove_all(dir);
}

TEST(AudioCli, AnUnwritablePathIsRefusedBeforeRendering) {
    const ProgramRun r = run_spindrift(kReplay + " --headless --frames none --audio /nonexistent-dir/x.wav");
    EXPECT_EQ(r.code, 5) << r.output;
    EXPECT_NE(r.output.find("/nonexistent-dir/x.wav.partial"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("ticks"), std::string::npos) << "nothing was replayed: " << r.output;
}

TEST(AudioCli, AudioNeedsHeadless) {
    const ProgramRun r = run_spindrift(kReplay + " --audio /tmp/x.wav");
    EXPECT_EQ(r.code, 2) << r.output;
    EXPECT_NE(r.output.find("--headless"), std::string::npos) << r.output;
}

}  // namespace
