// `edgeland replay`'s JSON for a landscape log, from edgeland::io alone: what the browser
// playground runs. scripts/wasm_determinism.sh builds it with Emscripten and compares its output
// with the native command's. Usage: wasm_replay LOG (read through Node's file system).
#include <cstdio>
#include <fstream>
#include <sstream>

#include "edgeland/io/landscape_replay.hpp"

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  std::ifstream in(argv[1], std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  if (!in) return 2;
  const edgeland::log::LandscapeReplay replay = edgeland::log::replay_landscape_log(text.str());
  std::printf("%s\n", edgeland::log::replay_json(replay).c_str());
  return replay.failure ? 1 : 0;
}
