#pragma once
#include "effects/gl/Gl.h"
#include "effects/gl/Handle.h"

#include <array>
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace effects::gl {

enum class TimingMode {
    GpuQueries,  // GL_TIME_ELAPSED queries, read a few frames later (no stall); ~0 on llvmpipe
    Profile,     // glFinish around each pass + wall clock: exact on llvmpipe, slows the frame
    Sampled,     // Profile's measurement for one pass a frame, in turn: exact and nearly free
};

struct PassTime {
    std::string name;
    double ms = 0.0;          // Sampled: the pass's latest measurement, up to a round of passes old
    double average_ms = 0.0;  // smoothed over recent frames (per name, per frame total)
};

// Times named passes per frame:
//   timer.frame_begin();
//   { auto t = timer.scope("water"); ... }
//   timer.frame_end();
// Sampled mode measures every run of one pass name per frame, the next name in the
// last frame's order each frame, so a list of N passes is measured once every N frames
// (from the second frame on: the first one's times are mostly shader compiles).
// Passes do not nest (GL_TIME_ELAPSED queries cannot). Misuse (begin without
// frame_begin, nested begin, end without begin) throws std::logic_error.
class PassTimer {
public:
    static constexpr int kLatencyFrames = 3;  // GPU results are this many frames old at most

    explicit PassTimer(TimingMode mode = TimingMode::GpuQueries);
    ~PassTimer();
    PassTimer(const PassTimer&) = delete;
    PassTimer& operator=(const PassTimer&) = delete;

    void frame_begin();
    void frame_end();
    void begin(std::string_view name);
    void end();

    class Scope {
    public:
        Scope(PassTimer& timer, std::string_view name) : timer_(timer) { timer_.begin(name); }
        ~Scope() { timer_.end(); }
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;

    private:
        PassTimer& timer_;
    };
    [[nodiscard]] Scope scope(std::string_view name) { return Scope(*this, name); }

    // Passes of the last frame whose times are known, in the order they ran.
    const std::vector<PassTime>& results() const { return results_; }
    // Smoothed time of a pass name, if it has been measured.
    std::optional<double> average_ms(std::string_view name) const;
    // Number of frames whose results have been published.
    std::uint64_t completed_frames() const { return completed_frames_; }
    TimingMode mode() const { return mode_; }

private:
    struct FrameQueries {
        std::vector<std::string> names;
        std::vector<Handle<QueryDeleter>> queries;  // pool, grows to the most passes seen
        bool pending = false;
    };

    struct NameStats {
        std::string name;
        double last_ms = 0.0;
        double average_ms = 0.0;
    };

    void require(bool condition, std::string_view what) const;
    bool collect(FrameQueries& frame, bool wait);
    void publish(std::vector<PassTime> passes);
    void publish_sample();
    NameStats& record(const std::string& name, double ms, double weight);
    const NameStats* stats(std::string_view name) const;

    TimingMode mode_;
    bool in_frame_ = false;
    bool pass_open_ = false;
    std::string open_name_;
    std::uint64_t frame_number_ = 0;
    std::uint64_t completed_frames_ = 0;

    std::array<FrameQueries, kLatencyFrames> frames_;  // GpuQueries: frame n uses [n % size]
    std::chrono::steady_clock::time_point pass_start_;  // Profile, Sampled
    std::vector<PassTime> profile_passes_;              // Profile: current frame

    // Sampled: the pass names of this frame and the last in order (each once), the name
    // measured this frame, whether the open pass is it, and its time so far this frame.
    std::vector<std::string> frame_names_, last_frame_names_;
    std::string sample_name_;
    bool sampling_ = false;
    std::optional<double> sample_ms_;

    std::vector<PassTime> results_;
    std::vector<NameStats> stats_;
};

}  // namespace effects::gl
