#include "replay_json.hpp"

#include "edgeland/io/landscape_replay.hpp"

namespace edgeland::play {

// What `edgeland replay LOG` prints for the same text (cli/landscape_replay.cpp): the library's
// JSON line, the message on stderr ("edgeland replay: log: ..." as for a file named "log"),
// and the exit status (2 unreadable, 3 internal).
ReplayOutput replay_landscape_text(std::string_view text) {
  const log::LandscapeReplay replay = log::replay_landscape_log(text);
  ReplayOutput out{log::replay_json(replay), "", 0};
  if (replay.failure) {
    out.error = "edgeland replay: log: " + replay.failure->message;
    out.status = replay.failure->kind == log::ReplayFailure::Kind::kInternal ? 3 : 2;
  }
  return out;
}

}  // namespace edgeland::play
