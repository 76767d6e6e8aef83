#pragma once
// The fuzz targets' decoding and checking code, shared by the libFuzzer executables (clang,
// fuzz/CMakeLists.txt) and by the regression replay in the normal gcc build
// (tests/regress/CMakeLists.txt), so that a saved input means the same case in both.
//
// Each run_* function decodes one input (FuzzedDataProvider, structure-aware), runs the
// library in checked mode and checks its contracts. It returns a Finding when a contract is
// broken (an InternalError, an invalid output, a wrong area or point classification, an
// exception that is not the documented typed error); memory errors are left to the
// sanitizers. Inputs that decode to nothing interesting simply pass.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace edgeland::fuzz {

struct Finding {
  std::string what;  // one paragraph: the broken contract and the inputs as WKT
  std::string log;   // a replayable continuous-clip log of the case (empty if not a clip)
};

// Two valid polygon sets biased toward near-degenerate geometry (shared edges, vertices on
// edges, one-unit slivers, coordinates at +-kCoordBound, many edges through one pixel); all
// four operations; every output validated; exact area identities when nothing was snapped,
// the accuracy contract's bound otherwise; for small inputs lattice points far from both
// boundaries are classified against the operands (kernel point-in-polygon).
std::optional<Finding> run_clip_pair(const std::uint8_t* data, std::size_t size);

// A continuous-clip sequence on one evolving set (operands built from the current state's
// own vertices); every output validated; a step rejected with InvalidInput leaves the set
// unchanged; the recorded log replays to the same final state.
std::optional<Finding> run_clip_sequence(const std::uint8_t* data, std::size_t size);

// Arbitrary rings (any orientation, self-intersections, repeats, out-of-range coordinates)
// and a fill rule: a valid set, or InvalidInput when a coordinate is out of range; for small
// inputs lattice points far from every ring are classified against the winding numbers.
std::optional<Finding> run_normalize(const std::uint8_t* data, std::size_t size);

// The WKT reader and the log parser on arbitrary bytes: a result or their typed error.
std::optional<Finding> run_parse(const std::uint8_t* data, std::size_t size);

// A landscape (spatial/) built from a decoded world and configuration, then up to 24 edits
// (carve, fill, fill_empty, replace, relabel with a map of materials 0..4) whose shapes lie on
// cell lines, reuse the landscape's own vertices, are one unit thin, cross themselves
// (InvalidInput), leave the coordinate range (CoordinateOutOfRange) or come from
// kernel/shapes.hpp's builders at every radius up to 2^33 (each must keep its guarantees: valid,
// strictly convex, in range, and refuse exactly the arguments out of range), all in checked
// mode: a rejected edit leaves the state hash unchanged; check() holds at the end;
// material_at, raycast and overlaps(box) agree with a scan of every polygon; save -> load
// keeps the state hash; a snapshot taken along the way is untouched by later edits.
// landscape_decoders.cpp.
std::optional<Finding> run_edit_sequence(const std::uint8_t* data, std::size_t size);

// Arbitrary bytes into Landscape::load (after the first byte: odd asks for the checksum to be
// made right first, so mutations reach the parser; load_fuzzer.cpp also mutates decoded saves
// field by field, save_mutator.hpp): a LoadError or LimitExceeded, or a world that passes
// check() and survives save -> load with its state hash; and the heap the load needed at its
// peak (allocation_meter.hpp) within a small multiple of the file plus twice the world it
// returns (a refused file: 256 bytes per byte of it, what the nodes read before the refusal can
// take). landscape_decoders.cpp.
std::optional<Finding> run_load(const std::uint8_t* data, std::size_t size);

// Valid polygons decoded from bytes (normalized rings on small grids, polyominoes keeping every
// lattice point of their boundary, combs, spirals, zigzags, boxes with vertices on their sides;
// moved by unimodular maps and scales anywhere in range, up to the bound) and raw rings that
// may be invalid, with a piece size N from 3 to 12 or unbounded. For each valid polygon:
// triangulate() (n - 2 counter-clockwise triangles of positive area, exact area sum, disjoint
// interiors, every side an edge or an inside diagonal by brute force or the union equal to the
// polygon by the clipper's xor), convex_pieces() (strictly convex, 3..N vertices of the
// polygon's, exact area, disjoint, union equal to the polygon) and centroid() (the same exact
// point for the polygon, its triangles and its pieces). For an invalid one: both algorithms
// throw InvalidInput with validate()'s first violation. polygon_decoders.cpp.
std::optional<Finding> run_polygon_pieces(const std::uint8_t* data, std::size_t size);

// The game layer (game/, issue 26) over an edit sequence decoded as run_edit_sequence decodes it,
// with a material table (solid and anchored flags of materials 1..4) and the border as a wall or
// not. After every edit: the SurfaceTracker's mirror (its updates applied) equals
// surface_chains(), whose chains keep the chain rules and describe the brute-force surface; the
// meshes of the change set's added polygons are exact triangulations; their convex pieces (at
// most 8 vertices) are strictly convex and exactly the polygon; the IslandTracker's islands equal
// a brute-force union-find over every solid polygon and the update reports exactly the new ones;
// each new island detached from a copy leaves check() ok and its area in the regions. Now and
// then the new islands are detached from the landscape itself and those change sets are checked
// the same way. game_decoders.cpp.
std::optional<Finding> run_game_sequence(const std::uint8_t* data, std::size_t size);

// Arbitrary bytes as a delta (issue 37; after the first byte, whose bit 0 asks for the checksum to
// be made right, bits 1-2 pick the world it is applied to and bits 3-4 turn on the base and result
// checks): decode_delta gives a DeltaError (or a shape's InvalidInput) or a delta whose bytes
// decode to the same bytes again, having held at most a constant times its size; applied in checked
// mode to a fixed world (a CHANGES delta to an empty DrawMirror), it is refused with a typed error
// leaving the world's state hash as it was, or gives a world that passes check() and survives save
// -> load. delta_decoders.cpp.
std::optional<Finding> run_delta(const std::uint8_t* data, std::size_t size);
// Inputs of run_delta built from real deltas of its worlds (regress_replay delta --write-seeds).
std::vector<std::string> delta_seeds();

// Pairs of 128-bit values of every width decoded from bytes, through every operation of the
// portable Int128 (kernel/.../portable_int128.hpp) and of the compiler's __int128: the results
// must agree bit for bit (+ - * / % with wrapping, shifts, comparisons, conversions to double,
// float and narrower integers, from double). int128_decoders.cpp.
std::optional<Finding> run_int128_portable(const std::uint8_t* data, std::size_t size);

// Arbitrary bytes as one message a client sends the server (issue 37, item 5; after the first
// byte, whose bit 0 asks for an EDIT's delta checksum to be made right, bit 1 picks the server's
// world: every region held, or half of them as stubs, and bit 2 grants the client the lower half
// of the world only): decode_message gives a ProtocolError or a message that round-trips,
// having held at most a constant times its size; then handled as the server handles it
// (net/request_checks.hpp): an EDIT refused with a typed reason and the world unchanged, or
// applied in checked mode leaving check() ok; a HASHES or PATCH_REQUEST refused, or answered
// within a bound (a PATCH no bigger than the world, and changing nothing applied to it).
// net_decoders.cpp; built when net/ is (EDGELAND_FUZZ_NET).
std::optional<Finding> run_net_message(const std::uint8_t* data, std::size_t size);
// Inputs of run_net_message: real EDITs, repair requests and other messages.
std::vector<std::string> net_message_seeds();

// The seeds a target writes for its corpus (regress_replay TARGET --write-seeds DIR): delta's and
// net_message's; none for the others.
std::vector<std::string> seeds_for(std::string_view target);

// The logs the inputs of clip_pair (its four operations) and clip_sequence (the steps as
// recorded) decode to, as continuous-clip logs.
std::string clip_pair_log(const std::uint8_t* data, std::size_t size);
std::string clip_sequence_log(const std::uint8_t* data, std::size_t size);

// The landscape edit log an edit_sequence input decodes to (recorded by the landscape itself).
std::string edit_sequence_log(const std::uint8_t* data, std::size_t size);

// The target's run_* function by name ("clip_pair", ...); nullptr for an unknown name.
using Runner = std::optional<Finding> (*)(const std::uint8_t*, std::size_t);
Runner runner_for(std::string_view target);

// The continuous-clip log an input of clip_pair or clip_sequence decodes to (what the
// campaign saves under tests/regress/logs/); empty for other targets.
std::string input_as_log(std::string_view target, const std::uint8_t* data, std::size_t size);

}  // namespace edgeland::fuzz
