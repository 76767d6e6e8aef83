// el_replay_*: io's replay of a landscape edit log (landscape_replay.hpp), one translation each.
#include <memory>
#include <string_view>

#include "border.hpp"
#include "edgeland/edgeland.h"
#include "edgeland/io/landscape_replay.hpp"
#include "handles.hpp"
#include "translate.hpp"

namespace edgeland::capi {
namespace {

const log::LandscapeReplay& replay_of(const el_replay* replay) {
  return object_of(replay, "replay").replay;
}

// Why a replay stopped, thrown for execute() to write with its line: a line that cannot be read
// or an edit refused is EL_LOAD_ERROR, a bug of edgeland's EL_INTERNAL (line 0: the final check).
[[noreturn]] void throw_stop(const log::ReplayFailure& stop) {
  const bool internal = stop.kind == log::ReplayFailure::Kind::kInternal;
  throw BorderError(internal ? EL_INTERNAL : EL_LOAD_ERROR, stop.message, stop.line);
}

}  // namespace
}  // namespace edgeland::capi

using namespace edgeland;
using namespace edgeland::capi;

extern "C" {

EL_API el_status el_replay_log(const char* text, size_t size, el_replay** out, el_error* error) {
  return execute(error, [&] {
    need(out, "out");
    if (size > 0) need(text, "text");
    const std::string_view log_text = size > 0 ? std::string_view(text, size) : std::string_view();
    hand_out(std::make_unique<ReplayHandle>(
                 ReplayHandle{log::replay_landscape_log(log_text, {.record_log = true})}),
             out);
  });
}

EL_API void el_replay_destroy(el_replay* replay) { delete object(replay); }

EL_API el_status el_replay_landscape(const el_replay* replay, el_landscape** out, el_error* error) {
  return execute(error, [&] {
    const log::LandscapeReplay& r = replay_of(replay);
    need(out, "out");
    if (!r.landscape) throw_stop(*r.failure);
    hand_out(std::make_unique<LandscapeHandle>(LandscapeHandle{*r.landscape}), out);
  });
}

EL_API size_t el_replay_edits(const el_replay* replay) {
  return replay == nullptr ? 0 : object(replay)->replay.edits;
}

EL_API el_status el_replay_stopped(const el_replay* replay, el_error* error) {
  return execute(error, [&] {
    const log::LandscapeReplay& r = replay_of(replay);
    if (r.failure) throw_stop(*r.failure);
  });
}

EL_API el_status el_replay_report(const el_replay* replay, el_bytes** out, el_error* error) {
  return execute(error, [&] {
    const log::LandscapeReplay& r = replay_of(replay);
    need(out, "out");
    hand_out(bytes_of(log::replay_json(r)), out);
  });
}

}  // extern "C"
