#include "game/cli/Progress.h"

#include <unistd.h>

#include <cstdio>

namespace game {

Progress::Progress(std::string label, size_t total, std::string unit)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      total_(total),
      start_(std::chrono::steady_clock::now()),
      last_print_(start_),
      tty_(isatty(fileno(stderr)) != 0) {}

Progress::~Progress() { finish(); }

void Progress::update(size_t done) {
    done_ = done;
    auto now = std::chrono::steady_clock::now();
    // Terminals get a live line; logs get a line every few seconds.
    auto every = tty_ ? std::chrono::milliseconds(250) : std::chrono::milliseconds(3000);
    if (now - last_print_ < every) return;
    last_print_ = now;
    print(done, false);
}

void Progress::finish() {
    if (finished_) return;
    finished_ = true;
    if (std::chrono::steady_clock::now() - start_ > std::chrono::milliseconds(500)) print(done_, true);
}

void Progress::print(size_t done, bool last) {
    double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    double rate = s > 0 ? double(done) / s : 0.0;
    double eta = rate > 0 ? double(total_ - std::min(done, total_)) / rate : 0.0;
    std::fprintf(stderr, "%s%s: %zu/%zu %s, %.1f/s, %s %.1f s%s", tty_ ? "\r" : "", label_.c_str(), done, total_,
                 unit_.c_str(), rate, last ? "took" : "ETA", last ? s : eta, (tty_ && !last) ? "   " : "\n");
    std::fflush(stderr);
}

}  // namespace game
