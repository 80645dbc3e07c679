#pragma once
// Progress of long headless work on stderr: done/total, rate and time left, at most
// a few updates a second, on one line when stderr is a terminal.
#include <chrono>
#include <string>

namespace game {

class Progress {
public:
    Progress(std::string label, size_t total, std::string unit);
    ~Progress();
    void update(size_t done);
    void finish();

private:
    void print(size_t done, bool last);
    std::string label_, unit_;
    size_t total_;
    std::chrono::steady_clock::time_point start_, last_print_;
    bool tty_;
    bool finished_ = false;
    size_t done_ = 0;
};

}  // namespace game
