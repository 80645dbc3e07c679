#pragma once
// Runs `spindrift` as a user would, with OpenAL's null backend (no test plays sound on a
// device), and returns its exit code and everything it printed.
#include <sys/wait.h>

#include <cstdio>
#include <string>

struct ProgramRun {
    int code = -1;
    std::string output;  // stdout and stderr
};

inline ProgramRun run_spindrift(const std::string& args) {
    ProgramRun r;
    FILE* p = popen(("ALSOFT_DRIVERS=null " + std::string(SPINDRIFT_BIN) + " " + args + " 2>&1").c_str(), "r");
    if (!p) return r;
    char buf[4096];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, p)) > 0) r.output.append(buf, n);
    const int status = pclose(p);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return r;
}
