#include "effects/gl/PassTimer.h"

#include <algorithm>
#include <stdexcept>

namespace effects::gl {
namespace {
constexpr double kSmoothing = 0.1;  // weight of the newest frame in the average
// A sampled pass is measured once a round of passes, so its newest time weighs more.
constexpr double kSampleSmoothing = 0.25;

double ms_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}
}  // namespace

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
    if (mode_ == TimingMode::Sampled) {
        frame_names_.clear();
        sample_ms_.reset();
        // The first frame only lists the passes: its times are mostly the driver
        // compiling shaders, and a pass measured once a round would show them for long.
        sample_name_ = last_frame_names_.empty()
                           ? std::string()
                           : last_frame_names_[(frame_number_ - 1) % last_frame_names_.size()];
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
    if (mode_ == TimingMode::Sampled) {
        if (std::find(frame_names_.begin(), frame_names_.end(), name) == frame_names_.end())
            frame_names_.emplace_back(name);
        sampling_ = !sample_name_.empty() && name == sample_name_;
        if (!sampling_) return;
    }
    if (mode_ == TimingMode::Profile || mode_ == TimingMode::Sampled) {
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
        profile_passes_.push_back({open_name_, ms_since(pass_start_), 0.0});
        return;
    }
    if (mode_ == TimingMode::Sampled) {
        if (!sampling_) return;
        sampling_ = false;
        glFinish();
        sample_ms_ = sample_ms_.value_or(0.0) + ms_since(pass_start_);
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
    if (mode_ == TimingMode::Sampled) {
        publish_sample();
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

PassTimer::NameStats& PassTimer::record(const std::string& name, double ms, double weight) {
    auto it = std::find_if(stats_.begin(), stats_.end(), [&](const NameStats& s) { return s.name == name; });
    if (it == stats_.end()) return stats_.emplace_back(NameStats{name, ms, ms});
    it->last_ms = ms;
    it->average_ms += weight * (ms - it->average_ms);
    return *it;
}

const PassTimer::NameStats* PassTimer::stats(std::string_view name) const {
    for (const NameStats& s : stats_)
        if (s.name == name) return &s;
    return nullptr;
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
    for (const auto& total : totals) record(total.first, total.second, kSmoothing);
    for (PassTime& pass : passes) pass.average_ms = stats(pass.name)->average_ms;
    results_ = std::move(passes);
    ++completed_frames_;
}

void PassTimer::publish_sample() {
    if (sample_ms_) record(sample_name_, *sample_ms_, kSampleSmoothing);
    // Every pass of this frame measured so far, with its latest measurement.
    results_.clear();
    for (const std::string& name : frame_names_)
        if (const NameStats* s = stats(name)) results_.push_back({name, s->last_ms, s->average_ms});
    last_frame_names_ = std::move(frame_names_);
    frame_names_.clear();
    ++completed_frames_;
}

std::optional<double> PassTimer::average_ms(std::string_view name) const {
    if (const NameStats* s = stats(name)) return s->average_ms;
    return std::nullopt;
}

}  // namespace effects::gl
