#pragma once
// The bytes of the landscape's binary formats (save files, deltas, region records) and of the
// messages that carry them (net/'s protocol): fixed-width little-endian integers, LEB128 varints
// and zigzag varints, written by ByteWriter and read by ByteReader. The reader is for untrusted
// bytes: it never reads past its end, refuses a varint longer than 64 bits, and bounds every
// count by the bytes left before anything is allocated for it. A refusal is a ReadFailure (what
// and where), which each format turns into its own typed error (LoadError, DeltaError,
// net::ProtocolError). Header-only plain C++20.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace edgeland {

class ByteWriter {
 public:
  void u8(std::uint8_t v) { out_.push_back(static_cast<char>(v)); }
  void fixed(std::uint64_t v, int bytes) {
    for (int i = 0; i < bytes; ++i) u8(static_cast<std::uint8_t>(v >> (8 * i)));
  }
  void varint(std::uint64_t v) {
    while (v >= 0x80) {
      u8(static_cast<std::uint8_t>(v | 0x80));
      v >>= 7;
    }
    u8(static_cast<std::uint8_t>(v));
  }
  void zigzag(std::int64_t v) {
    varint((static_cast<std::uint64_t>(v) << 1) ^ static_cast<std::uint64_t>(v >> 63));
  }
  void raw(std::string_view bytes) { out_.append(bytes); }
  std::string& bytes() { return out_; }

 private:
  std::string out_;
};

// Why and where reading stopped: `offset` counts from the start of the whole buffer.
struct ReadFailure {
  std::string what;
  std::size_t offset;
};

class ByteReader {
 public:
  // Reads bytes[at, end).
  ByteReader(std::string_view bytes, std::size_t at, std::size_t end)
      : bytes_(bytes), at_(at), end_(end) {}

  [[noreturn]] void fail(const std::string& what) const { throw ReadFailure{what, at_}; }

  std::uint64_t fixed(std::size_t n) {
    if (end_ - at_ < n) fail("truncated");
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < n; ++i)
      v |= std::uint64_t{static_cast<unsigned char>(bytes_[at_ + i])} << (8 * i);
    at_ += n;
    return v;
  }
  std::uint64_t varint() {
    std::uint64_t v = 0;
    for (int shift = 0; shift < 64; shift += 7) {
      const std::uint64_t b = fixed(1);
      if (shift == 63 && b > 1) fail("varint overflows 64 bits");
      v |= (b & 0x7f) << shift;
      if (!(b & 0x80)) return v;
    }
    // Not reached by tests: a tenth byte with its continuation bit is above 1 and refused
    // above, so the loop never runs out; kept so the function visibly ends.
    fail("varint longer than 10 bytes");
  }
  std::int64_t zigzag() {
    const std::uint64_t v = varint();
    return static_cast<std::int64_t>(v >> 1) ^ -static_cast<std::int64_t>(v & 1);
  }
  // A count of items of at least `min_bytes` each: bounded by the bytes left before anything
  // is allocated for it.
  std::size_t count(std::size_t min_bytes) {
    const std::uint64_t n = varint();
    if (n > left() / min_bytes) fail("count larger than the file");
    return static_cast<std::size_t>(n);
  }
  std::string_view take(std::size_t n) {
    if (left() < n) fail("truncated");
    const std::string_view out = bytes_.substr(at_, n);
    at_ += n;
    return out;
  }

  std::size_t at() const noexcept { return at_; }
  void seek(std::size_t at) noexcept { at_ = at; }
  std::size_t end() const noexcept { return end_; }
  std::size_t left() const noexcept { return end_ - at_; }
  bool done() const noexcept { return at_ == end_; }

 private:
  std::string_view bytes_;
  std::size_t at_, end_;
};

}  // namespace edgeland
