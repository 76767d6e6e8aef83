// The JavaScript API of the WebAssembly module (embind): `new Module.World(x0, y0, x1, y1, fill,
// seed)` with apply / undo / redo / everything / loadLog returning update objects of typed
// arrays, log(), stateHash(), stats(); `Module.replay(logText)`, the JSON text that `edgeland
// replay` prints for that log; `Module.materialColour(m)`. play/web/README.md documents it for the
// page.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <string>

#include "edgeland/demo/palette.hpp"
#include "replay_json.hpp"
#include "web_world.hpp"

namespace edgeland::play {
namespace {

using emscripten::val;

// A copy of `values` as a new JavaScript typed array of type `type`.
template <class T>
val typed_array(const char* type, const std::vector<T>& values) {
  return val::global(type).new_(emscripten::typed_memory_view(values.size(), values.data()));
}

val to_js(const WebUpdate& u) {
  val out = val::object();
  out.set("reset", u.reset);
  out.set("removed", typed_array("Float64Array", u.removed));
  out.set("ids", typed_array("Float64Array", u.ids));
  out.set("materials", typed_array("Uint8Array", u.materials));
  out.set("offsets", typed_array("Uint32Array", u.offsets));
  out.set("xy", typed_array("Int32Array", u.xy));
  out.set("cells", typed_array("Int32Array", u.cells));
  out.set("chainsRemoved", typed_array("Float64Array", u.chains_removed));
  out.set("chainIds", typed_array("Float64Array", u.chain_ids));
  out.set("chainClosed", typed_array("Uint8Array", u.chain_closed));
  out.set("chainOffsets", typed_array("Uint32Array", u.chain_offsets));
  out.set("chainXy", typed_array("Int32Array", u.chain_xy));
  out.set("chainGhosts", typed_array("Int32Array", u.chain_ghosts));
  out.set("debrisCentroids", typed_array("Float64Array", u.debris_centroids));
  out.set("debrisPieces", typed_array("Uint32Array", u.debris_pieces));
  out.set("pieceMaterials", typed_array("Uint8Array", u.piece_materials));
  out.set("pieceOffsets", typed_array("Uint32Array", u.piece_offsets));
  out.set("pieceXy", typed_array("Float64Array", u.piece_xy));
  out.set("error", u.error);
  return out;
}

// Coordinates arrive as JavaScript numbers; the page rounds them to integers first.
Point64 point(double x, double y) {
  return {static_cast<std::int64_t>(x), static_cast<std::int64_t>(y)};
}

class JsWorld {
 public:
  JsWorld(double x0, double y0, double x1, double y1, int fill, double seed)
      : world_(Box64{point(x0, y0), point(x1, y1)}, static_cast<Material>(fill),
               static_cast<std::uint64_t>(seed)) {}

  // tool: 0 explosion, 1 digger, 2 fill, 3 water, 4 replace (ToolKind's order).
  val apply(int tool, double fx, double fy, double tx, double ty, double radius, int material,
            int from) {
    const ToolEdit edit{.tool = static_cast<ToolKind>(tool),
                        .from = point(fx, fy),
                        .to = point(tx, ty),
                        .radius = static_cast<std::int64_t>(radius),
                        .material = static_cast<Material>(material),
                        .from_material = static_cast<Material>(from)};
    return to_js(world_.apply(edit));
  }
  val undo() { return to_js(world_.undo()); }
  val redo() { return to_js(world_.redo()); }
  val everything() const { return to_js(world_.everything()); }
  val load_log(const std::string& text) { return to_js(world_.load_log(text)); }
  // The world box as [x0, y0, x1, y1] (a loaded log brings its own).
  val box() const {
    const Box64& b = world_.landscape().world();
    const std::vector<double> corners{static_cast<double>(b.min.x), static_cast<double>(b.min.y),
                                      static_cast<double>(b.max.x), static_cast<double>(b.max.y)};
    return typed_array("Float64Array", corners);
  }
  val cells() const { return typed_array("Int32Array", world_.cells()); }
  std::string log() const { return world_.log(); }
  std::string state_hash() const { return world_.state_hash(); }
  val stats() const {
    const WebStats s = world_.stats();
    val out = val::object();
    out.set("polygons", static_cast<double>(s.polygons));
    out.set("vertices", static_cast<double>(s.vertices));
    out.set("cells", static_cast<double>(s.cells));
    out.set("depth", static_cast<double>(s.depth));
    out.set("edits", static_cast<double>(s.edits));
    out.set("chains", static_cast<double>(s.chains));
    out.set("islandsDetached", static_cast<double>(s.islands_detached));
    out.set("lastEditMs", s.last_edit_ms);
    out.set("totalEditMs", s.total_edit_ms);
    return out;
  }

 private:
  WebWorld world_;
};

// The JSON `edgeland replay` prints, with "stderr" and "status" beside it for the page.
val replay(const std::string& text) {
  const ReplayOutput out = replay_landscape_text(text);
  val result = val::object();
  result.set("json", out.json);
  result.set("stderr", out.error);
  result.set("status", out.status);
  return result;
}

// A material's colour in pictures (edgeland/demo/palette.hpp) as 0xRRGGBB, so that the page
// and the PNGs agree.
int material_colour(int material) {
  const demo::Rgb c = demo::material_colour(static_cast<Material>(material));
  return c.r << 16 | c.g << 8 | c.b;
}

}  // namespace

EMSCRIPTEN_BINDINGS(edgeland_web) {
  emscripten::class_<JsWorld>("World")
      .constructor<double, double, double, double, int, double>()
      .function("apply", &JsWorld::apply)
      .function("undo", &JsWorld::undo)
      .function("redo", &JsWorld::redo)
      .function("everything", &JsWorld::everything)
      .function("loadLog", &JsWorld::load_log)
      .function("box", &JsWorld::box)
      .function("cells", &JsWorld::cells)
      .function("log", &JsWorld::log)
      .function("stateHash", &JsWorld::state_hash)
      .function("stats", &JsWorld::stats);
  emscripten::function("replay", &replay);
  emscripten::function("materialColour", &material_colour);
}

}  // namespace edgeland::play
