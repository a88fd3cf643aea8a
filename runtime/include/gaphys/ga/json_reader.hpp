// A small JSON reader for the profile recorder (profile_recorder.hpp), which
// adds its counts to a profile file that gaphys-gen, a person or another
// tool may have written in any layout JSON allows. It reads a whole
// document into values, keeps integers exact (as a sign and a 64-bit
// magnitude, or too large for one) and tells where the text stops being
// JSON. Strings keep their bytes; escapes are decoded to UTF-8.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace gaphys::ga::json {

struct value {
  enum class kind { null, boolean, integer, number, string, array, object };
  kind type = kind::null;
  bool boolean = false;
  // An integer (no fraction, no exponent): its sign and magnitude, or
  // too_large when the magnitude needs more than 64 bits. Other numbers are
  // `number`, unread.
  bool negative = false;
  bool too_large = false;
  std::uint64_t magnitude = 0;
  std::string text;                                    // string
  std::vector<value> items;                            // array
  std::vector<std::pair<std::string, value>> members;  // object, in order

  // The member named `name` (the last, where a name repeats, as most
  // readers take it), or nullptr.
  const value* member(const std::string& name) const {
    for (auto it = members.rbegin(); it != members.rend(); ++it) {
      if (it->first == name) return &it->second;
    }
    return nullptr;
  }
  bool is_unsigned_integer() const { return type == kind::integer && !negative && !too_large; }
};

namespace detail {

class reader {
 public:
  explicit reader(const std::string& text) : text_(text) {}

  bool document(value& out, std::string& error) {
    skip_space();
    bool read_whole = read(out, 0);
    skip_space();
    if (read_whole && at_ != text_.size()) read_whole = fail("text after the document");
    return read_whole || failed(error);
  }

 private:
  static constexpr int deepest = 64;  // nesting; a profile needs 3

  bool read(value& out, int depth) {
    if (depth > deepest) return fail("nested too deeply");
    if (at_ == text_.size()) return fail("the text ends where a value should be");
    const char c = text_[at_];
    if (c == '{') return object(out, depth);
    if (c == '[') return array(out, depth);
    if (c == '"') {
      out.type = value::kind::string;
      return string(out.text);
    }
    if (c == '-' || (c >= '0' && c <= '9')) return number(out);
    if (word("true")) return out.type = value::kind::boolean, out.boolean = true, true;
    if (word("false")) return out.type = value::kind::boolean, true;
    if (word("null")) return out.type = value::kind::null, true;
    return fail("not a JSON value");
  }

  bool object(value& out, int depth) {
    out.type = value::kind::object;
    ++at_;  // {
    skip_space();
    if (take('}')) return true;
    for (;;) {
      skip_space();
      if (at_ == text_.size() || text_[at_] != '"') return fail("expected a member's name in quotes");
      std::string name;
      if (!string(name)) return false;
      skip_space();
      if (!take(':')) return fail("expected ':' after a member's name");
      skip_space();
      out.members.emplace_back(std::move(name), value{});
      if (!read(out.members.back().second, depth + 1)) return false;
      skip_space();
      if (take('}')) return true;
      if (!take(',')) return fail("expected ',' or '}' in an object");
    }
  }

  bool array(value& out, int depth) {
    out.type = value::kind::array;
    ++at_;  // [
    skip_space();
    if (take(']')) return true;
    for (;;) {
      skip_space();
      out.items.emplace_back();
      if (!read(out.items.back(), depth + 1)) return false;
      skip_space();
      if (take(']')) return true;
      if (!take(',')) return fail("expected ',' or ']' in an array");
    }
  }

  bool number(value& out) {
    out.type = value::kind::integer;
    out.negative = take('-');
    if (at_ == text_.size() || !digit(text_[at_])) return fail("expected a digit");
    if (text_[at_] == '0' && at_ + 1 < text_.size() && digit(text_[at_ + 1])) {
      return fail("a number may not start with 0");
    }
    for (; at_ < text_.size() && digit(text_[at_]); ++at_) {
      const std::uint64_t d = std::uint64_t(text_[at_] - '0');
      if (out.magnitude > (UINT64_MAX - d) / 10) out.too_large = true;
      if (!out.too_large) out.magnitude = out.magnitude * 10 + d;
    }
    bool fraction = false;
    if (take('.')) {
      fraction = true;
      if (!digits()) return fail("expected a digit after '.'");
    }
    if (at_ < text_.size() && (text_[at_] == 'e' || text_[at_] == 'E')) {
      fraction = true;
      ++at_;
      if (!take('+')) take('-');
      if (!digits()) return fail("expected a digit in the exponent");
    }
    if (fraction) out.type = value::kind::number;
    return true;
  }

  bool string(std::string& out) {
    ++at_;  // "
    while (at_ < text_.size()) {
      const unsigned char c = static_cast<unsigned char>(text_[at_++]);
      if (c == '"') return true;
      if (c < 0x20) return fail("a control character inside a string");
      if (c != '\\') {
        out += static_cast<char>(c);
        continue;
      }
      if (at_ == text_.size()) break;
      const char e = text_[at_++];
      switch (e) {
        case '"': case '\\': case '/': out += e; break;
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'n': out += '\n'; break;
        case 'r': out += '\r'; break;
        case 't': out += '\t'; break;
        case 'u': {
          std::uint32_t code = 0;
          if (!hex4(code)) return fail("expected four hex digits after \\u");
          if (code >= 0xD800 && code < 0xDC00) {  // a pair's first half
            std::uint32_t low = 0;
            if (!(take('\\') && take('u') && hex4(low) && low >= 0xDC00 && low < 0xE000)) {
              return fail("a lone surrogate in \\u escapes");
            }
            code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
          } else if (code >= 0xDC00 && code < 0xE000) {
            return fail("a lone surrogate in \\u escapes");
          }
          append_utf8(out, code);
          break;
        }
        default:
          return fail("an unknown escape in a string");
      }
    }
    return fail("a string without its closing quote");
  }

  bool hex4(std::uint32_t& code) {
    for (int i = 0; i < 4; ++i, ++at_) {
      if (at_ == text_.size()) return false;
      const char h = text_[at_];
      const int v = h >= '0' && h <= '9' ? h - '0'
                    : h >= 'a' && h <= 'f' ? h - 'a' + 10
                    : h >= 'A' && h <= 'F' ? h - 'A' + 10
                                           : -1;
      if (v < 0) return false;
      code = code << 4 | std::uint32_t(v);
    }
    return true;
  }

  static void append_utf8(std::string& out, std::uint32_t code) {
    if (code < 0x80) {
      out += static_cast<char>(code);
    } else if (code < 0x800) {
      out += static_cast<char>(0xC0 | code >> 6);
      out += static_cast<char>(0x80 | (code & 0x3F));
    } else if (code < 0x10000) {
      out += static_cast<char>(0xE0 | code >> 12);
      out += static_cast<char>(0x80 | (code >> 6 & 0x3F));
      out += static_cast<char>(0x80 | (code & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | code >> 18);
      out += static_cast<char>(0x80 | (code >> 12 & 0x3F));
      out += static_cast<char>(0x80 | (code >> 6 & 0x3F));
      out += static_cast<char>(0x80 | (code & 0x3F));
    }
  }

  static bool digit(char c) { return c >= '0' && c <= '9'; }
  bool digits() {
    const std::size_t start = at_;
    while (at_ < text_.size() && digit(text_[at_])) ++at_;
    return at_ > start;
  }
  bool take(char c) {
    if (at_ < text_.size() && text_[at_] == c) return ++at_, true;
    return false;
  }
  bool word(const char* w) {
    const std::string expected(w);
    if (text_.compare(at_, expected.size(), expected) != 0) return false;
    at_ += expected.size();
    return true;
  }
  void skip_space() {
    while (at_ < text_.size() &&
           (text_[at_] == ' ' || text_[at_] == '\t' || text_[at_] == '\n' || text_[at_] == '\r')) {
      ++at_;
    }
  }
  bool fail(const char* what) {
    if (what_.empty()) what_ = what, where_ = at_;
    return false;
  }
  // "line L, column C: what" of the first failure.
  bool failed(std::string& error) const {
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < where_ && i < text_.size(); ++i) {
      if (text_[i] == '\n') {
        ++line, column = 1;
      } else {
        ++column;
      }
    }
    error = "line " + std::to_string(line) + ", column " + std::to_string(column) + ": " + what_;
    return false;
  }

  const std::string& text_;
  std::size_t at_ = 0;
  std::string what_;
  std::size_t where_ = 0;
};

}  // namespace detail

// Reads `text` as one JSON document into `out`; on failure returns false
// with `error` saying where ("line L, column C: what").
inline bool parse(const std::string& text, value& out, std::string& error) {
  out = value{};
  return detail::reader(text).document(out, error);
}

}  // namespace gaphys::ga::json
