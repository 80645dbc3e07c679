#include "effects/gl/PassTimer.h"

#include <algorithm>
#include <stdexcept>

namespace effects::gl {
namespace {
constexpr double kSmoothing = 0.1;  // weight of the newest frame in the average
}

PassTimer::PassTimer(TimingMode mode) : mode_(mode) {}

PassTimer::~PassTimer() {
    // Leaving scope mid-pass (an exception): do not leave a query running.
    if (pass_open_ && mode_ == TimingMode::GpuQueries) glEndQuery(GL_TIME_ELAPSED);
}

void PassTimer::require(bool condition, std::string_view what) const {
    if (!condition) throw std::logic_error("PassTimer: " + std::string(what));
}

void PassTimer::frame_begin() {
    require(!in_frame_, "frame_begin() twice without frame_end()");
    in_frame_ = true;
    if (mode_ == TimingMode::Profile) {
        profile_passes_.clear();
        return;
    }
    FrameQueries& frame = frames_[frame_number_ % frames_.size()];
    // Reusing this frame's queries: their results are kLatencyFrames old by now,
    // so waiting for them almost never stalls.
    if (frame.pending) collect(frame, true);
    frame.names.clear();
}

void PassTimer::begin(std::string_view name) {
    require(in_frame_, "begin('" + std::string(name) + "') outside frame_begin()/frame_end()");
    require(!pass_open_, "begin('" + std::string(name) + "') while '" + open_name_ +
                             "' is open: passes do not nest");
    pass_open_ = true;
    open_name_ = name;
    if (mode_ == TimingMode::Profile) {
        glFinish();  // earlier work must not count against this pass
        pass_start_ = std::chrono::steady_clock::now();
        return;
    }
    FrameQueries& frame = frames_[frame_number_ % frames_.size()];
    if (frame.names.size() == frame.queries.size()) {
        GLuint query = 0;
        glCreateQueries(GL_TIME_ELAPSED, 1, &query);
        label_object(GL_QUERY, query, "PassTimer");
        frame.queries.emplace_back(query);
    }
    glBeginQuery(GL_TIME_ELAPSED, frame.queries[frame.names.size()].get());
    frame.names.emplace_back(name);
}

void PassTimer::end() {
    require(pass_open_, "end() without begin()");
    pass_open_ = false;
    if (mode_ == TimingMode::Profile) {
        glFinish();
        const auto elapsed = std::chrono::steady_clock::now() - pass_start_;
        profile_passes_.push_back(
            {open_name_, std::chrono::duration<double, std::milli>(elapsed).count(), 0.0});
        return;
    }
    glEndQuery(GL_TIME_ELAPSED);
}

void PassTimer::frame_end() {
    require(in_frame_, "frame_end() without frame_begin()");
    require(!pass_open_, "frame_end() while '" + open_name_ + "' is open");
    in_frame_ = false;
    if (mode_ == TimingMode::Profile) {
        publish(std::move(profile_passes_));
        profile_passes_.clear();
        ++frame_number_;
        return;
    }
    frames_[frame_number_ % frames_.size()].pending = true;
    ++frame_number_;
    // Publish finished frames oldest first, without waiting for any.
    const std::uint64_t oldest = frame_number_ > frames_.size() ? frame_number_ - frames_.size() : 0;
    for (std::uint64_t n = oldest; n < frame_number_; ++n) {
        FrameQueries& frame = frames_[n % frames_.size()];
        if (frame.pending && !collect(frame, false)) break;
    }
}

bool PassTimer::collect(FrameQueries& frame, bool wait) {
    if (!wait) {
        for (std::size_t i = 0; i < frame.names.size(); ++i) {
            GLuint available = GL_FALSE;
            glGetQueryObjectuiv(frame.queries[i].get(), GL_QUERY_RESULT_AVAILABLE, &available);
            if (!available) return false;
        }
    }
    std::vector<PassTime> passes;
    for (std::size_t i = 0; i < frame.names.size(); ++i) {
        GLuint64 nanoseconds = 0;
        glGetQueryObjectui64v(frame.queries[i].get(), GL_QUERY_RESULT, &nanoseconds);
        passes.push_back({frame.names[i], static_cast<double>(nanoseconds) * 1e-6, 0.0});
    }
    frame.pending = false;
    publish(std::move(passes));
    return true;
}

void PassTimer::publish(std::vector<PassTime> passes) {
    // A pass name run twice in a frame averages its total.
    std::vector<std::pair<std::string, double>> totals;
    for (const PassTime& pass : passes) {
        auto it = std::find_if(totals.begin(), totals.end(),
                               [&](const auto& t) { return t.first == pass.name; });
        if (it == totals.end())
            totals.emplace_back(pass.name, pass.ms);
        else
            it->second += pass.ms;
    }
    for (const auto& total : totals) {  // not a structured binding: clang 14 cannot capture one
        auto it = std::find_if(averages_.begin(), averages_.end(),
                               [&](const auto& a) { return a.first == total.first; });
        if (it == averages_.end())
            averages_.emplace_back(total.first, total.second);
        else
            it->second += kSmoothing * (total.second - it->second);
    }
    for (PassTime& pass : passes) pass.average_ms = *average_ms(pass.name);
    results_ = std::move(passes);
    ++completed_frames_;
}

std::optional<double> PassTimer::average_ms(std::string_view name) const {
    for (const auto& [n, ms] : averages_)
        if (n == name) return ms;
    return std::nullopt;
}

}  // namespace effects::gl
