#include "jobs/session_read.h"

#include <exception>
#include <filesystem>
#include <new>

namespace somicage::editor {

Session readSessionFile(const std::string& path, JobContext&) { return loadSession(path); }

SessionRead readSessionOnJob(const std::string& path, const SessionReader& read, JobContext& context) {
  SessionRead out;
  out.path = path;
  context.setStage("Reading session " + std::filesystem::path(path).filename().string());
  context.report(0.0);
  try {
    if (!context.cancelled()) out.session = read(path, context);  // superseded while it waited for its core: skip
  } catch (const std::bad_alloc&) {
    out.error = path + ": out of memory while reading the session";
  } catch (const std::exception& e) {
    out.error = e.what();
  }
  out.cancelled = context.cancelled();
  if (out.cancelled) {
    out.session.reset();
    out.error.clear();
  }
  context.report(1.0);
  context.setStage("");
  return out;
}

}  // namespace somicage::editor
