#include "input_script.hpp"

#include <array>
#include <charconv>
#include <utility>

#include "edgeland/io/log_words.hpp"

namespace edgeland::play {
namespace {

constexpr std::array<std::pair<std::string_view, InputKind>, 9> kKinds{{
    {"tool", InputKind::kTool},
    {"material", InputKind::kMaterial},
    {"from", InputKind::kFrom},
    {"radius", InputKind::kRadius},
    {"down", InputKind::kDown},
    {"move", InputKind::kMove},
    {"up", InputKind::kUp},
    {"wheel", InputKind::kWheel},
    {"key", InputKind::kKey},
}};

std::string_view kind_name(InputKind kind) {
  for (const auto& [name, k] : kKinds) {
    if (k == kind) return name;
  }
  return "?";
}

template <class T>
T number(std::string_view word, std::size_t line, std::string_view what) {
  T value{};
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (word.empty() || error != std::errc{} || end != word.data() + word.size()) {
    throw ScriptError(
        line, std::string(what) + " is not an integer: '" + log::printable_excerpt(word) + "'");
  }
  return value;
}

bool takes_point(InputKind kind) {
  return kind == InputKind::kDown || kind == InputKind::kMove || kind == InputKind::kUp;
}
bool takes_name(InputKind kind) { return kind == InputKind::kTool || kind == InputKind::kKey; }

// The words after FRAME EVENT.
void read_arguments(InputEvent& event, std::string_view rest, std::size_t line) {
  if (takes_name(event.kind)) {
    event.name = std::string(log::take_word(rest));
    if (event.name.empty()) throw ScriptError(line, "a name is missing");
  } else if (takes_point(event.kind)) {
    event.x = number<int>(log::take_word(rest), line, "x");
    event.y = number<int>(log::take_word(rest), line, "y");
  } else {
    event.x = number<int>(log::take_word(rest), line, "the number");
  }
  if (!rest.empty()) throw ScriptError(line, "unexpected words at the end");
}

InputEvent parse_line(std::string_view rest, std::size_t line) {
  InputEvent event;
  event.frame = number<std::uint64_t>(log::take_word(rest), line, "the frame");
  const std::string_view word = log::take_word(rest);
  bool known = false;
  for (const auto& [name, kind] : kKinds) {
    if (name == word) {
      event.kind = kind;
      known = true;
    }
  }
  if (!known) throw ScriptError(line, "unknown event '" + log::printable_excerpt(word) + "'");
  read_arguments(event, rest, line);
  return event;
}

}  // namespace

ScriptError::ScriptError(std::size_t line_number, const std::string& reason)
    : std::runtime_error("line " + std::to_string(line_number) + ": " + reason),
      line(line_number) {}

std::vector<InputEvent> parse_input_script(std::string_view text) {
  std::vector<InputEvent> events;
  std::size_t line = 0;
  while (!text.empty()) {
    ++line;
    const std::string_view trimmed = log::trim_blanks(log::take_line(text));
    if (log::is_skipped_line(trimmed)) continue;
    InputEvent event = parse_line(trimmed, line);
    if (!events.empty() && event.frame < events.back().frame) {
      throw ScriptError(line, "frames must not go back");
    }
    events.push_back(std::move(event));
  }
  return events;
}

std::string input_line(const InputEvent& event) {
  std::string out = std::to_string(event.frame) + " " + std::string(kind_name(event.kind));
  if (takes_name(event.kind)) {
    out += " " + event.name;
  } else if (takes_point(event.kind)) {
    out += " " + std::to_string(event.x) + " " + std::to_string(event.y);
  } else {
    out += " " + std::to_string(event.x);
  }
  return out + "\n";
}

}  // namespace edgeland::play
