#include "edgeland/io/landscape_log.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <utility>

#include "edgeland/io/clip_log.hpp"
#include "log_text.hpp"

namespace edgeland::log {
namespace {

LandscapeLogError bad_argument(std::size_t line, const std::string& reason) {
  return LandscapeLogError(LandscapeLogErrorKind::kBadArgument, line, reason);
}

// A whole word as a decimal integer (an optional '-', then digits; no '+', no spaces).
std::optional<std::int64_t> integer_of(std::string_view word) {
  std::int64_t value = 0;
  const char* end = word.data() + word.size();
  const auto [stop, error] = std::from_chars(word.data(), end, value);
  if (word.empty() || error != std::errc() || stop != end) return std::nullopt;
  return value;
}

Material take_material(std::string_view& rest, std::string_view what, std::size_t line) {
  const std::string_view word = take_word(rest);
  if (word.empty()) throw bad_argument(line, std::string(what) + " is missing");
  const std::optional<std::int64_t> value = integer_of(word);
  if (!value || *value < 0 || *value > 255) {
    throw bad_argument(line, std::string(what) + " '" + printable_excerpt(word) +
                                 "' is not a material number 0..255");
  }
  return static_cast<Material>(*value);
}

std::int64_t take_coordinate(std::string_view& rest, std::size_t line) {
  const std::string_view word = take_word(rest);
  if (word.empty()) throw bad_argument(line, "world: expected X0 Y0 X1 Y1 [MATERIAL]");
  const std::optional<std::int64_t> value = integer_of(word);
  if (!value || !coord_in_range(*value)) {
    throw bad_argument(line, "world: coordinate '" + printable_excerpt(word) +
                                 "' is not an integer within +-" + std::to_string(kCoordBound));
  }
  return *value;
}

// `X0 Y0 X1 Y1 [MATERIAL]`, the box of positive width and height.
WorldCommand parse_world(std::string_view rest, std::size_t line) {
  WorldCommand world;
  world.line = line;
  world.box.min.x = take_coordinate(rest, line);
  world.box.min.y = take_coordinate(rest, line);
  world.box.max.x = take_coordinate(rest, line);
  world.box.max.y = take_coordinate(rest, line);
  if (!rest.empty()) world.fill = take_material(rest, "world: material", line);
  if (!rest.empty()) {
    throw bad_argument(
        line, "world: unexpected '" + printable_excerpt(rest) + "' after X0 Y0 X1 Y1 [MATERIAL]");
  }
  if (!world.box.has_interior()) {
    throw bad_argument(line, "world: the box needs X0 < X1 and Y0 < Y1");
  }
  return world;
}

// `wkt` is the rest of `raw`, the whole line.
WktGeometry parse_shape(std::string_view raw, std::string_view wkt, std::string_view keyword,
                        std::size_t line) {
  if (wkt.empty()) {
    throw LandscapeLogError(LandscapeLogErrorKind::kMissingShape, line,
                            std::string(keyword) + ": missing WKT shape");
  }
  try {
    return read_wkt(wkt);
  } catch (const WktError& error) {
    const ShapeError where = shape_error(raw, wkt, error);
    LandscapeLogError log_error(LandscapeLogErrorKind::kBadShape, line,
                                std::string(keyword) + ": " + where.reason, where.column);
    log_error.wkt_error = error.kind;
    throw log_error;
  }
}

// relabel's `FROM TO` pairs, up to the WKT (whose keyword is no number); a FROM at most once.
MaterialMap take_pairs(std::string_view& rest, std::size_t line) {
  MaterialMap map;
  std::array<bool, kMaterialCount> named{};
  for (std::string_view ahead = rest; integer_of(take_word(ahead)); ahead = rest) {
    const Material from = take_material(rest, "relabel: FROM", line);
    if (named[from.value()]) {
      throw bad_argument(line, "relabel: FROM " + to_string(from) + " is given twice");
    }
    named[from.value()] = true;
    map.set(from, take_material(rest, "relabel: TO", line));
  }
  return map;
}

LandscapeEdit parse_edit(const EditKeyword& keyword, std::string_view raw, std::string_view rest,
                         std::size_t line) {
  LandscapeEdit edit;
  edit.kind = keyword.kind;
  edit.line = line;
  const std::string name(keyword.word);
  if (keyword.materials < 0) edit.map = take_pairs(rest, line);
  if (keyword.materials == 2) edit.from = take_material(rest, name + ": FROM", line);
  if (keyword.materials >= 1) {
    edit.material =
        take_material(rest, name + (keyword.materials == 2 ? ": TO" : ": material"), line);
  }
  edit.shape = parse_shape(raw, rest, keyword.word, line);
  return edit;
}

// `batch EDIT | EDIT | ...`: each part an edit line's words (its WKT a part of `raw`, so that a
// bad shape's column is the log line's). Every edit carries the line and the batch's size.
LandscapeBatch parse_batch(std::string_view raw, std::string_view rest, std::size_t line) {
  LandscapeBatch batch;
  batch.line = line;
  for (bool more = true; more;) {
    const std::size_t bar = rest.find(kBatchSeparator);
    more = bar != std::string_view::npos;
    std::string_view part = trim_blanks(rest.substr(0, bar));
    if (more) rest.remove_prefix(bar + 1);
    const std::string_view word = take_word(part);
    if (word.empty())
      throw bad_argument(line, "batch: edit " + std::to_string(batch.edits.size() + 1) +
                                   " is empty (expected EDIT | EDIT | ...)");
    const EditKeyword* keyword = find_edit_keyword(word);
    if (!keyword)
      throw LandscapeLogError(LandscapeLogErrorKind::kUnknownCommand, line,
                              "batch: unknown edit '" + printable_excerpt(word) +
                                  "' (expected carve, fill, fill_empty, replace or relabel)");
    batch.edits.push_back(parse_edit(*keyword, raw, part, line));
  }
  for (LandscapeEdit& e : batch.edits) e.batch = batch.edits.size();
  return batch;
}

// The first command word of the text, or empty when it has no command.
std::string_view first_command(std::string_view text) {
  while (!text.empty()) {
    std::string_view line = trim_blanks(take_line(text));
    if (!is_skipped_line(line)) return take_word(line);
  }
  return {};
}

LandscapeLogError missing_world(std::size_t line) {
  return LandscapeLogError(LandscapeLogErrorKind::kMissingWorld, line,
                           "a landscape log starts with `world X0 Y0 X1 Y1 [MATERIAL]`");
}

// Places one parsed command in the log: the world line first and only there.
void add_command(ParsedLandscapeLog& parsed, LandscapeCommand command, std::size_t line) {
  if (auto* world = std::get_if<WorldCommand>(&command)) {
    if (parsed.world) {
      throw LandscapeLogError(
          LandscapeLogErrorKind::kRepeatedWorld, line,
          "a second world line (the first is line " + std::to_string(parsed.world->line) + ")");
    }
    parsed.world = *world;
    return;
  }
  if (!parsed.world) throw missing_world(line);
  if (auto* batch = std::get_if<LandscapeBatch>(&command)) {
    for (LandscapeEdit& e : batch->edits) parsed.edits.push_back(std::move(e));
    return;
  }
  parsed.edits.push_back(std::get<LandscapeEdit>(std::move(command)));
}

}  // namespace

const char* landscape_edit_keyword(LandscapeEditKind kind) noexcept {
  return edit_keyword(kind).word.data();  // the table's words are string literals
}

const char* landscape_log_error_kind_name(LandscapeLogErrorKind kind) noexcept {
  switch (kind) {
    case LandscapeLogErrorKind::kUnknownCommand:
      return "unknown-command";
    case LandscapeLogErrorKind::kMissingWorld:
      return "missing-world";
    case LandscapeLogErrorKind::kRepeatedWorld:
      return "repeated-world";
    case LandscapeLogErrorKind::kBadArgument:
      return "bad-argument";
    case LandscapeLogErrorKind::kMissingShape:
      return "missing-shape";
    case LandscapeLogErrorKind::kBadShape:
      return "bad-shape";
  }
  return "?";
}

LandscapeLogError::LandscapeLogError(LandscapeLogErrorKind kind_, std::size_t line_,
                                     const std::string& reason, std::size_t column_)
    : Error(line_place(line_, column_) + ": " + reason),
      kind(kind_),
      line(line_),
      column(column_) {}

std::optional<LandscapeCommand> parse_landscape_line(std::string_view raw,
                                                     std::size_t line_number) {
  std::string_view rest = trim_blanks(raw);
  if (is_skipped_line(rest)) return std::nullopt;
  const std::string_view word = take_word(rest);
  if (word == kWorldKeyword) return parse_world(rest, line_number);
  if (word == kBatchKeyword) return parse_batch(raw, rest, line_number);
  if (const EditKeyword* keyword = find_edit_keyword(word)) {
    return parse_edit(*keyword, raw, rest, line_number);
  }
  throw LandscapeLogError(
      LandscapeLogErrorKind::kUnknownCommand, line_number,
      "unknown command '" + printable_excerpt(word) +
          "' (expected world, carve, fill, fill_empty, replace, relabel or batch)");
}

ParsedLandscapeLog parse_landscape_log(std::string_view text) {
  ParsedLandscapeLog parsed;
  std::size_t line_number = 0;
  try {
    while (!text.empty()) {
      ++line_number;
      if (std::optional<LandscapeCommand> command =
              parse_landscape_line(take_line(text), line_number)) {
        add_command(parsed, std::move(*command), line_number);
      }
    }
    if (!parsed.world) throw missing_world(1);
  } catch (const LandscapeLogError& error) {
    parsed.error = error;
  }
  return parsed;
}

bool is_landscape_log(std::string_view text) { return first_command(text) == kWorldKeyword; }

Landscape make_landscape(const WorldCommand& world) { return Landscape(world.box, world.fill); }

ChangeSet apply_edit(Landscape& landscape, const LandscapeEdit& edit) {
  const PolygonSet shape = shape_to_set(edit.shape, ClipOptions{.checked = landscape.checked()});
  if (edit.kind == LandscapeEditKind::kRelabel) return landscape.relabel(shape, edit.map);
  return apply_edit(landscape, edit.kind, shape, edit.material, edit.from);
}

ChangeSet apply_edit(Landscape& landscape, LandscapeEditKind kind, const PolygonSet& shape,
                     Material material, Material from) {
  switch (kind) {
    case LandscapeEditKind::kCarve:
      return landscape.carve(shape);
    case LandscapeEditKind::kFill:
      return landscape.fill(shape, material);
    case LandscapeEditKind::kFillEmpty:
      return landscape.fill_empty(shape, material);
    case LandscapeEditKind::kReplace:
    case LandscapeEditKind::kRelabel:
      break;
  }
  return landscape.replace(shape, from, material);
}

namespace {

// The edit as Landscape::apply_batch takes it, its shape read as apply_edit reads it.
Edit as_edit(const LandscapeEdit& e, const ClipOptions& options) {
  ValidSet shape = edit_shape(shape_to_set(e.shape, options));
  switch (e.kind) {
    case LandscapeEditKind::kCarve:
      return Edit::carve(std::move(shape));
    case LandscapeEditKind::kFill:
      return Edit::fill(std::move(shape), e.material);
    case LandscapeEditKind::kFillEmpty:
      return Edit::fill_empty(std::move(shape), e.material);
    case LandscapeEditKind::kReplace:
      return Edit::replace(std::move(shape), e.from, e.material);
    case LandscapeEditKind::kRelabel:
      break;
  }
  return Edit::relabel(std::move(shape), e.map);
}

}  // namespace

std::size_t step_size(std::span<const LandscapeEdit> edits) noexcept {
  if (edits.empty()) return 0;
  return std::clamp<std::size_t>(edits.front().batch, 1, edits.size());
}

ChangeSet apply_step(Landscape& landscape, std::span<const LandscapeEdit> step) {
  if (step.size() == 1 && step.front().batch == 0) return apply_edit(landscape, step.front());
  std::vector<Edit> batch;
  batch.reserve(step.size());
  for (const LandscapeEdit& e : step)
    batch.push_back(as_edit(e, ClipOptions{.checked = landscape.checked()}));
  return landscape.apply_batch(batch);
}

}  // namespace edgeland::log
