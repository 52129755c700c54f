// A session file read and parsed on a job (JobsState::session), never on the UI thread: opening a session (File ▸
// Open session, Open Recent, a dropped .json, --session) keeps the views drawing, shows the stage with a progress bar
// and Cancel (Esc), and leaves the open document as it is until the session is applied. The frame loop's
// pollSessionRead (document_files.cpp) applies what was read, on the UI thread. No GL.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "engine/session.h"
#include "jobs/background_job.h"

namespace somicage::editor {

struct SessionRead {
  std::string path;
  std::optional<Session> session;  // read and parsed
  std::string error;               // else why not: the InputError's text (the file, the line, what is wrong)
  bool cancelled = false;          // cancelled while it was read: nothing is applied
};

// How a session file is read on the job: core's loadSession (readSessionFile); a test passes one it steers. It may
// return early when context.cancelled() (what it read is then dropped anyway).
using SessionReader = std::function<Session(const std::string& path, JobContext& context)>;
Session readSessionFile(const std::string& path, JobContext& context);

// The job's work: `read` run on `path`, its errors caught, a cancel that came while it ran honoured.
SessionRead readSessionOnJob(const std::string& path, const SessionReader& read, JobContext& context);

}  // namespace somicage::editor
