// The modal that shows a running export (export_worker.h): what is written, a progress bar and Cancel.
#pragma once

namespace somicage::editor {

struct AppState;

void drawExportProgress(AppState& state);

}  // namespace somicage::editor
