#pragma once
// The messages between `edgeland serve` and its clients (net/README.md, "Messages"): one message
// per ENet packet, the first byte its type. Deltas travel as the core's delta bytes inside them;
// everything else is plain little-endian fields. decode_message reads untrusted bytes: every
// length is bounded by the bytes left, and anything else is a ProtocolError naming the byte.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "edgeland/kernel/errors.hpp"
#include "edgeland/kernel/export.hpp"
#include "edgeland/spatial/types.hpp"

namespace edgeland::net {

inline constexpr std::uint32_t kProtocolVersion = 1;

// Bytes that are no message: `offset` is where reading stopped.
class EDGELAND_EXPORT ProtocolError : public Error {
 public:
  ProtocolError(const std::string& what, std::size_t offset);
  std::size_t offset;
};

enum class Role : std::uint8_t { kFull = 0, kThin = 1 };

enum class RejectReason : std::uint8_t {
  kMalformed = 1,     // the message or its delta does not decode (ProtocolError, DeltaError)
  kOutOfRange = 2,    // CoordinateOutOfRange
  kInvalidShape = 3,  // InvalidInput
  kNotPermitted = 4,  // the shape's box leaves the box granted to the client
  kTooLarge = 5,      // the message or the shape over the limits
  kRate = 6,          // over the client's edits per second
  kOtherWorld = 7,    // DeltaMismatch: another world or algorithm version
  kLimit = 8,         // the world would pass its LandscapeLimits
};
EDGELAND_EXPORT const char* reason_name(RejectReason reason) noexcept;

// Client -> server.
struct Hello {
  std::uint32_t version = kProtocolVersion;
  Role role = Role::kFull;
  bool watch_all = true;
  std::vector<std::uint32_t> regions;  // watched region indices when not watch_all
  Box64 edit_box{{1, 1}, {0, 0}};      // where it asks to edit; an inverted box: nowhere
};
struct EditRequest {
  std::uint32_t number = 0;
  std::string delta;  // a COMMAND delta
};
struct HashesRequest {
  std::uint32_t request = 0;
  std::vector<TreePath> paths;
};
struct PatchRequest {
  std::uint32_t request = 0;
  std::vector<TreePath> paths;
};

// Server -> client.
struct RegionPart {
  bool record = false;  // a region record (watched), else a summary record (a stub)
  std::string bytes;
};
struct Welcome {
  std::uint32_t client = 0;
  Box64 world;
  LandscapeConfig config;
  PolygonId next_id = 1;
  std::uint64_t sequence = 0;  // the snapshot's
  Box64 granted{{1, 1}, {0, 0}};
  std::vector<RegionPart> regions;  // full clients: one per region of the world, in tree order
  std::string changes;              // thin clients: a CHANGES delta of every polygon watched
};
struct Command {
  std::uint32_t origin = 0;  // the client that asked for it (0: the server)
  std::uint32_t number = 0;  // its edit number
  std::string delta;
};
struct Changes {
  std::string delta;
};
struct Checkpoint {
  std::uint64_t sequence = 0;
  std::uint64_t hash = 0;                                        // the state hash
  std::vector<std::pair<std::uint32_t, std::uint64_t>> regions;  // index, hash (or digest)
};
struct Reject {
  std::uint32_t number = 0;
  RejectReason reason = RejectReason::kMalformed;
  std::string message;
};
struct Digests {
  std::uint32_t request = 0;
  std::vector<std::optional<NodeDigest>> digests;  // boxes are not sent (the client knows them)
};
struct PatchReply {
  std::uint32_t request = 0;
  std::string delta;
};

using Message = std::variant<Hello, EditRequest, HashesRequest, PatchRequest, Welcome, Command,
                             Changes, Checkpoint, Reject, Digests, PatchReply>;

EDGELAND_EXPORT std::string encode_message(const Message& message);
// Throws ProtocolError. A decoded message holds at most a constant times its size.
EDGELAND_EXPORT Message decode_message(std::string_view bytes);

}  // namespace edgeland::net
