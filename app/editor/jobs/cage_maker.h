// File > Make cage...: generates candidate cages for the scene's mesh on a worker thread
// (core/generation/cage_generation.h), one at a time, and makes the accepted one the scene's cage as one undo step. The
// dialog (cage_maker_panel.h) and the renderer's preview read it; no GL, no ImGui.
//
// A new request (the face-count slider moved) supersedes the running one (background_job.h): its progress callback
// asks it to stop at its next check, and the newest request runs after it, so the UI never waits for a generation to
// end. A superseded or cancelled generation never shows its result.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "base/progress.h"
#include "generation/cage_generation.h"
#include "jobs/background_job.h"

namespace somicage::editor {

struct AppState;

// What the dialog shows of a generated cage.
struct CageCandidate {
  GeneratedCage generated;  // the cage and how it was made
  CageGenerationOptions options;
  double seconds = 0.0;  // wall time of the generation
};

// The generator the worker runs (generateCage; tests substitute one they control).
using CageGenerator = std::function<GeneratedCage(const Eigen::MatrixXd& vertices, const Eigen::MatrixXi& triangles,
                                                  const CageGenerationOptions& options, const std::string& source,
                                                  const ProgressCallback& progress)>;

class CageMaker {
 public:
  enum class Status { Closed, Generating, Ready, Failed, Cancelled };

  explicit CageMaker(CageGenerator generator = generateCage);

  void setGenerator(CageGenerator generator);  // tests; only while closed and idle
  // Called on the job's thread after each generation's result is stored (background_job.h); set it before open().
  void setOnFinished(std::function<void()> onFinished);

  // Opens the dialog for a mesh (#V by 3, #T by 3; source names it in errors) and generates with `options`.
  void open(const Eigen::MatrixXd& vertices, const Eigen::MatrixXi& triangles, const std::string& source,
            const CageGenerationOptions& options);
  // Generates again with other options; the running generation is abandoned. Ignored while closed.
  void request(const CageGenerationOptions& options);
  void cancel();  // stops the running generation (status Cancelled); the dialog stays open
  void close();   // cancels and closes; the scene is untouched

  // Takes the worker's finished result, if it is the latest request's. Call once per frame.
  void poll();
  bool busy() const { return job_.busy(); }  // the latest request runs (poll() takes its result once it has ended)

  Status status() const { return status_; }
  bool isOpen() const { return status_ != Status::Closed; }
  double progress() const { return job_.progress(); }  // of the running generation, 0..1
  const CageGenerationOptions& options() const { return options_; }
  // The latest finished cage (kept while a newer one is generated, so the preview does not blink); empty before.
  const std::optional<CageCandidate>& candidate() const { return candidate_; }
  const std::string& error() const { return error_; }  // Status::Failed: why
  // Bumps when candidate() changes (the renderer re-uploads the preview).
  std::uint64_t candidateGeneration() const { return candidateGeneration_; }

 private:
  struct Result {
    std::optional<CageCandidate> candidate;
    std::string error;
    bool cancelled = false;
  };
  void start(const CageGenerationOptions& options);

  CageGenerator generator_;
  Status status_ = Status::Closed;
  CageGenerationOptions options_;
  std::optional<CageCandidate> candidate_;
  std::string error_;
  std::uint64_t candidateGeneration_ = 0;
  std::shared_ptr<const Eigen::MatrixXd> vertices_;
  std::shared_ptr<const Eigen::MatrixXi> triangles_;
  std::string source_;
  BackgroundJob<Result> job_;  // last: its destructor stops the generation first
};

// File > Make cage...: opens the dialog for the scene's mesh (3D scenes) with the given face count.
void openCageMaker(AppState& state, int faces);
// Accept: the candidate becomes the scene's cage, at rest, as one undo step ("Make cage"); the pose library and the
// timeline are cleared (their poses belong to the old cage; undo restores them). Closes the dialog. Returns false when
// there is no candidate.
bool acceptGeneratedCage(AppState& state);

}  // namespace somicage::editor
