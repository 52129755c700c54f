#include "jobs/background_job.h"

namespace somicage::editor {

std::thread startJobThread(std::function<void()> body) { return std::thread(std::move(body)); }

}  // namespace somicage::editor
