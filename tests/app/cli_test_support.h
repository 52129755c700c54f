// Helpers of the command-line tests: run the real somicage executable, a scratch folder, a strict JSON parser.
#pragma once

#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <Eigen/Core>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace somicage::test {

namespace fs = std::filesystem;

inline const fs::path kDataDir = SOMICAGE_TEST_DATA_DIR;
inline const fs::path kModelsDir = SOMICAGE_MODELS_DIR;

inline std::string dataFile(const std::string& name) { return (kDataDir / name).string(); }

// `somicage deform` of the pyramid mesh in the cube cage at rest, writing out, with extra options after the files.
inline std::vector<std::string> cubeDeformArgs(const std::string& out, const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args = {"deform",
                                   "--cage",
                                   dataFile("cube_cage.obj"),
                                   "--posed",
                                   dataFile("cube_cage.obj"),
                                   "--mesh",
                                   dataFile("pyramid_mesh.obj"),
                                   "--out",
                                   out};
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

inline std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

// A tetrahedron inside the cube cage with one normal per vertex that is not the faces' (so carried and recomputed
// normals differ).
inline const char* const kTetWithNormals =
    "v 0.5 0 0\nv 0 0.5 0\nv 0 0 0.5\nv -0.2 -0.2 -0.2\n"
    "vn 1 0.1 0.2\nvn 0.1 1 0\nvn 0 0.3 1\nvn -1 -1 -0.5\n"
    "f 1//1 2//2 3//3\nf 1//1 4//4 2//2\nf 2//2 4//4 3//3\nf 3//3 4//4 1//1\n";

// The `vn` lines of an OBJ file, in order.
inline std::vector<Eigen::Vector3d> objNormals(const fs::path& path) {
  std::vector<Eigen::Vector3d> normals;
  std::istringstream lines(readFile(path));
  std::string line;
  while (std::getline(lines, line)) {
    if (line.rfind("vn ", 0) != 0) continue;
    std::istringstream numbers(line.substr(3));
    Eigen::Vector3d n;
    numbers >> n[0] >> n[1] >> n[2];
    normals.push_back(n);
  }
  return normals;
}

// A fresh folder, removed with its contents at the end of the test.
class ScratchDir {
 public:
  ScratchDir() {
    std::string pattern = (fs::temp_directory_path() / "somicage-cli-test-XXXXXX").string();
    path_ = ::mkdtemp(pattern.data());
  }
  ~ScratchDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

struct RunResult {
  int exitCode = -1;  // 128 + signal when the process was killed (a crash)
  std::string out, err;

  // Number of lines on stderr.
  int errLines() const {
    int lines = 0;
    for (const char c : err) lines += c == '\n';
    return lines;
  }
};

inline std::ostream& operator<<(std::ostream& os, const RunResult& r) {
  return os << "exit " << r.exitCode << "\n--- stdout:\n" << r.out << "--- stderr:\n" << r.err;
}

// Runs somicage with the arguments; stdout and stderr are captured in files.
inline RunResult runSomicage(const std::vector<std::string>& args) {
  ScratchDir capture;
  const std::string outPath = capture.file("stdout"), errPath = capture.file("stderr");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<std::string> storage = {SOMICAGE_EXE};
  storage.insert(storage.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& arg : storage) argv.push_back(arg.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  RunResult result;
  const int spawned = posix_spawn(&pid, SOMICAGE_EXE, &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) {
    ADD_FAILURE() << "cannot run " << SOMICAGE_EXE;
    return result;
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  result.out = readFile(outPath);
  result.err = readFile(errPath);
  return result;
}

// ---------------------------------------------------------------------------------------------------------------
// A strict JSON parser (RFC 8259 values), enough to check that output parses and to read it.
// ---------------------------------------------------------------------------------------------------------------

struct Json {
  enum class Type { Null, Bool, Number, String, Array, Object } type = Type::Null;
  bool boolean = false;
  double number = 0.0;
  std::string string;
  std::vector<Json> array;
  std::map<std::string, Json> object;

  bool has(const std::string& key) const { return type == Type::Object && object.count(key); }
  const Json& operator[](const std::string& key) const { return object.at(key); }
};

class JsonParser {
 public:
  static Json parse(const std::string& text) {
    JsonParser parser(text);
    Json value = parser.value();
    parser.skipSpace();
    if (parser.pos_ != text.size()) parser.fail("text after the value");
    return value;
  }

 private:
  explicit JsonParser(const std::string& text) : text_(text) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("JSON: " + what + " at offset " + std::to_string(pos_));
  }
  void skipSpace() {
    while (pos_ < text_.size() &&
           (text_[pos_] == ' ' || text_[pos_] == '\n' || text_[pos_] == '\r' || text_[pos_] == '\t')) {
      ++pos_;
    }
  }
  char peek() {
    skipSpace();
    if (pos_ >= text_.size()) fail("unexpected end");
    return text_[pos_];
  }
  void expect(char c) {
    if (peek() != c) fail(std::string("expected '") + c + "'");
    ++pos_;
  }
  void literal(const std::string& word) {
    if (text_.compare(pos_, word.size(), word) != 0) fail("expected " + word);
    pos_ += word.size();
  }

  Json value() {
    Json v;
    const char c = peek();
    if (c == '{') {
      v.type = Json::Type::Object;
      ++pos_;
      if (peek() == '}') return ++pos_, v;
      for (;;) {
        if (peek() != '"') fail("expected a key");
        const std::string key = stringValue();
        expect(':');
        if (v.object.count(key)) fail("duplicate key " + key);
        v.object[key] = value();
        if (peek() == ',') {
          ++pos_;
          continue;
        }
        expect('}');
        return v;
      }
    }
    if (c == '[') {
      v.type = Json::Type::Array;
      ++pos_;
      if (peek() == ']') return ++pos_, v;
      for (;;) {
        v.array.push_back(value());
        if (peek() == ',') {
          ++pos_;
          continue;
        }
        expect(']');
        return v;
      }
    }
    if (c == '"') {
      v.type = Json::Type::String;
      v.string = stringValue();
      return v;
    }
    if (c == 't' || c == 'f') {
      v.type = Json::Type::Bool;
      v.boolean = c == 't';
      literal(c == 't' ? "true" : "false");
      return v;
    }
    if (c == 'n') {
      literal("null");
      return v;
    }
    v.type = Json::Type::Number;
    const size_t start = pos_;
    if (text_[pos_] == '-') ++pos_;
    const auto digits = [&] {
      const size_t from = pos_;
      while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) ++pos_;
      if (pos_ == from) fail("expected a digit");
    };
    if (pos_ < text_.size() && text_[pos_] == '0') {
      ++pos_;
    } else {
      digits();
    }
    if (pos_ < text_.size() && text_[pos_] == '.') ++pos_, digits();
    if (pos_ < text_.size() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
      ++pos_;
      if (pos_ < text_.size() && (text_[pos_] == '+' || text_[pos_] == '-')) ++pos_;
      digits();
    }
    v.number = std::stod(text_.substr(start, pos_ - start));
    return v;
  }

  std::string stringValue() {
    expect('"');
    std::string s;
    while (pos_ < text_.size() && text_[pos_] != '"') {
      const char c = text_[pos_++];
      if (static_cast<unsigned char>(c) < 0x20) fail("control character in a string");
      if (c != '\\') {
        s += c;
        continue;
      }
      if (pos_ >= text_.size()) fail("unexpected end");
      const char e = text_[pos_++];
      const std::string simple = "\"\\/bfnrt", meaning = "\"\\/\b\f\n\r\t";
      if (simple.find(e) != std::string::npos) {
        s += meaning[simple.find(e)];
      } else if (e == 'u' && pos_ + 4 <= text_.size()) {
        s += static_cast<char>(std::stoi(text_.substr(pos_, 4), nullptr, 16));
        pos_ += 4;
      } else {
        fail("bad escape");
      }
    }
    if (pos_ >= text_.size()) fail("unterminated string");
    ++pos_;
    return s;
  }

  const std::string& text_;
  size_t pos_ = 0;
};

}  // namespace somicage::test
