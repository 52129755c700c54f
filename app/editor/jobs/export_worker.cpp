#include "jobs/export_worker.h"

#include <exception>
#include <new>
#include <utility>

#include "base/errors.h"

namespace somicage::editor {

bool ExportWorker::start(std::string target, std::string doneMessage, Job job) {
  if (busy()) return false;
  target_ = target;
  job_.start(
      [target = std::move(target), doneMessage = std::move(doneMessage), job = std::move(job)](JobContext& context) {
        ExportOutcome outcome;
        outcome.target = target;
        outcome.doneMessage = doneMessage;
        const ProgressCallback progress = context.span(0.0, 1.0);
        try {
          if (!progress(0.0)) throw Cancelled();
          outcome.notes = job(progress);
        } catch (const Cancelled&) {
          outcome.cancelled = true;
        } catch (const std::bad_alloc&) {
          outcome.error = target + ": not enough memory for the export; nothing was written";
        } catch (const std::exception& e) {
          outcome.error = e.what();
        }
        return outcome;
      },
      job_.cores() - 1);  // the UI keeps a core: it draws the views under the progress bar
  return true;
}

ProgressCallback stageProgress(const ProgressCallback& whole, double from, double to) {
  return [whole, from, to](double fraction) { return whole(from + (to - from) * fraction); };
}

}  // namespace somicage::editor
