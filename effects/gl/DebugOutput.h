#pragma once
#include "effects/gl/Gl.h"

#include <cstddef>
#include <functional>
#include <iosfwd>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <tuple>

namespace effects::gl {

// Prints the driver's high and medium severity debug messages (KHR_debug, core in
// 4.5) to a stream, each distinct message once. Distinct means id and text: Mesa
// gives every GL error the same id, so the id alone would hide all but the first;
// an id whose texts keep changing stops printing after kMaxTextsPerId. Installs on the current context at
// construction and uninstalls at destruction. Messages arrive synchronously, so a
// breakpoint in the callback shows the offending call. A debug context
// (HeadlessContext debug flag) makes drivers report more.
class DebugOutput {
public:
    explicit DebugOutput(std::ostream& sink);
    DebugOutput();  // prints to stderr
    ~DebugOutput();
    DebugOutput(const DebugOutput&) = delete;
    DebugOutput& operator=(const DebugOutput&) = delete;

    static constexpr std::size_t kMaxTextsPerId = 8;

    std::size_t printed() const;     // distinct messages printed
    std::size_t suppressed() const;  // repeats not printed

private:
    static void APIENTRY on_message(GLenum source, GLenum type, GLuint id, GLenum severity,
                                      GLsizei length, const GLchar* message,
                                      const void* user);
    void handle(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                const GLchar* message);

    std::ostream& sink_;
    mutable std::mutex mutex_;
    using MessageId = std::tuple<GLenum, GLenum, GLuint>;  // (source, type, id)
    std::map<MessageId, std::set<std::string, std::less<>>> seen_;
    std::size_t printed_ = 0;
    std::size_t suppressed_ = 0;
};

}  // namespace effects::gl
