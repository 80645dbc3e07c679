#include "game/capture/VideoEncoder.h"

#include <algorithm>
#include <system_error>
#include <vector>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/channel_layout.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

namespace game {

namespace fs = std::filesystem;

namespace {

std::string av_error(int code) {
    char text[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(code, text, sizeof text);
    return text;
}

}  // namespace

struct VideoEncoder::State {
    fs::path path, partial;
    VideoFormat format;
    std::string codec_name;
    AVFormatContext* muxer = nullptr;
    AVCodecContext* video = nullptr;
    AVCodecContext* audio = nullptr;
    AVStream* video_stream = nullptr;
    AVStream* audio_stream = nullptr;
    SwsContext* to_yuv = nullptr;
    AVFrame* picture = nullptr;
    AVFrame* sound = nullptr;
    AVPacket* packet = nullptr;
    int64_t frames = 0, sound_pts = 0;
    std::vector<float> left, right;  // sound not yet a whole AAC frame
    bool finished = false;

    [[noreturn]] void fail(const std::string& what, int code) const {
        throw VideoError(partial.string() + ": " + what + ": " + av_error(code));
    }
    void check(int code, const char* what) const {
        if (code < 0) fail(what, code);
    }

    // Sends `frame` (nullptr: the end) and writes every packet the encoder gives back.
    void encode(AVCodecContext* codec, AVStream* stream, const AVFrame* frame) {
        check(avcodec_send_frame(codec, frame), "encoding");
        for (;;) {
            const int got = avcodec_receive_packet(codec, packet);
            if (got == AVERROR(EAGAIN) || got == AVERROR_EOF) return;
            check(got, "encoding");
            av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
            packet->stream_index = stream->index;
            check(av_interleaved_write_frame(muxer, packet), "writing");
        }
    }

    // One AAC frame (or the shorter last one) from the front of the pending sound.
    void encode_sound(int count) {
        check(av_frame_make_writable(sound), "encoding sound");
        sound->nb_samples = count;
        std::copy_n(left.begin(), count, reinterpret_cast<float*>(sound->data[0]));
        std::copy_n(right.begin(), count, reinterpret_cast<float*>(sound->data[1]));
        left.erase(left.begin(), left.begin() + count);
        right.erase(right.begin(), right.begin() + count);
        sound->pts = sound_pts;
        sound_pts += count;
        encode(audio, audio_stream, sound);
    }

    void open_video() {
        const AVCodec* h264 = avcodec_find_encoder_by_name("libx264");
        if (!h264) h264 = avcodec_find_encoder(AV_CODEC_ID_H264);
        if (!h264) throw VideoError("this libavcodec has no H.264 encoder (Debian's links libx264)");
        codec_name = h264->name;
        video = avcodec_alloc_context3(h264);
        video->width = format.width;
        video->height = format.height;
        video->time_base = AVRational{1, format.fps};
        video->framerate = AVRational{format.fps, 1};
        video->pix_fmt = AV_PIX_FMT_YUV420P;  // what every player decodes
        video->gop_size = 2 * format.fps;     // a key frame every 2 s: players seek quickly
        // The frames are sRGB; BT.709 is what players assume for HD and read from the tags.
        video->color_primaries = AVCOL_PRI_BT709;
        video->color_trc = AVCOL_TRC_BT709;
        video->colorspace = AVCOL_SPC_BT709;
        video->color_range = AVCOL_RANGE_MPEG;
        if (muxer->oformat->flags & AVFMT_GLOBALHEADER) video->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
        AVDictionary* options = nullptr;
        av_dict_set_int(&options, "crf", format.crf, 0);
        av_dict_set(&options, "preset", "medium", 0);
        const int opened = avcodec_open2(video, h264, &options);
        av_dict_free(&options);
        check(opened, "opening the H.264 encoder");
        video_stream = avformat_new_stream(muxer, nullptr);
        check(avcodec_parameters_from_context(video_stream->codecpar, video), "video stream");
        video_stream->time_base = video->time_base;
        video_stream->avg_frame_rate = video->framerate;

        picture = av_frame_alloc();
        picture->format = video->pix_fmt;
        picture->width = format.width;
        picture->height = format.height;
        check(av_frame_get_buffer(picture, 0), "video frame");
        to_yuv = sws_getContext(format.width, format.height, AV_PIX_FMT_RGBA, format.width, format.height,
                                AV_PIX_FMT_YUV420P, SWS_BILINEAR | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INP, nullptr,
                                nullptr, nullptr);
        if (!to_yuv) throw VideoError(partial.string() + ": libswscale cannot convert RGBA to YUV 4:2:0");
        const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
        sws_setColorspaceDetails(to_yuv, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
    }

    void open_audio() {
        const AVCodec* aac = avcodec_find_encoder(AV_CODEC_ID_AAC);
        if (!aac) throw VideoError("this libavcodec has no AAC encoder");
        audio = avcodec_alloc_context3(aac);
        audio->sample_fmt = AV_SAMPLE_FMT_FLTP;
        audio->sample_rate = format.sample_rate;
        av_channel_layout_default(&audio->ch_layout, 2);
        audio->bit_rate = 192000;
        audio->time_base = AVRational{1, format.sample_rate};
        if (muxer->oformat->flags & AVFMT_GLOBALHEADER) audio->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
        check(avcodec_open2(audio, aac, nullptr), "opening the AAC encoder");
        audio_stream = avformat_new_stream(muxer, nullptr);
        check(avcodec_parameters_from_context(audio_stream->codecpar, audio), "sound stream");
        audio_stream->time_base = audio->time_base;

        sound = av_frame_alloc();
        sound->format = audio->sample_fmt;
        sound->sample_rate = audio->sample_rate;
        sound->nb_samples = audio->frame_size;
        check(av_channel_layout_copy(&sound->ch_layout, &audio->ch_layout), "sound frame");
        check(av_frame_get_buffer(sound, 0), "sound frame");
    }

    ~State() {
        sws_freeContext(to_yuv);
        av_frame_free(&picture);
        av_frame_free(&sound);
        av_packet_free(&packet);
        avcodec_free_context(&video);
        avcodec_free_context(&audio);
        if (muxer) {
            if (muxer->pb) avio_closep(&muxer->pb);
            avformat_free_context(muxer);
        }
        std::error_code ignored;
        if (!finished && !partial.empty()) fs::remove(partial, ignored);
    }
};

const char* VideoEncoder::container_for(const fs::path& path) {
    const std::string ext = path.extension().string();
    if (ext == ".mp4") return "mp4";
    if (ext == ".mov") return "mov";
    if (ext == ".mkv") return "matroska";
    return nullptr;
}

VideoEncoder::VideoEncoder(fs::path path, const VideoFormat& format) : s_(std::make_unique<State>()) {
    const char* container = container_for(path);
    if (!container) throw VideoError(path.string() + ": the name must end in .mp4, .mov or .mkv");
    if (format.width % 2 || format.height % 2 || format.width < kMinVideoSide || format.height < kMinVideoSide ||
        format.width > kMaxVideoSide || format.height > kMaxVideoSide)
        throw VideoError("a video's sides must be even and " + std::to_string(kMinVideoSide) + ".." +
                         std::to_string(kMaxVideoSide));
    av_log_set_level(AV_LOG_ERROR);
    State& s = *s_;
    s.path = path;
    s.partial = path.string() + ".partial";
    s.format = format;
    if (fs::is_directory(path)) throw VideoError(path.string() + " is a directory");
    s.check(avformat_alloc_output_context2(&s.muxer, nullptr, container, s.partial.c_str()), "container");
    // The file first: an unwritable path is refused before any encoder is set up.
    s.check(avio_open(&s.muxer->pb, s.partial.c_str(), AVIO_FLAG_WRITE), "cannot write the file");
    s.packet = av_packet_alloc();
    s.open_video();
    if (format.sample_rate > 0) s.open_audio();
    AVDictionary* options = nullptr;
    // The index at the front: a shared file plays before it has all arrived.
    if (std::string(container) != "matroska") av_dict_set(&options, "movflags", "+faststart", 0);
    const int written = avformat_write_header(s.muxer, &options);
    av_dict_free(&options);
    s.check(written, "writing the header");
}

VideoEncoder::~VideoEncoder() = default;

void VideoEncoder::add_frame(const ImageRGBA8& image) {
    State& s = *s_;
    if (image.width != s.format.width || image.height != s.format.height)
        throw VideoError("a " + std::to_string(image.width) + "x" + std::to_string(image.height) + " frame for a " +
                         std::to_string(s.format.width) + "x" + std::to_string(s.format.height) + " video");
    s.check(av_frame_make_writable(s.picture), "video frame");
    const uint8_t* rows[1] = {image.pixels.data()};
    const int stride[1] = {4 * image.width};
    sws_scale(s.to_yuv, rows, stride, 0, image.height, s.picture->data, s.picture->linesize);
    s.picture->pts = s.frames++;
    s.encode(s.video, s.video_stream, s.picture);
}

void VideoEncoder::add_sound(const float* interleaved, int frames) {
    State& s = *s_;
    if (!s.audio) throw VideoError(s.partial.string() + ": the video was opened without a sound track");
    for (int i = 0; i < frames; ++i) {
        s.left.push_back(interleaved[2 * i]);
        s.right.push_back(interleaved[2 * i + 1]);
    }
    while (s.left.size() >= size_t(s.audio->frame_size)) s.encode_sound(s.audio->frame_size);
}

void VideoEncoder::finish() {
    State& s = *s_;
    if (s.finished) return;
    s.encode(s.video, s.video_stream, nullptr);
    if (s.audio) {
        if (!s.left.empty()) s.encode_sound(int(s.left.size()));
        s.encode(s.audio, s.audio_stream, nullptr);
    }
    s.check(av_write_trailer(s.muxer), "completing the file");
    s.check(avio_closep(&s.muxer->pb), "closing the file");
    std::error_code error;
    fs::rename(s.partial, s.path, error);
    if (error) throw VideoError("cannot rename " + s.partial.string() + " to " + s.path.string() + ": " + error.message());
    s.finished = true;
}

int64_t VideoEncoder::frames() const { return s_->frames; }
const std::string& VideoEncoder::video_codec() const { return s_->codec_name; }
const fs::path& VideoEncoder::partial_path() const { return s_->partial; }

}  // namespace game
