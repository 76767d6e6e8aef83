// The messages (protocol.hpp): written with the core's byte codec, read back with its bounded
// reader.
#include "edgeland/net/protocol.hpp"

#include "edgeland/spatial/byte_codec.hpp"

namespace edgeland::net {
namespace {

enum class Type : std::uint8_t {
  kHello = 1,
  kEdit = 2,
  kHashes = 3,
  kPatchRequest = 4,
  kWelcome = 10,
  kCommand = 11,
  kChanges = 12,
  kCheckpoint = 13,
  kReject = 14,
  kDigests = 15,
  kPatch = 16,
};

constexpr std::size_t kMaxPath = 64;

// --- writing -----------------------------------------------------------------------------------
struct Writer {
  ByteWriter w;
  void u8(std::uint8_t v) { w.u8(v); }
  void u32(std::uint64_t v) { w.fixed(v, 4); }
  void u64(std::uint64_t v) { w.fixed(v, 8); }
  void i64(std::int64_t v) { w.fixed(static_cast<std::uint64_t>(v), 8); }
  void bytes(std::string_view b) {
    u32(b.size());
    w.raw(b);
  }
  void box(const Box64& b) {
    for (const std::int64_t v : {b.min.x, b.min.y, b.max.x, b.max.y}) i64(v);
  }
  void path(const TreePath& p) {
    u8(static_cast<std::uint8_t>(p.size()));
    for (const std::uint8_t i : p) u8(i);
  }
  void paths(const std::vector<TreePath>& ps) {
    u32(ps.size());
    for (const TreePath& p : ps) path(p);
  }
  void config(const LandscapeConfig& c) {
    u8(static_cast<std::uint8_t>(c.tree));
    u32(c.edge_cap);
    u32(c.merge_below);
    i64(c.min_cell_size);
    i64(c.grid_depth);
    i64(c.region_depth);
    u8(c.region_ids ? 1 : 0);
  }
  void digest(const std::optional<NodeDigest>& d) {
    u8(d ? 1 : 0);
    if (!d) return;
    u64(d->hash);
    u8(static_cast<std::uint8_t>((d->cell ? 1 : 0) | (d->loaded ? 2 : 0)));
    u8(static_cast<std::uint8_t>(d->children.size()));
    for (const std::uint64_t h : d->children) u64(h);
  }

  void body(const Hello& m) {
    u8(static_cast<std::uint8_t>(Type::kHello));
    u32(m.version);
    u8(static_cast<std::uint8_t>(m.role));
    u8(m.watch_all ? 1 : 0);
    u32(m.regions.size());
    for (const std::uint32_t r : m.regions) u32(r);
    box(m.edit_box);
  }
  void body(const EditRequest& m) {
    u8(static_cast<std::uint8_t>(Type::kEdit));
    u32(m.number);
    bytes(m.delta);
  }
  void body(const HashesRequest& m) {
    u8(static_cast<std::uint8_t>(Type::kHashes));
    u32(m.request);
    paths(m.paths);
  }
  void body(const PatchRequest& m) {
    u8(static_cast<std::uint8_t>(Type::kPatchRequest));
    u32(m.request);
    paths(m.paths);
  }
  void body(const Welcome& m) {
    u8(static_cast<std::uint8_t>(Type::kWelcome));
    u32(m.client);
    box(m.world);
    config(m.config);
    u64(m.next_id);
    u64(m.sequence);
    box(m.granted);
    u32(m.regions.size());
    for (const RegionPart& r : m.regions) {
      u8(r.record ? 1 : 0);
      bytes(r.bytes);
    }
    bytes(m.changes);
  }
  void body(const Command& m) {
    u8(static_cast<std::uint8_t>(Type::kCommand));
    u32(m.origin);
    u32(m.number);
    bytes(m.delta);
  }
  void body(const Changes& m) {
    u8(static_cast<std::uint8_t>(Type::kChanges));
    bytes(m.delta);
  }
  void body(const Checkpoint& m) {
    u8(static_cast<std::uint8_t>(Type::kCheckpoint));
    u64(m.sequence);
    u64(m.hash);
    u32(m.regions.size());
    for (const auto& [index, hash] : m.regions) {
      u32(index);
      u64(hash);
    }
  }
  void body(const Reject& m) {
    u8(static_cast<std::uint8_t>(Type::kReject));
    u32(m.number);
    u8(static_cast<std::uint8_t>(m.reason));
    bytes(m.message);
  }
  void body(const Digests& m) {
    u8(static_cast<std::uint8_t>(Type::kDigests));
    u32(m.request);
    u32(m.digests.size());
    for (const std::optional<NodeDigest>& d : m.digests) digest(d);
  }
  void body(const PatchReply& m) {
    u8(static_cast<std::uint8_t>(Type::kPatch));
    u32(m.request);
    bytes(m.delta);
  }
};

// --- reading -----------------------------------------------------------------------------------
struct Reader {
  explicit Reader(std::string_view b) : in(b, 0, b.size()) {}
  ByteReader in;

  std::uint8_t u8() { return static_cast<std::uint8_t>(in.fixed(1)); }
  std::uint32_t u32() { return static_cast<std::uint32_t>(in.fixed(4)); }
  std::uint64_t u64() { return in.fixed(8); }
  std::int64_t i64() { return static_cast<std::int64_t>(in.fixed(8)); }
  // A count of items of at least `min_bytes` each, bounded by the bytes left.
  std::size_t count(std::size_t min_bytes) {
    const std::uint32_t n = u32();
    if (n > in.left() / min_bytes) in.fail("count larger than the message");
    return n;
  }
  std::string bytes() { return std::string(in.take(count(1))); }
  bool flag() {
    const std::uint8_t v = u8();
    if (v > 1) in.fail("a flag neither 0 nor 1");
    return v == 1;
  }
  Box64 box() {
    Box64 b;
    b.min.x = i64();
    b.min.y = i64();
    b.max.x = i64();
    b.max.y = i64();
    return b;
  }
  TreePath path() {
    const std::size_t n = u8();
    if (n > kMaxPath) in.fail("path longer than the deepest tree");
    TreePath p(n);
    for (std::uint8_t& i : p) {
      i = u8();
      if (i > 3) in.fail("path index above 3");
    }
    return p;
  }
  std::vector<TreePath> paths() {
    std::vector<TreePath> ps(count(1));
    for (TreePath& p : ps) p = path();
    return ps;
  }
  LandscapeConfig config() {
    LandscapeConfig c;
    const std::uint8_t tree = u8();
    if (tree > 1) in.fail("unknown tree kind");
    c.tree = static_cast<TreeKind>(tree);
    c.edge_cap = u32();
    c.merge_below = u32();
    c.min_cell_size = i64();
    c.grid_depth = small_int();
    c.region_depth = small_int();
    c.region_ids = flag();
    return c;
  }
  int small_int() {
    const std::int64_t v = i64();
    if (v < -1 || v > 64) in.fail("a depth outside -1..64");
    return static_cast<int>(v);
  }
  std::optional<NodeDigest> digest() {
    if (!flag()) return std::nullopt;
    NodeDigest d;
    d.hash = u64();
    const std::uint8_t flags = u8();
    if (flags > 3) in.fail("unknown digest flags");
    d.cell = (flags & 1) != 0;
    d.loaded = (flags & 2) != 0;
    const std::size_t children = u8();
    if (children > 4) in.fail("more than four children");
    for (std::size_t i = 0; i < children; ++i) d.children.push_back(u64());
    return d;
  }

  Message message() {
    const auto type = static_cast<Type>(u8());
    switch (type) {
      case Type::kHello:
        return hello();
      case Type::kEdit: {
        EditRequest m;
        m.number = u32();
        m.delta = bytes();
        return m;
      }
      case Type::kHashes: {
        HashesRequest m;
        m.request = u32();
        m.paths = paths();
        return m;
      }
      case Type::kPatchRequest: {
        PatchRequest m;
        m.request = u32();
        m.paths = paths();
        return m;
      }
      case Type::kWelcome:
        return welcome();
      case Type::kCommand: {
        Command m;
        m.origin = u32();
        m.number = u32();
        m.delta = bytes();
        return m;
      }
      case Type::kChanges:
        return Changes{bytes()};
      case Type::kCheckpoint:
        return checkpoint();
      case Type::kReject:
        return reject();
      case Type::kDigests: {
        Digests m;
        m.request = u32();
        m.digests.resize(count(1));
        for (std::optional<NodeDigest>& d : m.digests) d = digest();
        return m;
      }
      case Type::kPatch: {
        PatchReply m;
        m.request = u32();
        m.delta = bytes();
        return m;
      }
    }
    in.seek(0);
    in.fail("unknown message type");
  }

  Hello hello() {
    Hello m;
    m.version = u32();
    const std::uint8_t role = u8();
    if (role > 1) in.fail("unknown role");
    m.role = static_cast<Role>(role);
    m.watch_all = flag();
    m.regions.resize(count(4));
    for (std::uint32_t& r : m.regions) r = u32();
    m.edit_box = box();
    return m;
  }

  Welcome welcome() {
    Welcome m;
    m.client = u32();
    m.world = box();
    m.config = config();
    m.next_id = u64();
    m.sequence = u64();
    m.granted = box();
    m.regions.resize(count(5));
    for (RegionPart& r : m.regions) {
      r.record = flag();
      r.bytes = bytes();
    }
    m.changes = bytes();
    return m;
  }

  Checkpoint checkpoint() {
    Checkpoint m;
    m.sequence = u64();
    m.hash = u64();
    m.regions.resize(count(12));
    for (auto& [index, hash] : m.regions) {
      index = u32();
      hash = u64();
    }
    return m;
  }

  Reject reject() {
    Reject m;
    m.number = u32();
    const std::uint8_t reason = u8();
    if (reason < 1 || reason > 8) in.fail("unknown reject reason");
    m.reason = static_cast<RejectReason>(reason);
    m.message = bytes();
    return m;
  }
};

}  // namespace

ProtocolError::ProtocolError(const std::string& what, std::size_t at)
    : Error("bad message at byte " + std::to_string(at) + ": " + what), offset(at) {}

const char* reason_name(RejectReason reason) noexcept {
  switch (reason) {
    case RejectReason::kMalformed:
      return "malformed";
    case RejectReason::kOutOfRange:
      return "out_of_range";
    case RejectReason::kInvalidShape:
      return "invalid_shape";
    case RejectReason::kNotPermitted:
      return "not_permitted";
    case RejectReason::kTooLarge:
      return "too_large";
    case RejectReason::kRate:
      return "rate";
    case RejectReason::kOtherWorld:
      return "other_world";
    case RejectReason::kLimit:
      return "limit";
  }
  return "unknown";
}

std::string encode_message(const Message& message) {
  Writer w;
  std::visit([&](const auto& m) { w.body(m); }, message);
  return std::move(w.w.bytes());
}

Message decode_message(std::string_view bytes) {
  try {
    Reader r(bytes);
    Message m = r.message();
    if (!r.in.done()) r.in.fail("bytes left after the message");
    return m;
  } catch (const ReadFailure& failure) {
    throw ProtocolError(failure.what, failure.offset);
  }
}

}  // namespace edgeland::net
