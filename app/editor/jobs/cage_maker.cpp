#include "jobs/cage_maker.h"

#include <chrono>
#include <exception>
#include <utility>

#include "animation/pose_timeline.h"
#include "base/errors.h"
#include "model/app_state.h"

namespace somicage::editor {

CageMaker::CageMaker(CageGenerator generator) : generator_(std::move(generator)) {}

void CageMaker::setOnFinished(std::function<void()> onFinished) { job_.setOnFinished(std::move(onFinished)); }

void CageMaker::setGenerator(CageGenerator generator) { generator_ = std::move(generator); }

void CageMaker::open(const Eigen::MatrixXd& vertices, const Eigen::MatrixXi& triangles, const std::string& source,
                     const CageGenerationOptions& options) {
  vertices_ = std::make_shared<const Eigen::MatrixXd>(vertices);
  triangles_ = std::make_shared<const Eigen::MatrixXi>(triangles);
  source_ = source;
  candidate_.reset();
  ++candidateGeneration_;
  start(options);
}

void CageMaker::request(const CageGenerationOptions& options) {
  if (isOpen()) start(options);
}

void CageMaker::start(const CageGenerationOptions& options) {
  options_ = options;
  status_ = Status::Generating;
  error_.clear();
  job_.start(
      [generator = generator_, vertices = vertices_, triangles = triangles_, source = source_,
       options](JobContext& context) {
        Result result;
        const auto start = std::chrono::steady_clock::now();
        try {
          if (context.cancelled()) throw Cancelled();  // superseded while it waited for its cores
          CageCandidate candidate;
          candidate.options = options;
          candidate.generated = generator(*vertices, *triangles, options, source, context.span(0.0, 1.0));
          candidate.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          result.candidate = std::move(candidate);
        } catch (const Cancelled&) {
          result.cancelled = true;
        } catch (const std::exception& e) {
          result.error = e.what();
        }
        return result;
      },
      job_.cores() - 1);  // the UI keeps a core: the dialog and the views stay live
}

void CageMaker::cancel() {
  if (status_ != Status::Generating) return;
  job_.cancel();
  status_ = Status::Cancelled;
}

void CageMaker::close() {
  job_.cancel();
  status_ = Status::Closed;
  candidate_.reset();
  ++candidateGeneration_;
  vertices_.reset();
  triangles_.reset();
}

void CageMaker::poll() {
  std::optional<Result> result = job_.poll();
  if (!result || status_ != Status::Generating) return;  // cancelled or closed since
  if (result->candidate) {
    candidate_ = std::move(result->candidate);
    ++candidateGeneration_;
    status_ = Status::Ready;
  } else if (result->cancelled) {
    status_ = Status::Cancelled;
  } else {
    error_ = result->error;
    status_ = Status::Failed;
  }
}

void openCageMaker(AppState& state, int faces) {
  if (!state.model.scene || state.loadingScene()) {
    state.status.errors.push_back("Make cage: wait until the scene has loaded");
    return;
  }
  if (state.model.scene->dim() != 3 || state.model.scene->meshTriangles.rows() == 0) {
    state.status.errors.push_back("Make cage needs a 3D mesh with faces; this scene's mesh has none");
    return;
  }
  CageGenerationOptions options = state.jobs.cageMaker.options();
  options.maxFaces = faces;
  state.jobs.cageMaker.open(state.model.scene->meshVertices, state.model.scene->meshTriangles, state.model.scene->name,
                            options);
}

bool acceptGeneratedCage(AppState& state) {
  if (!state.model.scene || !state.jobs.cageMaker.candidate()) return false;
  const GeneratedCage generated = state.jobs.cageMaker.candidate()->generated;
  state.jobs.cageMaker.close();
  state.animation.poses = PoseLibrary{};  // poses of the old cage's vertices
  state.animation.timeline.keys.clear();
  replaceRestCage(state, generated.cage);
  commitEdit(state, "Make cage");
  state.status.message = "made a cage of " + std::to_string(generated.cage.numFaces()) + " faces (undo: Ctrl+Z)";
  return true;
}

}  // namespace somicage::editor
