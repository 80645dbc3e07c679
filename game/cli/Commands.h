#pragma once
// The subcommands of `spindrift`; each returns an ExitCode.
#include <string>
#include <vector>

namespace game {

int play_command(const std::vector<std::string>& args);
int record_command(const std::vector<std::string>& args);
int replay_command(const std::vector<std::string>& args);
int bench_command(const std::vector<std::string>& args);
int timedemo_command(const std::vector<std::string>& args);
int fibres_command(const std::vector<std::string>& args);

// Whether a window can be opened here (an X11 or Wayland display is set).
bool display_available();

}  // namespace game
