#include "base/json.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "base/errors.h"

namespace somicage {

JsonValue JsonValue::boolean(bool b) {
  JsonValue v;
  v.type_ = Type::Bool;
  v.bool_ = b;
  return v;
}
JsonValue JsonValue::number(double x) {
  JsonValue v;
  v.type_ = Type::Number;
  v.number_ = x;
  return v;
}
JsonValue JsonValue::string(std::string s) {
  JsonValue v;
  v.type_ = Type::String;
  v.string_ = std::move(s);
  return v;
}
JsonValue JsonValue::array() {
  JsonValue v;
  v.type_ = Type::Array;
  return v;
}
JsonValue JsonValue::object() {
  JsonValue v;
  v.type_ = Type::Object;
  return v;
}

const JsonValue* JsonValue::find(const std::string& key) const {
  if (type_ != Type::Object) return nullptr;
  auto it = members_.find(key);
  return it == members_.end() ? nullptr : &it->second;
}

void appendJsonNumber(double x, std::string& out) {
  if (!std::isfinite(x)) {
    out += "null";
    return;
  }
  char text[32];
  const auto result = std::to_chars(text, text + sizeof text, x);  // shortest text that reads back exactly
  out.append(text, result.ptr);
}

void appendJsonString(const std::string& s, std::string& out) {
  out += '"';
  for (char c : s) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      case '\r':
        out += "\\r";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
          out += buf;
        } else {
          out += c;
        }
    }
  }
  out += '"';
}

namespace {

void dumpTo(const JsonValue& v, int indent, int depth, std::string& out) {
  const std::string pad = indent > 0 ? "\n" + std::string(static_cast<std::size_t>(indent * (depth + 1)), ' ') : "";
  const std::string padEnd = indent > 0 ? "\n" + std::string(static_cast<std::size_t>(indent * depth), ' ') : "";
  switch (v.type()) {
    case JsonValue::Type::Null:
      out += "null";
      break;
    case JsonValue::Type::Bool:
      out += v.asBool() ? "true" : "false";
      break;
    case JsonValue::Type::Number:
      appendJsonNumber(v.asNumber(), out);
      break;
    case JsonValue::Type::String:
      appendJsonString(v.asString(), out);
      break;
    case JsonValue::Type::Array: {
      // Arrays of numbers stay on one line (poses are rows of 2 or 3 numbers).
      bool flat = true;
      for (const JsonValue& item : v.items()) flat = flat && item.isNumber();
      out += '[';
      for (std::size_t i = 0; i < v.items().size(); ++i) {
        if (i > 0) out += flat ? ", " : ",";
        if (!flat) out += pad;
        dumpTo(v.items()[i], indent, depth + 1, out);
      }
      if (!flat && !v.items().empty()) out += padEnd;
      out += ']';
      break;
    }
    case JsonValue::Type::Object: {
      out += '{';
      bool first = true;
      for (const auto& [key, value] : v.members()) {
        if (!first) out += ',';
        first = false;
        out += pad;
        appendJsonString(key, out);
        out += indent > 0 ? ": " : ":";
        dumpTo(value, indent, depth + 1, out);
      }
      if (!v.members().empty()) out += padEnd;
      out += '}';
      break;
    }
  }
}

class Parser {
 public:
  Parser(const std::string& text, const std::string& source) : text_(text), source_(source) {}

  JsonValue parseDocument() {
    JsonValue v = parseValue(0);
    skipSpace();
    if (pos_ != text_.size()) fail("unexpected text after the JSON value");
    return v;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    long line = 1;
    for (std::size_t i = 0; i < pos_ && i < text_.size(); ++i) line += text_[i] == '\n';
    throw InputError(source_, line, what, "fix the JSON syntax, or save the session again from the editor");
  }
  void skipSpace() {
    while (pos_ < text_.size() &&
           (text_[pos_] == ' ' || text_[pos_] == '\n' || text_[pos_] == '\t' || text_[pos_] == '\r'))
      ++pos_;
  }
  bool consume(const char* word) {
    std::size_t n = 0;
    while (word[n]) ++n;
    if (text_.compare(pos_, n, word) == 0) {
      pos_ += n;
      return true;
    }
    return false;
  }
  JsonValue parseValue(int depth) {
    if (depth > 64) fail("JSON nested too deeply");
    skipSpace();
    if (pos_ >= text_.size()) fail("unexpected end of the JSON text");
    const char c = text_[pos_];
    if (c == '{') return parseObject(depth);
    if (c == '[') return parseArray(depth);
    if (c == '"') return JsonValue::string(parseString());
    if (consume("true")) return JsonValue::boolean(true);
    if (consume("false")) return JsonValue::boolean(false);
    if (consume("null")) return JsonValue();
    if (c == '-' || (c >= '0' && c <= '9')) {
      const char* begin = text_.c_str() + pos_;
      char* end = nullptr;
      const double x = std::strtod(begin, &end);
      // strtod also reads nan, inf and hexadecimal, and overflows to inf: JSON has only finite decimals.
      const bool decimal = std::all_of(begin, static_cast<const char*>(end), [](char d) {
        return (d >= '0' && d <= '9') || d == '-' || d == '+' || d == '.' || d == 'e' || d == 'E';
      });
      if (end == begin || !decimal) fail("malformed number");
      if (!std::isfinite(x)) fail("number out of range (JSON numbers must be finite)");
      pos_ += static_cast<std::size_t>(end - begin);
      return JsonValue::number(x);
    }
    fail(std::string("unexpected character '") + c + "'");
  }
  std::string parseString() {
    ++pos_;  // opening quote
    std::string out;
    while (true) {
      if (pos_ >= text_.size()) fail("unterminated string");
      const char c = text_[pos_++];
      if (c == '"') return out;
      if (c != '\\') {
        out += c;
        continue;
      }
      if (pos_ >= text_.size()) fail("unterminated escape");
      const char e = text_[pos_++];
      switch (e) {
        case '"':
          out += '"';
          break;
        case '\\':
          out += '\\';
          break;
        case '/':
          out += '/';
          break;
        case 'n':
          out += '\n';
          break;
        case 't':
          out += '\t';
          break;
        case 'r':
          out += '\r';
          break;
        case 'b':
          out += '\b';
          break;
        case 'f':
          out += '\f';
          break;
        case 'u': {
          if (pos_ + 4 > text_.size() ||
              !std::all_of(text_.begin() + static_cast<std::ptrdiff_t>(pos_),
                           text_.begin() + static_cast<std::ptrdiff_t>(pos_ + 4),
                           [](char h) { return std::isxdigit(static_cast<unsigned char>(h)) != 0; })) {
            fail("a \\u escape needs 4 hexadecimal digits");
          }
          const unsigned code = static_cast<unsigned>(std::strtoul(text_.substr(pos_, 4).c_str(), nullptr, 16));
          pos_ += 4;
          if (code < 0x80) {
            out += static_cast<char>(code);
          } else if (code < 0x800) {
            out += static_cast<char>(0xC0 | (code >> 6));
            out += static_cast<char>(0x80 | (code & 0x3F));
          } else {
            out += static_cast<char>(0xE0 | (code >> 12));
            out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (code & 0x3F));
          }
          break;
        }
        default:
          fail(std::string("unknown escape \\") + e);
      }
    }
  }
  JsonValue parseArray(int depth) {
    ++pos_;
    JsonValue v = JsonValue::array();
    skipSpace();
    if (pos_ < text_.size() && text_[pos_] == ']') {
      ++pos_;
      return v;
    }
    while (true) {
      v.push(parseValue(depth + 1));
      skipSpace();
      if (pos_ < text_.size() && text_[pos_] == ',') {
        ++pos_;
        continue;
      }
      if (pos_ < text_.size() && text_[pos_] == ']') {
        ++pos_;
        return v;
      }
      fail("expected ',' or ']' in an array");
    }
  }
  JsonValue parseObject(int depth) {
    ++pos_;
    JsonValue v = JsonValue::object();
    skipSpace();
    if (pos_ < text_.size() && text_[pos_] == '}') {
      ++pos_;
      return v;
    }
    while (true) {
      skipSpace();
      if (pos_ >= text_.size() || text_[pos_] != '"') fail("expected a quoted key in an object");
      const std::string key = parseString();
      skipSpace();
      if (pos_ >= text_.size() || text_[pos_] != ':') fail("expected ':' after the key \"" + key + "\"");
      ++pos_;
      v.set(key, parseValue(depth + 1));
      skipSpace();
      if (pos_ < text_.size() && text_[pos_] == ',') {
        ++pos_;
        continue;
      }
      if (pos_ < text_.size() && text_[pos_] == '}') {
        ++pos_;
        return v;
      }
      fail("expected ',' or '}' in an object");
    }
  }

  const std::string& text_;
  const std::string& source_;
  std::size_t pos_ = 0;
};

}  // namespace

std::string JsonValue::dump(int indent) const {
  std::string out;
  dumpTo(*this, indent, 0, out);
  out += '\n';
  return out;
}

JsonValue parseJson(const std::string& text, const std::string& source) { return Parser(text, source).parseDocument(); }

}  // namespace somicage
