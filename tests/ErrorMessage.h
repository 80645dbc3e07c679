#pragma once
// The message an input check throws, for tests that assert what it names.
#include <exception>
#include <string>

// The message of the `Error` that `f` throws, or "(no exception)"; any other exception
// goes on up (and fails the test).
template <typename Error = std::exception, typename F>
std::string message_of(F&& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "(no exception)";
}
