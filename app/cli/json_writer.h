// A flat JSON object written field by field (machine-readable command output), with core's encoding of numbers and
// strings (json.h: shortest exact text; a non-finite number is null).
#pragma once

#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace somicage {

class JsonObjectWriter {
 public:
  explicit JsonObjectWriter(std::ostream& out);
  ~JsonObjectWriter();  // closes the object if close() was not called
  JsonObjectWriter(const JsonObjectWriter&) = delete;
  JsonObjectWriter& operator=(const JsonObjectWriter&) = delete;

  void field(const std::string& key, double value);
  void field(const std::string& key, int value);
  void field(const std::string& key, long long value);
  void field(const std::string& key, bool value);
  void field(const std::string& key, const char* value);
  void field(const std::string& key, const std::string& value);
  void field(const std::string& key, const std::vector<std::string>& values);
  // A nested object of numbers, in the given order: "key": {"a": 1, "b": 2}.
  void field(const std::string& key, const std::vector<std::pair<std::string, double>>& values);
  // A list of such objects: "key": [{"a": 1, "b": 2}, {"a": 3, "b": 4}].
  using NumberObject = std::vector<std::pair<std::string, double>>;
  void field(const std::string& key, const std::vector<NumberObject>& objects);
  void null(const std::string& key);
  void close();

  static std::string quote(const std::string& text);

 private:
  void key(const std::string& name);
  void writeNumber(double value);

  std::ostream& out_;
  bool first_ = true;
  bool closed_ = false;
};

}  // namespace somicage
