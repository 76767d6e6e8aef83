#pragma once
// Recorded input of the desktop demo: the mouse and the keys, frame by frame, as text, so that a
// session can be replayed without a person (`--script FILE`) and recorded from one
// (`--record FILE`). One event a line, `FRAME EVENT [ARGS]`, frames ascending:
//   FRAME tool NAME        explosion | digger | fill | water | replace | ball | box
//   FRAME material M       the material of fill and the target of replace (1..255)
//   FRAME from M           the material replace turns into the target
//   FRAME radius R         the tool's radius in world units
//   FRAME down X Y         the left button pressed at window pixel (X, Y)
//   FRAME move X Y         the mouse moved there (a drag while pressed)
//   FRAME up X Y           the button released there
//   FRAME wheel N          N wheel steps (negative: down); the radius grows 15 % a step
//   FRAME key NAME         ctrl+z (undo), ctrl+y (redo), f5 (save), f9 (load), c (cell lines),
//                          d (dirty cells), b (a ball at the mouse), x (a box at the mouse)
//   # a comment; blank lines are skipped
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace edgeland::play {

enum class InputKind : std::uint8_t {
  kTool,
  kMaterial,
  kFrom,
  kRadius,
  kDown,
  kMove,
  kUp,
  kWheel,
  kKey
};

struct InputEvent {
  std::uint64_t frame = 0;
  InputKind kind = InputKind::kMove;
  int x = 0, y = 0;    // pixels (down, move, up); the number (material, from, radius, wheel)
  std::string name{};  // tool or key name
};

// A line of a script that cannot be read; what() is "line N: reason".
class ScriptError : public std::runtime_error {
 public:
  ScriptError(std::size_t line, const std::string& reason);
  std::size_t line;
};

// Reads a whole script. Throws ScriptError at the first bad line.
std::vector<InputEvent> parse_input_script(std::string_view text);

// One event as a script line (with its '\n'), the inverse of the parser.
std::string input_line(const InputEvent& event);

}  // namespace edgeland::play
