// encode_delta and decode_delta (delta.hpp): the envelope of delta_format.hpp around the kind's
// payload. The reader bounds every count by the bytes left before allocating for it.
#include <string>

#include "delta_format.hpp"
#include "edgeland/spatial/byte_codec.hpp"
#include "edgeland/spatial/delta.hpp"
#include "edit_form.hpp"
#include "save_format.hpp"

namespace edgeland {
namespace {

namespace format = detail::delta_format;
using Kind = Edit::Kind;

// --- writing -----------------------------------------------------------------------------------
void write_ring(ByteWriter& w, const Polygon& ring) {
  w.varint(ring.size());
  Point64 prev{0, 0};
  for (Point64 p : ring) {
    w.zigzag(p.x - prev.x);
    w.zigzag(p.y - prev.y);
    prev = p;
  }
}

// The (from, to) pairs the map changes, from ascending.
void write_map(ByteWriter& w, const MaterialMap& map) {
  std::vector<std::uint8_t> changed;
  for (std::size_t m = 0; m < kMaterialCount; ++m)
    if (map[static_cast<std::uint8_t>(m)] != Material(m))
      changed.push_back(static_cast<std::uint8_t>(m));
  w.varint(changed.size());
  for (std::uint8_t m : changed) {
    w.u8(m);
    w.u8(map[m].value());
  }
}

// The kind and its materials (a map of another form than its kind's is sent as a relabel: the
// map is what an Edit does), then the shape.
void write_edit(ByteWriter& w, const Edit& e) {
  const Kind kind = detail::has_its_form(e) ? e.kind : Kind::kRelabel;
  w.u8(static_cast<std::uint8_t>(kind));
  if (kind == Kind::kFill || kind == Kind::kFillEmpty) w.u8(e.map[kEmpty].value());
  if (kind == Kind::kReplace) {
    const auto [from, to] = detail::replaced(e.map);
    w.u8(from.value());
    w.u8(to.value());
  }
  if (kind == Kind::kRelabel) write_map(w, e.map);
  w.varint(e.shape.polygons().size());
  for (const Polygon& p : e.shape.polygons()) write_ring(w, p);
}

void write_patch(ByteWriter& w, const Delta& d) {
  w.fixed(d.next_id, 8);
  w.varint(d.patches.size());
  for (const PatchEntry& e : d.patches) {
    w.varint(e.path.size());
    for (std::uint8_t i : e.path) w.u8(i);
    w.fixed(e.hash, 8);
    w.varint(e.region_next);
    w.varint(e.subtree.size());
    w.raw(e.subtree);
  }
}

// Ascending ids as gaps from the previous one (the first from 0).
void write_changes(ByteWriter& w, const Delta& d) {
  w.varint(d.removed.size());
  PolygonId prev = 0;
  for (PolygonId id : d.removed) {
    w.varint(id - prev);
    prev = id;
  }
  w.varint(d.added.size());
  prev = 0;
  for (const DrawnPolygon& a : d.added) {
    w.varint(a.id - prev);
    prev = a.id;
    w.u8(a.material.value());
    write_ring(w, a.polygon);
  }
}

void write_payload(ByteWriter& w, const Delta& d) {
  switch (d.header.kind) {
    case DeltaKind::kCommand:
      w.u8(d.edits.size() == 1 ? format::kSingleEdit : format::kBatch);
      w.varint(d.edits.size());
      for (const Edit& e : d.edits) write_edit(w, e);
      return;
    case DeltaKind::kPatch:
      write_patch(w, d);
      return;
    case DeltaKind::kChanges:
      write_changes(w, d);
      return;
  }
}

// --- reading -----------------------------------------------------------------------------------
class DeltaReader {
 public:
  explicit DeltaReader(std::string_view bytes) : bytes_(bytes), in_(bytes, 0, bytes.size()) {}

  Delta read() {
    check_envelope();
    Delta d;
    read_header(d.header);
    read_payload(d);
    if (!in_.done()) in_.fail("bytes left after the payload");
    return d;
  }

 private:
  void check_envelope() {
    if (bytes_.size() < format::kHeaderBytes + format::kChecksumBytes)
      in_.fail("too short for a delta");
    if (bytes_.substr(0, sizeof format::kMagic) !=
        std::string_view(format::kMagic, sizeof format::kMagic))
      in_.fail("not a delta");
    const std::size_t end = bytes_.size() - format::kChecksumBytes;
    ByteReader tail(bytes_, end, bytes_.size());
    const std::uint64_t checksum = tail.fixed(format::kChecksumBytes);
    in_ = ByteReader(bytes_, sizeof format::kMagic, end);
    if (checksum != detail::save_format::fnv1a64(bytes_.substr(0, end)))
      in_.fail("checksum mismatch: the delta is corrupt");
    if (const auto v = in_.fixed(4); v != format::kVersion)
      in_.fail("unsupported delta format version " + std::to_string(v));
  }

  void read_header(DeltaHeader& h) {
    const auto kind = in_.fixed(1);
    if (kind < 1 || kind > 3) in_.fail("unknown delta kind " + std::to_string(kind));
    h.kind = static_cast<DeltaKind>(kind);
    h.algorithm = static_cast<std::uint32_t>(in_.fixed(4));
    h.world = in_.fixed(8);
    h.sequence = in_.fixed(8);
    h.base = in_.fixed(8);
    h.result = in_.fixed(8);
  }

  void read_payload(Delta& d) {
    switch (d.header.kind) {
      case DeltaKind::kCommand:
        return read_command(d);
      case DeltaKind::kPatch:
        return read_patch(d);
      case DeltaKind::kChanges:
        return read_changes(d);
    }
  }

  // One edit, or a batch of two or more (a batch of one is that edit: it is sent as one).
  void read_command(Delta& d) {
    const auto form = in_.fixed(1);
    if (form != format::kSingleEdit && form != format::kBatch) in_.fail("unknown command form");
    const std::size_t n = in_.count(format::kMinEditBytes);
    if (form == format::kSingleEdit && n != 1)
      in_.fail("a single-edit command holds " + std::to_string(n) + " edits");
    if (form == format::kBatch && n < 2)
      in_.fail("a batch command holds " + std::to_string(n) + " edits (two or more)");
    d.edits.reserve(n);
    for (std::size_t i = 0; i < n; ++i) d.edits.push_back(read_edit());
  }

  Edit read_edit() {
    const auto number = in_.fixed(1);
    if (number > static_cast<std::uint64_t>(Kind::kRelabel))
      in_.fail("unknown edit kind " + std::to_string(number));
    const auto kind = static_cast<Kind>(number);
    MaterialMap map;
    if (kind == Kind::kCarve) map = MaterialMap::uniform(kEmpty);
    if (kind == Kind::kFill) map = MaterialMap::uniform(static_cast<std::uint8_t>(in_.fixed(1)));
    if (kind == Kind::kFillEmpty) map.set(kEmpty, static_cast<std::uint8_t>(in_.fixed(1)));
    if (kind == Kind::kReplace) {
      const auto from = static_cast<std::uint8_t>(in_.fixed(1));
      map.set(from, static_cast<std::uint8_t>(in_.fixed(1)));
    }
    if (kind == Kind::kRelabel) map = read_map();
    PolygonSet shape(in_.count(format::kMinPolygonBytes));
    for (Polygon& p : shape) p = read_shape_ring();
    return Edit{kind, edit_shape(std::move(shape)), map};  // validated as an edit validates it
  }

  MaterialMap read_map() {
    MaterialMap map;
    const std::size_t n = in_.count(2);
    int prev = -1;
    for (std::size_t i = 0; i < n; ++i) {
      const auto from = static_cast<int>(in_.fixed(1));
      const auto to = static_cast<std::uint8_t>(in_.fixed(1));
      if (from <= prev) in_.fail("relabel pairs not in ascending order");
      if (to == from) in_.fail("a relabel pair that changes nothing");
      map.set(static_cast<std::uint8_t>(from), to);
      prev = from;
    }
    return map;
  }

  // A shape's ring: any integers whose magnitude stays below 2^62 (the edit checks the bound).
  Polygon read_shape_ring() {
    Polygon ring(in_.count(format::kMinVertexBytes));
    Point64 prev{0, 0};
    for (Point64& p : ring) {
      p = {add(prev.x, in_.zigzag()), add(prev.y, in_.zigzag())};
      prev = p;
    }
    return ring;
  }

  std::int64_t add(std::int64_t a, std::int64_t delta) {
    constexpr std::int64_t kMax = format::kMaxShapeCoordinate;
    if (delta <= -kMax || delta >= kMax) in_.fail("coordinate beyond 2^62");
    const std::int64_t sum = a + delta;  // both below 2^62 in magnitude: no overflow
    if (sum <= -kMax || sum >= kMax) in_.fail("coordinate beyond 2^62");
    return sum;
  }

  // A polygon of the landscape: coordinates within the bound.
  Polygon read_ring() {
    Polygon ring(in_.count(format::kMinVertexBytes));
    Point64 prev{0, 0};
    for (Point64& p : ring) {
      p = {add(prev.x, in_.zigzag()), add(prev.y, in_.zigzag())};
      if (!in_range(p)) in_.fail("coordinate beyond the bound");
      prev = p;
    }
    return ring;
  }

  void read_patch(Delta& d) {
    d.next_id = in_.fixed(8);
    if (d.next_id == 0) in_.fail("next id 0: ids start at 1");
    d.patches.resize(in_.count(format::kMinEntryBytes));
    for (PatchEntry& e : d.patches) read_entry(e);
  }

  void read_entry(PatchEntry& e) {
    const std::size_t length = in_.count(1);
    if (length > format::kMaxPathLength) in_.fail("path longer than the deepest tree");
    e.path.resize(length);
    for (std::uint8_t& i : e.path) {
      i = static_cast<std::uint8_t>(in_.fixed(1));
      if (i > 3) in_.fail("path index above 3");
    }
    e.hash = in_.fixed(8);
    e.region_next = in_.varint();
    const std::size_t size = in_.count(1);
    e.subtree = std::string(in_.take(size));
  }

  void read_changes(Delta& d) {
    d.removed.resize(in_.count(1));
    PolygonId prev = 0;
    for (PolygonId& id : d.removed) id = next_id(prev);
    d.added.resize(in_.count(format::kMinAddedBytes));
    prev = 0;
    for (DrawnPolygon& a : d.added) {
      a.id = next_id(prev);
      a.material = static_cast<std::uint8_t>(in_.fixed(1));
      if (!a.material.solid()) in_.fail("an added polygon of material 0");
      a.polygon = read_ring();
    }
  }

  // The next of ascending ids, from its gap: at least 1, no wrap.
  PolygonId next_id(PolygonId& prev) {
    const std::uint64_t gap = in_.varint();
    if (gap == 0) in_.fail("ids not ascending");
    if (gap > ~prev) in_.fail("id beyond 2^64 - 1");
    prev += gap;
    return prev;
  }

  std::string_view bytes_;
  ByteReader in_;
};

}  // namespace

std::string encode_delta(const Delta& d) {
  ByteWriter w;
  for (char c : format::kMagic) w.u8(static_cast<std::uint8_t>(c));
  w.fixed(format::kVersion, 4);
  w.u8(static_cast<std::uint8_t>(d.header.kind));
  w.fixed(d.header.algorithm, 4);
  for (std::uint64_t v : {d.header.world, d.header.sequence, d.header.base, d.header.result})
    w.fixed(v, 8);
  write_payload(w, d);
  w.fixed(detail::save_format::fnv1a64(w.bytes()), 8);
  return std::move(w.bytes());
}

Delta decode_delta(std::string_view bytes) {
  try {
    return DeltaReader(bytes).read();
  } catch (const ReadFailure& failure) {
    throw DeltaError(failure.what, failure.offset);
  }
}

}  // namespace edgeland
