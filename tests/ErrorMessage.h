#pragma once
// The message an input check throws, for tests that assert what it names.
#include <exception>
#include <functional>
#include <string>

inline std::string message_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const std::exception& e) {
        return e.what();
    }
    return "(no exception)";
}
