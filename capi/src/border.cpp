#include "border.hpp"

#include <cstdint>
#include <exception>
#include <limits>
#include <new>

#include "edgeland/clip/errors.hpp"
#include "edgeland/game/islands.hpp"
#include "edgeland/kernel/errors.hpp"
#include "edgeland/spatial/errors.hpp"

namespace edgeland::capi {
namespace {

// The C codes mirror the C++ enumerations value for value: a reordering there must fail here.
static_assert(EL_RULE_TOO_FEW_VERTICES == static_cast<int>(Rule::kTooFewVertices) &&
              EL_RULE_COORDINATE_OUT_OF_RANGE == static_cast<int>(Rule::kCoordinateOutOfRange) &&
              EL_RULE_REPEATED_VERTEX == static_cast<int>(Rule::kRepeatedVertex) &&
              EL_RULE_SELF_INTERSECTION == static_cast<int>(Rule::kSelfIntersection) &&
              EL_RULE_SPIKE == static_cast<int>(Rule::kSpike) &&
              EL_RULE_NOT_COUNTER_CLOCKWISE == static_cast<int>(Rule::kNotCounterClockwise) &&
              EL_RULE_OVERLAPPING_INTERIORS == static_cast<int>(Rule::kOverlappingInteriors) &&
              EL_RULE_INVERTED_BOX == static_cast<int>(Rule::kInvertedBox));
using Setting = InvalidConfig::Setting;
static_assert(EL_SETTING_WORLD_OUT_OF_RANGE == static_cast<int>(Setting::kWorldOutOfRange) &&
              EL_SETTING_WORLD_EMPTY == static_cast<int>(Setting::kWorldEmpty) &&
              EL_SETTING_EDGE_CAP == static_cast<int>(Setting::kEdgeCap) &&
              EL_SETTING_MERGE_BELOW == static_cast<int>(Setting::kMergeBelow) &&
              EL_SETTING_MIN_CELL_SIZE == static_cast<int>(Setting::kMinCellSize) &&
              EL_SETTING_GRID_DEPTH == static_cast<int>(Setting::kGridDepth) &&
              EL_SETTING_TREE == static_cast<int>(Setting::kTree) &&
              EL_SETTING_GRID_DEPTH_BEYOND_CELLS ==
                  static_cast<int>(Setting::kGridDepthBeyondCells));
using Limit = LimitExceeded::Limit;
static_assert(EL_LIMIT_VERTICES == static_cast<int>(Limit::kVertices) &&
              EL_LIMIT_SHAPE_VERTICES == static_cast<int>(Limit::kShapeVertices) &&
              EL_LIMIT_CELLS == static_cast<int>(Limit::kCells) &&
              EL_LIMIT_POLYGON_IDS == static_cast<int>(Limit::kPolygonIds));
static_assert(EL_OPERAND_SUBJECT == static_cast<int>(Operand::kSubject) &&
              EL_OPERAND_CLIP == static_cast<int>(Operand::kClip) &&
              EL_OPERAND_RINGS == static_cast<int>(Operand::kRings) &&
              EL_OPERAND_QUERY == static_cast<int>(Operand::kQuery) &&
              EL_OPERAND_POLYGON == static_cast<int>(Operand::kPolygon) &&
              EL_OPERAND_SHAPE == static_cast<int>(Operand::kShape));

std::uint64_t index_of(std::size_t i) { return i == kNone ? EL_NONE : std::uint64_t{i}; }

std::int64_t saturated(std::size_t n) {
  constexpr auto kMax = static_cast<std::size_t>(std::numeric_limits<std::int64_t>::max());
  return static_cast<std::int64_t>(n < kMax ? n : kMax);
}

// An el_error of a status, its message, and no fields yet.
el_error base(el_status status, const char* what) {
  el_error e{};
  e.status = status;
  e.index = EL_NONE;
  e.vertex = EL_NONE;
  std::strncpy(e.message, what, sizeof e.message - 1);
  return e;
}

el_error input_error(el_status status, const InvalidInput& x) {
  el_error e = base(status, x.what());
  e.kind = static_cast<std::uint32_t>(x.violation.rule);
  e.operand = static_cast<std::uint32_t>(x.operand);
  e.index = index_of(x.violation.polygon);
  e.vertex = index_of(x.violation.edge);
  e.where = {x.violation.where.x, x.violation.where.y};
  return e;
}

el_error count_error(el_status status, const char* what, std::uint32_t kind, std::size_t maximum,
                     std::size_t requested) {
  el_error e = base(status, what);
  e.kind = kind;
  e.limit = saturated(maximum);
  e.value = saturated(requested);
  return e;
}

// The landscape's errors of deltas, tree paths, regions and polygon names, from the handler of
// describe_current() (the exception being handled); any other LandscapeError left there is
// LandscapeInternalError, a bug.
el_error describe_tree_error() {
  try {
    throw;
  } catch (const DeltaError& x) {
    el_error e = base(EL_DELTA_ERROR, x.what());
    e.index = x.offset;
    return e;
  } catch (const DeltaMismatch& x) {
    el_error e = base(EL_DELTA_MISMATCH, x.what());
    e.kind = static_cast<std::uint32_t>(x.field);
    return e;
  } catch (const InvalidPath& x) {
    el_error e = base(EL_INVALID_PATH, x.what());
    e.index = x.path.size();
    return e;
  } catch (const RegionNotLoaded& x) {
    el_error e = base(EL_REGION_NOT_LOADED, x.what());
    e.index = x.path.size();
    return e;
  } catch (const UnknownPolygon& x) {
    el_error e = base(EL_UNKNOWN_POLYGON, x.what());
    e.index = x.id;
    return e;
  } catch (const LandscapeError& x) {
    return base(EL_INTERNAL, x.what());
  }
}

// The innermost handler: the exception as an el_error, most derived classes first.
el_error describe_current() {
  try {
    throw;
  } catch (const BorderError& x) {
    el_error e = base(x.status, x.what());
    e.index = x.index;
    return e;
  } catch (const std::bad_alloc& x) {
    return base(EL_OUT_OF_MEMORY, x.what());
  } catch (const CoordinateOutOfRange& x) {
    el_error e = input_error(EL_COORDINATE_OUT_OF_RANGE, x);
    e.index = x.polygon;
    e.vertex = index_of(x.vertex);
    e.where = {x.where.x, x.where.y};
    return e;
  } catch (const InvalidBox& x) {
    el_error e = input_error(EL_INVALID_BOX, x);
    e.where = {x.box.min.x, x.box.min.y};
    return e;
  } catch (const InvalidInput& x) {
    return input_error(EL_INVALID_INPUT, x);
  } catch (const TooManyVertices& x) {
    return count_error(EL_TOO_MANY_VERTICES, x.what(), 0, x.maximum, x.requested);
  } catch (const InvalidArgument& x) {
    el_error e = base(EL_INVALID_ARGUMENT, x.what());
    e.value = saturated(x.value);
    e.minimum = saturated(x.minimum);
    return e;
  } catch (const ArgumentOutOfRange& x) {
    el_error e = base(EL_ARGUMENT_OUT_OF_RANGE, x.what());
    e.value = x.value;
    e.minimum = x.minimum;
    e.limit = x.maximum;
    return e;
  } catch (const NonPositiveArea& x) {
    el_error e = base(EL_NON_POSITIVE_AREA, x.what());
    e.value = static_cast<std::int64_t>(x.twice_area);
    return e;
  } catch (const InvalidOverlay& x) {
    el_error e = base(EL_INVALID_OVERLAY, x.what());
    e.kind = static_cast<std::uint32_t>(x.reason);
    e.index = x.index;
    return e;
  } catch (const InvalidConfig& x) {
    el_error e = base(EL_INVALID_CONFIG, x.what());
    e.kind = static_cast<std::uint32_t>(x.setting);
    return e;
  } catch (const InvalidMaterial& x) {
    el_error e = base(EL_INVALID_MATERIAL, x.what());
    e.value = x.number;
    e.minimum = 0;
    e.limit = 255;
    return e;
  } catch (const LimitExceeded& x) {
    return count_error(EL_LIMIT_EXCEEDED, x.what(), static_cast<std::uint32_t>(x.limit), x.maximum,
                       x.requested);
  } catch (const LoadError& x) {
    el_error e = base(EL_LOAD_ERROR, x.what());
    e.index = x.offset;
    return e;
  } catch (const StaleIsland& x) {
    el_error e = base(EL_STALE_ISLAND, x.what());
    e.index = x.polygon;
    return e;
  } catch (const LandscapeError&) {
    return describe_tree_error();
  } catch (const std::exception& x) {  // InternalError: a bug
    return base(EL_INTERNAL, x.what());
  } catch (...) {
    return base(EL_INTERNAL, "an exception of unknown type");
  }
}

}  // namespace

el_status translate_current_exception(el_error* error) noexcept {
  try {
    const el_error e = describe_current();
    if (error != nullptr) write_sized(error, e);
    return e.status;
  } catch (...) {  // only a bad_alloc building a message can get here
    return EL_OUT_OF_MEMORY;
  }
}

}  // namespace edgeland::capi

extern "C" {

EL_API void el_error_init(el_error* error) {
  if (error == nullptr) return;
  *error = el_error{};
  error->struct_size = sizeof(el_error);
  error->index = EL_NONE;
  error->vertex = EL_NONE;
}

EL_API const char* el_status_name(el_status status) {
  switch (status) {
    case EL_OK:
      return "EL_OK";
    case EL_NULL_ARGUMENT:
      return "EL_NULL_ARGUMENT";
    case EL_OUT_OF_MEMORY:
      return "EL_OUT_OF_MEMORY";
    case EL_VERSION_MISMATCH:
      return "EL_VERSION_MISMATCH";
    case EL_INTERNAL:
      return "EL_INTERNAL";
    case EL_INVALID_INPUT:
      return "EL_INVALID_INPUT";
    case EL_COORDINATE_OUT_OF_RANGE:
      return "EL_COORDINATE_OUT_OF_RANGE";
    case EL_INVALID_BOX:
      return "EL_INVALID_BOX";
    case EL_TOO_MANY_VERTICES:
      return "EL_TOO_MANY_VERTICES";
    case EL_INVALID_ARGUMENT:
      return "EL_INVALID_ARGUMENT";
    case EL_ARGUMENT_OUT_OF_RANGE:
      return "EL_ARGUMENT_OUT_OF_RANGE";
    case EL_NON_POSITIVE_AREA:
      return "EL_NON_POSITIVE_AREA";
    case EL_INVALID_OVERLAY:
      return "EL_INVALID_OVERLAY";
    case EL_INVALID_CONFIG:
      return "EL_INVALID_CONFIG";
    case EL_INVALID_MATERIAL:
      return "EL_INVALID_MATERIAL";
    case EL_LIMIT_EXCEEDED:
      return "EL_LIMIT_EXCEEDED";
    case EL_LOAD_ERROR:
      return "EL_LOAD_ERROR";
    case EL_DELTA_ERROR:
      return "EL_DELTA_ERROR";
    case EL_DELTA_MISMATCH:
      return "EL_DELTA_MISMATCH";
    case EL_INVALID_PATH:
      return "EL_INVALID_PATH";
    case EL_REGION_NOT_LOADED:
      return "EL_REGION_NOT_LOADED";
    case EL_UNKNOWN_POLYGON:
      return "EL_UNKNOWN_POLYGON";
    case EL_STALE_ISLAND:
      return "EL_STALE_ISLAND";
    case EL_INDEX_OUT_OF_RANGE:
      return "EL_INDEX_OUT_OF_RANGE";
    case EL_BUFFER_TOO_SMALL:
      return "EL_BUFFER_TOO_SMALL";
    default:
      return "EL_UNKNOWN";
  }
}

EL_API uint32_t el_version(void) { return EL_VERSION; }

EL_API int32_t el_check_version(uint32_t header_version) {
  const bool same_major = (header_version >> 16) == EL_VERSION_MAJOR;
  const bool minor_known = ((header_version >> 8) & 0xffu) <= EL_VERSION_MINOR;
  return same_major && minor_known ? EL_OK : EL_VERSION_MISMATCH;
}

}  // extern "C"
