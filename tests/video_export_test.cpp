// `spindrift replay FILE --video OUT.mp4` as a user meets it, and the file decoded back
// with libavformat and libavcodec as a player would: its frame count, size, duration and
// sound, each frame the headless render of its tick (the PNG `--frames T --out` writes),
// and bad requests refused before anything renders.
#include <gtest/gtest.h>

#if SPINDRIFT_VIDEO
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

#include "game/capture/Image.h"
#include "game/capture/ImageFiles.h"
#include "ProgramRun.h"

namespace fs = std::filesystem;

namespace {

// harbour_drive accelerates from the start: neighbouring ticks' frames differ.
const std::string kReplay = "replay " + std::string(SPINDRIFT_DATA_DIR) + "/replays/harbour_drive.replay";

struct DecodedVideo {
    std::vector<game::ImageRGBA8> frames;
    double duration_s = 0;        // the container's
    double video_duration_s = 0;  // the video stream's
    int64_t sound_frames = 0;     // stereo samples decoded
    int sound_rate = 0, sound_channels = 0;
    double sound_rms = 0;
};

// Decodes every packet of every stream, as a player does; the pictures as sRGB RGBA
// (BT.709, as the file's colour tags say).
DecodedVideo decode(const fs::path& path) {
    DecodedVideo out;
    AVFormatContext* format = nullptr;
    if (avformat_open_input(&format, path.c_str(), nullptr, nullptr) < 0) {
        ADD_FAILURE() << "cannot open " << path;
        return out;
    }
    EXPECT_GE(avformat_find_stream_info(format, nullptr), 0);
    out.duration_s = double(format->duration) / AV_TIME_BASE;
    std::vector<AVCodecContext*> decoders(format->nb_streams, nullptr);
    for (unsigned i = 0; i < format->nb_streams; ++i) {
        const AVCodecParameters* par = format->streams[i]->codecpar;
        const AVCodec* codec = avcodec_find_decoder(par->codec_id);
        if (!codec) continue;
        decoders[i] = avcodec_alloc_context3(codec);
        avcodec_parameters_to_context(decoders[i], par);
        EXPECT_GE(avcodec_open2(decoders[i], codec, nullptr), 0);
        if (par->codec_type == AVMEDIA_TYPE_VIDEO) {
            const AVStream* s = format->streams[i];
            out.video_duration_s = double(s->duration) * av_q2d(s->time_base);
        }
    }
    AVPacket* packet = av_packet_alloc();
    AVFrame* frame = av_frame_alloc();
    double sound_squares = 0;
    auto take = [&](AVCodecContext* c) {
        while (avcodec_receive_frame(c, frame) == 0) {
            if (c->codec_type == AVMEDIA_TYPE_VIDEO) {
                game::ImageRGBA8 image{frame->width, frame->height, {}};
                image.pixels.resize(size_t(4) * frame->width * frame->height);
                SwsContext* to_rgb = sws_getContext(frame->width, frame->height, AVPixelFormat(frame->format),
                                                    frame->width, frame->height, AV_PIX_FMT_RGBA,
                                                    SWS_BILINEAR | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT, nullptr,
                                                    nullptr, nullptr);
                const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
                sws_setColorspaceDetails(to_rgb, bt709, frame->color_range == AVCOL_RANGE_JPEG, bt709, 1, 0,
                                         1 << 16, 1 << 16);
                uint8_t* rows[1] = {image.pixels.data()};
                const int stride[1] = {4 * frame->width};
                sws_scale(to_rgb, frame->data, frame->linesize, 0, frame->height, rows, stride);
                sws_freeContext(to_rgb);
                out.frames.push_back(std::move(image));
            } else if (c->codec_type == AVMEDIA_TYPE_AUDIO) {
                out.sound_frames += frame->nb_samples;
                out.sound_rate = frame->sample_rate;
                out.sound_channels = frame->ch_layout.nb_channels;
                EXPECT_EQ(frame->format, AV_SAMPLE_FMT_FLTP);
                for (int ch = 0; ch < frame->ch_layout.nb_channels; ++ch)
                    for (int i = 0; i < frame->nb_samples; ++i) {
                        const float v = reinterpret_cast<const float*>(frame->extended_data[ch])[i];
                        sound_squares += double(v) * v;
                    }
            }
        }
    };
    while (av_read_frame(format, packet) >= 0) {
        AVCodecContext* c = decoders[size_t(packet->stream_index)];
        if (c && avcodec_send_packet(c, packet) >= 0) take(c);
        av_packet_unref(packet);
    }
    for (AVCodecContext* c : decoders)
        if (c && avcodec_send_packet(c, nullptr) >= 0) take(c);
    if (out.sound_frames) out.sound_rms = std::sqrt(sound_squares / double(2 * out.sound_frames));
    av_frame_free(&frame);
    av_packet_free(&packet);
    for (AVCodecContext*& c : decoders) avcodec_free_context(&c);
    avformat_close_input(&format);
    return out;
}

// Over R, G and B, 8 bits each.
double psnr(const game::ImageRGBA8& a, const game::ImageRGBA8& b) {
    if (a.width != b.width || a.height != b.height) return 0;
    double squares = 0;
    size_t n = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        if (i % 4 == 3) continue;
        const double d = double(a.pixels[i]) - double(b.pixels[i]);
        squares += d * d;
        ++n;
    }
    return squares == 0 ? 99.0 : 10.0 * std::log10(255.0 * 255.0 / (squares / double(n)));
}

class VideoExport : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("spindrift_video_" + std::to_string(getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

TEST_F(VideoExport, DecodesBackWithItsFramesSizeDurationAndSound) {
    // Ticks 89..100 of replay time: 12 ticks, 0.2 s.
    for (int fps : {60, 30}) {
        const fs::path out = dir_ / ("drive" + std::to_string(fps) + ".mp4");
        const ProgramRun r =
            run_spindrift(kReplay + " --video " + out.string() + " --from 89 --to 101 --size 320x180 --fps " + std::to_string(fps));
        ASSERT_EQ(r.code, 0) << r.output;
        EXPECT_TRUE(fs::exists(out));
        EXPECT_FALSE(fs::exists(out.string() + ".partial"));
        const DecodedVideo v = decode(out);
        const size_t frames = fps == 60 ? 12 : 6;
        ASSERT_EQ(v.frames.size(), frames) << fps << " fps";
        EXPECT_EQ(v.frames[0].width, 320);
        EXPECT_EQ(v.frames[0].height, 180);
        EXPECT_NEAR(v.video_duration_s, 0.2, 1e-3) << fps << " fps";
        EXPECT_NEAR(v.duration_s, 0.2, 0.03) << "the container's duration, the sound's priming trimmed";
        EXPECT_EQ(v.sound_rate, 48000);
        EXPECT_EQ(v.sound_channels, 2);
        // 12 ticks of 800 samples, within the one AAC frame the last packet rounds up to.
        EXPECT_GE(v.sound_frames, 12 * 800);
        EXPECT_LE(v.sound_frames, 12 * 800 + 1024);
        EXPECT_GT(v.sound_rms, 1e-3) << "the car's engine is heard";
    }
}

TEST_F(VideoExport, EachFrameIsTheRenderOfItsTick) {
    // The replay's own frame size (480x270), so that the PNG render is the same picture.
    const fs::path out = dir_ / "drive.mp4";
    ASSERT_EQ(run_spindrift(kReplay + " --video " + out.string() + " --from 89 --to 101 --size 480x270").code, 0);
    const ProgramRun png = run_spindrift(kReplay + " --headless --frames 94,95,96 --out " + dir_.string());
    ASSERT_EQ(png.code, 0) << png.output;
    const DecodedVideo v = decode(out);
    ASSERT_EQ(v.frames.size(), 12u);
    // Frame k shows the world after tick 89 + k + 1.
    for (int tick : {94, 95, 96}) {
        char name[32];
        std::snprintf(name, sizeof name, "tick_%06d.png", tick);
        const game::ImageRGBA8 want = game::read_png(dir_ / name);
        const size_t k = size_t(tick - 90);
        const double same = psnr(v.frames[k], want);
        EXPECT_GE(same, 35.0) << "tick " << tick;
        // And not its neighbour's: the frames are matched to the right ticks.
        EXPECT_GT(same, psnr(v.frames[k - 1], want) + 5.0) << "tick " << tick;
        EXPECT_GT(same, psnr(v.frames[k + 1], want) + 5.0) << "tick " << tick;
    }
}

TEST_F(VideoExport, BadRequestsAreRefusedBeforeRendering) {
    const std::string out = (dir_ / "x.mp4").string();
    struct Case {
        std::string args;
        int code;
        std::string says;
    };
    for (const Case& c : std::vector<Case>{
             {" --video /nonexistent-dir/x.mp4", 5, "/nonexistent-dir/x.mp4.partial"},
             {" --video " + out + " --size 4098x720", 2, "--size"},
             {" --video " + out + " --size 641x360", 2, "even"},
             {" --video " + out + " --size big", 2, "WIDTHxHEIGHT"},
             {" --video " + out + " --fps 25", 2, "30 or 60"},
             {" --video " + out + " --quality 60", 2, "CRF"},
             {" --video " + out + " --from 200 --to 100", 2, "not one frame"},
             {" --video " + out + " --to 999999", 2, "past the replay's end"},
             {" --video " + out + " --from 3x", 2, "seconds (10s)"},
             {" --video " + (dir_ / "x.avi").string(), 2, ".mp4, .mov or .mkv"},
             {" --video " + out + " --check", 2, "--check does not go with --video"},
             {" --from 10 --headless", 2, "belongs to --video"},
         }) {
        const ProgramRun r = run_spindrift(kReplay + c.args);
        EXPECT_EQ(r.code, c.code) << c.args << "\n" << r.output;
        EXPECT_NE(r.output.find(c.says), std::string::npos) << c.args << "\n" << r.output;
        EXPECT_EQ(r.output.find("frames,"), std::string::npos) << "nothing rendered: " << r.output;
        EXPECT_FALSE(fs::exists(out)) << c.args;
        EXPECT_FALSE(fs::exists(out + ".partial")) << c.args;
    }
}

TEST_F(VideoExport, SecondsAndTicksNameTheSameRange) {
    const fs::path out = dir_ / "s.mp4";
    const ProgramRun r = run_spindrift(kReplay + " --video " + out.string() + " --from 1.5s --to 1.6s --size 64x36");
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_NE(r.output.find("6 frames 64x36 at 60 fps (ticks 91..96 of 1680"), std::string::npos) << r.output;
    EXPECT_EQ(decode(out).frames.size(), 6u);
}

}  // namespace
#endif
