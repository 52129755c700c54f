#include "ui/file_dialog.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <system_error>
#include <utility>

#include "model/app_state.h"
#include "ui/panels.h"
#include "ui/screenshot.h"
#include "ui/unsaved_changes.h"

namespace somicage::editor {

namespace fs = std::filesystem;

namespace {

struct PurposeInfo {
  FileKind kind;
  bool writes;
  const char* title;
};

constexpr PurposeInfo kPurposes[] = {
    {FileKind::Mesh, false, "File"},  // None
    {FileKind::Mesh, false, "Open mesh + cage"},
    {FileKind::PosedCage, false, "Load posed cage"},
    {FileKind::PosedCage, true, "Save posed cage"},
    {FileKind::DeformedMesh, true, "Export deformed mesh"},
    {FileKind::Session, false, "Open session"},
    {FileKind::Session, true, "Save session"},
    {FileKind::Screenshot, true, "Save screenshot"},
};

const PurposeInfo& info(FileDialogPurpose purpose) { return kPurposes[static_cast<int>(purpose)]; }

std::string currentFolder() {
  std::error_code ec;
  const fs::path cwd = fs::current_path(ec);
  return ec ? std::string("/") : cwd.string();
}

FilePlace& place(FileDialogState& d, FileKind kind) { return d.places[static_cast<std::size_t>(kind)]; }

// Remembers where a file of this kind was read or written: the next dialog of the kind starts there.
void remember(FileDialogState& d, FileKind kind, const std::string& path) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(path, ec).lexically_normal();
  if (ec) return;
  place(d, kind) = {absolute.parent_path().string(), absolute.filename().string()};
  noteFolder(d.recentFolders, absolute.parent_path().string());
}

// Carries out the checked action; true on success.
bool act(AppState& state, FileDialogPurpose purpose, const std::string& path) {
  switch (purpose) {
    case FileDialogPurpose::LoadPose:
      return loadPosedCage(state, path);
    case FileDialogPurpose::SavePose:
      return savePosedCage(state, path);
    case FileDialogPurpose::ExportMesh:
      return exportDeformedMesh(state, path);
    case FileDialogPurpose::SaveSession:
      return saveSessionFile(state, path);
    case FileDialogPurpose::OpenSession:
      guardUnsaved(state, "open " + path, [path](AppState& s) { loadSessionFile(s, path); });
      return true;
    case FileDialogPurpose::Screenshot:
      state.view.screenshotRequest = path;
      return true;
    case FileDialogPurpose::OpenScene:
    case FileDialogPurpose::None:
      break;
  }
  return false;
}

void close(AppState& state, bool saved) {
  const bool sessionDialog = state.files.dialog.purpose == FileDialogPurpose::SaveSession;
  state.files.dialog.purpose = FileDialogPurpose::None;
  state.files.dialog.message.clear();
  state.files.dialog.confirmPath.clear();
  if (sessionDialog) sessionDialogFinished(state, saved);
}

bool submitScene(AppState& state) {
  FileDialogState& d = state.files.dialog;
  if (d.recentChoice && d.recentChoice->kind == RecentEntry::Kind::Session) {
    const RecentEntry entry = *d.recentChoice;
    close(state, false);
    openRecent(state, entry);
    return true;
  }
  for (auto [kind, path] : {std::pair{FileKind::Mesh, d.mesh}, std::pair{FileKind::Cage, d.cage}}) {
    if (kind == FileKind::Cage && path.empty() && d.posed.empty()) continue;  // a mesh alone: a cage is made for it
    const PathCheck check = checkOpenPath(kind, path);
    if (check.verdict != PathCheck::Verdict::Ok) {
      d.message = std::string(fileKindInfo(kind).title) + ": " + check.message;
      return false;
    }
  }
  if (!d.posed.empty()) {
    const PathCheck check = checkOpenPath(FileKind::PosedCage, d.posed);
    if (check.verdict != PathCheck::Verdict::Ok) {
      d.message = "posed cage: " + check.message;
      return false;
    }
  }
  remember(d, FileKind::Mesh, d.mesh);
  remember(d, FileKind::Cage, d.cage);
  if (!d.posed.empty()) remember(d, FileKind::PosedCage, d.posed);
  const std::string mesh = d.mesh, cage = d.cage, posed = d.posed;
  close(state, false);
  guardUnsaved(state, "open " + mesh, [=](AppState& s) { requestSceneFiles(s, mesh, cage, posed); });
  return true;
}

}  // namespace

FileKind purposeKind(FileDialogPurpose purpose) { return info(purpose).kind; }
bool purposeWrites(FileDialogPurpose purpose) { return info(purpose).writes; }
const char* purposeTitle(FileDialogPurpose purpose) { return info(purpose).title; }

std::string defaultWriteFolder(const AppState& state) {
  std::vector<std::string> candidates;
  if (!state.document.path.empty()) {
    std::error_code ec;
    candidates.push_back(fs::absolute(state.document.path, ec).lexically_normal().parent_path().string());
  }
  candidates.push_back(currentFolder());
  if (const char* home = std::getenv("HOME")) candidates.emplace_back(home);
  return firstWritableFolder(candidates);
}

std::string writePath(const AppState& state, const std::string& path) {
  if (path.empty() || fs::path(path).is_absolute()) return path;
  const std::string folder = defaultWriteFolder(state);
  return ((folder.empty() ? fs::path(currentFolder()) : fs::path(folder)) / path).lexically_normal().string();
}

void openFileDialog(AppState& state, FileDialogPurpose purpose) {
  FileDialogState& d = state.files.dialog;
  d.purpose = purpose;
  d.justOpened = true;
  d.message.clear();
  d.confirmPath.clear();
  d.recentChoice.reset();
  const FileKind kind = purpose == FileDialogPurpose::OpenScene ? d.sceneField : purposeKind(purpose);
  const FilePlace& p = place(d, kind);
  if (purposeWrites(purpose)) {
    // The kind's own last folder while it can be written to, else the session's, working or home folder.
    d.folder = folderWritable(p.folder) ? p.folder : defaultWriteFolder(state);
    if (d.folder.empty()) d.folder = currentFolder();  // nothing writable: OK will say why
  } else {
    // The kind's own last folder; a kind not used yet starts where the last file went.
    d.folder = !p.folder.empty() ? p.folder : !d.recentFolders.empty() ? d.recentFolders.front() : currentFolder();
  }
  if (purpose == FileDialogPurpose::Screenshot) {
    d.name = defaultScreenshotName();
  } else if (purposeWrites(purpose)) {
    d.name = p.name.empty() ? fileKindInfo(kind).defaultName : p.name;
  } else {
    d.name = p.name;
  }
  if (purpose == FileDialogPurpose::OpenScene && state.model.scene && !state.model.scene->isDemo() && d.mesh.empty()) {
    d.mesh = state.model.scene->meshPath;
    d.cage = state.model.scene->cagePath;
  }
}

std::string dialogPath(const FileDialogState& dialog, const std::string& name) {
  if (name.empty()) return "";
  const fs::path typed(name);
  if (typed.is_absolute()) return typed.lexically_normal().string();
  return (fs::path(dialog.folder) / typed).lexically_normal().string();
}

bool submitFileDialog(AppState& state, bool overwriteConfirmed) {
  FileDialogState& d = state.files.dialog;
  if (d.purpose == FileDialogPurpose::None) return true;
  if (d.purpose == FileDialogPurpose::OpenScene) return submitScene(state);
  const FileKind kind = purposeKind(d.purpose);
  const std::string typed = dialogPath(d, d.name);
  const PathCheck check = purposeWrites(d.purpose) ? checkSavePath(kind, typed) : checkOpenPath(kind, typed);
  d.confirmPath.clear();
  if (check.verdict == PathCheck::Verdict::Refuse) {
    d.message = check.message;
    return false;
  }
  if (check.verdict == PathCheck::Verdict::AskOverwrite && !overwriteConfirmed) {
    d.message = check.message;
    d.confirmPath = check.path;
    return false;
  }
  if (!act(state, d.purpose, check.path)) {
    d.message = state.status.errors.empty() ? "failed" : state.status.errors.back();
    if (!state.status.errors.empty()) state.status.errors.pop_back();  // shown in the dialog instead of a second modal
    return false;
  }
  remember(d, kind, check.path);
  close(state, true);
  return true;
}

void cancelFileDialog(AppState& state) { close(state, false); }

void chooseSceneFile(FileDialogState& d, const std::string& name) {
  std::string& target = d.sceneField == FileKind::Mesh ? d.mesh : d.sceneField == FileKind::Cage ? d.cage : d.posed;
  target = dialogPath(d, name);
  d.recentChoice.reset();
  if (d.sceneField == FileKind::Mesh && d.cage.empty()) d.sceneField = FileKind::Cage;
}

void chooseRecent(FileDialogState& d, const RecentEntry& entry) {
  d.recentChoice = entry;
  if (entry.kind != RecentEntry::Kind::Files) return;
  d.mesh = entry.mesh;
  d.cage = entry.cage;
  d.posed = entry.posed;
}

// ---- drawing ----

namespace {

// The recent files of the Open panel, most recent first, in a list of fixed height (so OK stays where it is as the
// list grows); entries with a missing file are greyed out (the tooltip names it). A click chooses an entry, a double
// click (returns true) opens it.
bool drawRecentFiles(AppState& state) {
  const std::vector<RecentEntry> entries = state.files.recent.entries();  // a copy: opening one reorders the list
  ImGui::Spacing();
  ImGui::TextColored(ImVec4(0.55f, 0.75f, 1.0f, 1.0f), "Recent");
  ImGui::BeginChild("##recentFiles", ImVec2(0, 5.5f * ImGui::GetTextLineHeightWithSpacing()), true);
  if (entries.empty()) ImGui::TextDisabled("(none yet: the scenes and sessions you open or save)");
  bool opened = false;
  FileDialogState& d = state.files.dialog;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const RecentEntry& e = entries[i];
    const std::string missing = missingRecentPath(e);
    ImGui::PushID(static_cast<int>(i));
    if (!missing.empty()) ImGui::BeginDisabled();
    const bool chosen = d.recentChoice && *d.recentChoice == e;
    const bool clicked = ImGui::Selectable(e.label().c_str(), chosen,
                                           ImGuiSelectableFlags_DontClosePopups | ImGuiSelectableFlags_AllowDoubleClick);
    if (!missing.empty()) ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
      std::string tip;
      for (const std::string& path : e.paths()) tip += path + "\n";
      if (!missing.empty()) tip += "missing: " + missing;
      ImGui::SetTooltip("%s", tip.c_str());
    }
    ImGui::PopID();
    if (clicked) {
      chooseRecent(d, e);
      opened |= ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left);
    }
  }
  ImGui::EndChild();
  return opened;
}

// Parent / Home / recent folders, the typed folder, and the listing. A click on a file puts its name in `name`;
// a double click also returns true (OK).
bool drawBrowser(FileDialogState& d, const std::string& extension, std::string& name) {
  if (ImGui::Button("Parent")) d.folder = fs::path(d.folder).parent_path().string();
  tooltip("Go to the folder above (Backspace in the list does the same)");
  ImGui::SameLine();
  const char* home = std::getenv("HOME");
  if (ImGui::Button("Home") && home) d.folder = home;
  tooltip("Go to your home folder");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(160);
  if (ImGui::BeginCombo("##recent", "Recent folders")) {
    for (const std::string& f : d.recentFolders) {
      if (ImGui::Selectable(f.c_str())) d.folder = f;
    }
    if (d.recentFolders.empty()) ImGui::TextDisabled("(none yet)");
    ImGui::EndCombo();
  }
  tooltip("Folders used in this session, most recent first");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1);
  ImGui::InputText("##folder", &d.folder);
  tooltip("The folder shown below; type one to go there");

  std::string error;
  const std::vector<FolderEntry> entries = listFolder(d.folder, extension, error);
  bool accepted = false;
  ImGui::BeginChild("##list", ImVec2(0, 220), true);
  if (!error.empty()) ImGui::TextColored(ImVec4(1.0f, 0.5f, 0.4f, 1.0f), "%s", error.c_str());
  std::string enter;
  for (const FolderEntry& e : entries) {
    const std::string label = e.folder ? "[" + e.name + "]" : e.name;
    const bool selected = !e.folder && e.name == name;
    if (ImGui::Selectable(label.c_str(), selected, ImGuiSelectableFlags_AllowDoubleClick)) {
      if (e.folder) {
        enter = e.name;
      } else {
        name = e.name;
        if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) accepted = true;
      }
    }
  }
  if (entries.empty() && error.empty()) ImGui::TextDisabled("(no folders or %s files here)", extension.c_str());
  ImGui::EndChild();
  if (!enter.empty()) d.folder = (fs::path(d.folder) / enter).string();
  return accepted;
}

}  // namespace

void drawFileDialog(AppState& state) {
  FileDialogState& d = state.files.dialog;
  if (d.purpose == FileDialogPurpose::None) return;
  const char* title = purposeTitle(d.purpose);
  if (d.justOpened) {
    ImGui::OpenPopup(title);
    d.justOpened = false;
    if (state.status.logActions) std::printf("dialog %s\n", title), std::fflush(stdout);
  }
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  // Height 0, always: the dialog grows with its message and never clips its buttons.
  ImGui::SetNextWindowSize(ImVec2(std::min(640.0f, vp->Size.x - 20.0f), 0), ImGuiCond_Always);
  if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_NoSavedSettings)) {
    if (d.purpose != FileDialogPurpose::None) cancelFileDialog(state);
    return;
  }
  bool ok = false;
  if (d.purpose == FileDialogPurpose::OpenScene) {
    const std::pair<FileKind, std::string*> fields[] = {
        {FileKind::Mesh, &d.mesh}, {FileKind::Cage, &d.cage}, {FileKind::PosedCage, &d.posed}};
    for (const auto& [kind, text] : fields) {
      ImGui::PushID(static_cast<int>(kind));
      if (ImGui::RadioButton("##field", d.sceneField == kind)) d.sceneField = kind;
      tooltip("The file list below fills this field");
      ImGui::SameLine();
      if (ImGui::InputText(kind == FileKind::PosedCage ? "posed cage (optional)" : fileKindInfo(kind).title, text)) {
        d.sceneField = kind;
        d.recentChoice.reset();
      }
      ImGui::PopID();
    }
    std::string* target = d.sceneField == FileKind::Mesh   ? &d.mesh
                          : d.sceneField == FileKind::Cage ? &d.cage
                                                           : &d.posed;
    std::string name = fs::path(*target).filename().string();
    const std::string before = name;
    ok = drawBrowser(d, ".obj", name);
    if (name != before) chooseSceneFile(d, name);
    ImGui::TextDisabled("or drop the files on the window");
    ok |= drawRecentFiles(state);
  } else {
    const FileKindInfo& kind = fileKindInfo(purposeKind(d.purpose));
    ok = drawBrowser(d, kind.extension, d.name);
    ImGui::SetNextItemWidth(-80);
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    if (ImGui::InputText("file name", &d.name, ImGuiInputTextFlags_EnterReturnsTrue)) ok = true;
    if (ImGui::IsItemDeactivated() && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter))) ok = true;
    tooltip("A name in the folder above, or a whole path. The extension is added when missing.");
    ImGui::TextDisabled("%s files (%s)", kind.title, kind.extension);
  }
  if (!d.message.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.75f, 0.4f, 1.0f));
    ImGui::TextWrapped("%s", d.message.c_str());
    ImGui::PopStyleColor();
  }
  bool cancel = false;
  if (!d.confirmPath.empty()) {
    if (ImGui::Button("Replace")) submitFileDialog(state, true);
    ImGui::SameLine();
    if (ImGui::Button("Keep it")) {
      d.confirmPath.clear();
      d.message.clear();
    }
  } else {
    ok |= ImGui::Button("OK");
    ImGui::SameLine();
    cancel = ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape));
    if (ok) submitFileDialog(state);
  }
  if (cancel) cancelFileDialog(state);
  if (d.purpose == FileDialogPurpose::None) ImGui::CloseCurrentPopup();
  ImGui::EndPopup();
}

}  // namespace somicage::editor
