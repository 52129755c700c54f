#include "cli/json_writer.h"

#include "base/json.h"

namespace somicage {

JsonObjectWriter::JsonObjectWriter(std::ostream& out) : out_(out) { out_ << "{"; }

JsonObjectWriter::~JsonObjectWriter() { close(); }

std::string JsonObjectWriter::quote(const std::string& text) {
  std::string quoted;
  appendJsonString(text, quoted);
  return quoted;
}

void JsonObjectWriter::key(const std::string& name) {
  out_ << (first_ ? "\n  " : ",\n  ") << quote(name) << ": ";
  first_ = false;
}

void JsonObjectWriter::writeNumber(double value) {
  std::string text;
  appendJsonNumber(value, text);
  out_ << text;
}

void JsonObjectWriter::field(const std::string& name, double value) {
  key(name);
  writeNumber(value);
}

void JsonObjectWriter::field(const std::string& name, int value) { key(name), out_ << value; }
void JsonObjectWriter::field(const std::string& name, long long value) { key(name), out_ << value; }
void JsonObjectWriter::field(const std::string& name, bool value) { key(name), out_ << (value ? "true" : "false"); }
void JsonObjectWriter::field(const std::string& name, const char* value) { field(name, std::string(value)); }
void JsonObjectWriter::field(const std::string& name, const std::string& value) { key(name), out_ << quote(value); }
void JsonObjectWriter::null(const std::string& name) { key(name), out_ << "null"; }

void JsonObjectWriter::field(const std::string& name, const std::vector<std::string>& values) {
  key(name);
  out_ << "[";
  for (size_t k = 0; k < values.size(); ++k) out_ << (k ? ",\n    " : "\n    ") << quote(values[k]);
  out_ << (values.empty() ? "]" : "\n  ]");
}

void JsonObjectWriter::field(const std::string& name, const std::vector<std::pair<std::string, double>>& values) {
  key(name);
  out_ << "{";
  for (size_t k = 0; k < values.size(); ++k) {
    out_ << (k ? ",\n    " : "\n    ") << quote(values[k].first) << ": ";
    writeNumber(values[k].second);
  }
  out_ << (values.empty() ? "}" : "\n  }");
}

void JsonObjectWriter::field(const std::string& name, const std::vector<NumberObject>& objects) {
  key(name);
  out_ << "[";
  for (size_t i = 0; i < objects.size(); ++i) {
    out_ << (i ? ",\n    {" : "\n    {");
    for (size_t k = 0; k < objects[i].size(); ++k) {
      out_ << (k ? ", " : "") << quote(objects[i][k].first) << ": ";
      writeNumber(objects[i][k].second);
    }
    out_ << "}";
  }
  out_ << (objects.empty() ? "]" : "\n  ]");
}

void JsonObjectWriter::close() {
  if (closed_) return;
  closed_ = true;
  out_ << (first_ ? "}\n" : "\n}\n");
  out_.flush();
}

}  // namespace somicage
