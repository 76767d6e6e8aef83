// A recursive-descent reader of decimal POLYGON / MULTIPOLYGON WKT (see decimal_wkt.hpp).
#include "decimal_wkt.hpp"

#include <cctype>

namespace edgeland::test {
namespace {

class Reader {
 public:
  explicit Reader(std::string_view text) : text_(text) {}

  DecimalGeometry geometry() {
    const std::string tag = word();
    DecimalGeometry g;
    if (tag == "POLYGON") {
      g.push_back(polygon());
    } else if (tag == "MULTIPOLYGON") {
      if (peek_word() == "EMPTY") {
        word();
      } else {
        expect('(');
        do g.push_back(polygon());
        while (accept(','));
        expect(')');
      }
    } else {
      fail("POLYGON or MULTIPOLYGON expected");
    }
    skip_space();
    if (pos_ != text_.size()) fail("trailing text");
    return g;
  }

 private:
  DecimalPolygon polygon() {
    DecimalPolygon p;
    expect('(');
    do p.push_back(ring());
    while (accept(','));
    expect(')');
    return p;
  }

  DecimalRing ring() {
    DecimalRing r;
    expect('(');
    do {
      Decimal x = number();
      Decimal y = number();
      r.push_back({std::move(x), std::move(y)});
    } while (accept(','));
    expect(')');
    return r;
  }

  Decimal number() {
    skip_space();
    auto d = parse_decimal(text_, pos_);
    if (!d) fail("number expected");
    return std::move(*d);
  }

  std::string word() {
    skip_space();
    std::string w;
    while (pos_ < text_.size() && std::isalpha(static_cast<unsigned char>(text_[pos_])))
      w.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(text_[pos_++]))));
    return w;
  }

  std::string peek_word() {
    const std::size_t saved = pos_;
    std::string w = word();
    pos_ = saved;
    return w;
  }

  bool accept(char c) {
    skip_space();
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }

  void expect(char c) {
    if (!accept(c)) fail(std::string("'") + c + "' expected");
  }

  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw std::invalid_argument("WKT at offset " + std::to_string(pos_) + ": " + what);
  }

  std::string_view text_;
  std::size_t pos_ = 0;
};

}  // namespace

DecimalGeometry read_decimal_wkt(std::string_view text) { return Reader(text).geometry(); }

}  // namespace edgeland::test
