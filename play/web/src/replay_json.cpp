#include "replay_json.hpp"

#include <iostream>
#include <sstream>

#include "landscape_png.hpp"
#include "landscape_replay.hpp"

namespace edgeland {

// The page never asks for a picture (ReplayOptions::png stays empty), and cairo is not built
// for the browser: this definition only satisfies the linker for cli/landscape_replay.cpp.
void cli::write_landscape_png(const Landscape&, const std::string& path, const PngOptions&) {
  throw PngError("cannot write PNG '" + path + "': no cairo in the browser");
}

namespace play {
namespace {

// cli/landscape_replay.cpp prints to std::cout and std::cerr, as the command does; while it
// runs, both go to strings instead.
class CapturedStreams {
 public:
  CapturedStreams() : out_(std::cout.rdbuf(json_.rdbuf())), err_(std::cerr.rdbuf(error_.rdbuf())) {}
  ~CapturedStreams() {
    std::cout.rdbuf(out_);
    std::cerr.rdbuf(err_);
  }
  CapturedStreams(const CapturedStreams&) = delete;
  CapturedStreams& operator=(const CapturedStreams&) = delete;

  static std::string first_line(const std::ostringstream& s) {
    const std::string text = s.str();
    return text.substr(0, text.find('\n'));
  }
  std::string json() const { return first_line(json_); }
  std::string error() const { return first_line(error_); }

 private:
  std::ostringstream json_, error_;
  std::streambuf* out_;
  std::streambuf* err_;
};

}  // namespace

ReplayOutput replay_landscape_text(std::string_view text) {
  CapturedStreams streams;
  const int status = cli::replay_landscape_log(text, cli::ReplayOptions{.path = "log"});
  return {streams.json(), streams.error(), status};
}

}  // namespace play
}  // namespace edgeland
