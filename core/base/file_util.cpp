#include "base/file_util.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "base/errors.h"

namespace somicage {

std::string readTextFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, -1, std::string("cannot open the file: ") + std::strerror(errno), "check the path");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void writeFileAtomic(const std::string& path, const std::string& bytes) {
  std::vector<char> tmpl(path.begin(), path.end());
  const std::string suffix = ".tmp-XXXXXX";
  tmpl.insert(tmpl.end(), suffix.begin(), suffix.end());
  tmpl.push_back('\0');
  const int fd = ::mkstemp(tmpl.data());
  if (fd < 0) {
    throw InputError(path, -1, std::string("cannot create a file in this folder: ") + std::strerror(errno),
                     "check that the folder exists and that you may write to it");
  }
  const std::string tmp(tmpl.data());
  auto failWith = [&](const char* what) {
    const std::string reason = std::strerror(errno);
    ::close(fd);
    std::remove(tmp.c_str());
    throw InputError(path, -1, std::string(what) + ": " + reason, "check the free space and the permissions");
  };
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      failWith("write failed");
    }
    done += static_cast<std::size_t>(n);
  }
  if (::fchmod(fd, 0644) != 0) failWith("chmod failed");
  if (::fsync(fd) != 0) failWith("fsync failed");
  if (::close(fd) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(tmp.c_str());
    throw InputError(path, -1, "close failed: " + reason, "check the free space");
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(tmp.c_str());
    throw InputError(path, -1, "rename failed: " + reason, "check the permissions of the folder");
  }
}

bool samePath(const std::string& a, const std::string& b) {
  if (a.empty() || b.empty()) return a.empty() && b.empty();
  std::error_code error;  // a path that cannot be resolved compares as written, made absolute
  const auto canonical = [&](const std::string& path) {
    const std::filesystem::path resolved = std::filesystem::weakly_canonical(path, error);
    return error ? std::filesystem::absolute(path, error).lexically_normal() : resolved;
  };
  return canonical(a) == canonical(b);
}

}  // namespace somicage
