// A small JSON reader and writer for session files (objects, arrays, strings, numbers, booleans, null), and the one
// encoding of numbers and strings every JSON this project writes uses (sessions, the commands' --json).
// Pure, no dependencies beyond the standard library and core/errors.h.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace somicage {

class JsonValue {
 public:
  enum class Type { Null, Bool, Number, String, Array, Object };

  JsonValue() = default;
  static JsonValue boolean(bool b);
  static JsonValue number(double x);
  static JsonValue string(std::string s);
  static JsonValue array();
  static JsonValue object();

  Type type() const { return type_; }
  bool isNull() const { return type_ == Type::Null; }
  bool isNumber() const { return type_ == Type::Number; }
  bool isString() const { return type_ == Type::String; }
  bool isArray() const { return type_ == Type::Array; }
  bool isObject() const { return type_ == Type::Object; }
  bool asBool() const { return bool_; }
  double asNumber() const { return number_; }
  const std::string& asString() const { return string_; }
  const std::vector<JsonValue>& items() const { return items_; }
  const std::map<std::string, JsonValue>& members() const { return members_; }

  void push(JsonValue v) { items_.push_back(std::move(v)); }
  void set(const std::string& key, JsonValue v) { members_[key] = std::move(v); }
  // nullptr when missing or when this is not an object.
  const JsonValue* find(const std::string& key) const;

  // Writes indented JSON, numbers and strings as appendJsonNumber and appendJsonString do.
  std::string dump(int indent = 0) const;

 private:
  Type type_ = Type::Null;
  bool bool_ = false;
  double number_ = 0.0;
  std::string string_;
  std::vector<JsonValue> items_;
  std::map<std::string, JsonValue> members_;
};

// A number as the shortest text that reads back to the same double; a non-finite one as null (JSON has no
// infinities: a session writes nu's as "inf" / "-inf" itself, a command's --json prints null for an undefined value).
void appendJsonNumber(double x, std::string& out);
// A quoted string, with quotes, backslashes and control characters escaped.
void appendJsonString(const std::string& text, std::string& out);

// Parses JSON text; throws InputError(source, line, what, hint) on a syntax error.
JsonValue parseJson(const std::string& text, const std::string& source);

}  // namespace somicage
