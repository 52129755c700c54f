#include "cage_maker.h"

#include <chrono>
#include <exception>

#include "app_state.h"
#include "errors.h"

namespace somicage::editor {

CageMaker::CageMaker(CageGenerator generator) : generator_(std::move(generator)) {}

CageMaker::~CageMaker() {
  wanted_ = 0;  // the running generation stops at its next progress check
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void CageMaker::setOnFinished(std::function<void()> onFinished) {
  std::lock_guard<std::mutex> lock(mutex_);
  onFinished_ = std::move(onFinished);
}

void CageMaker::setGenerator(CageGenerator generator) {
  std::lock_guard<std::mutex> lock(mutex_);
  generator_ = std::move(generator);
}

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
  const std::uint64_t id = nextId_++;
  wanted_ = id;
  progress_ = 0.0;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    pending_ = Job{id, vertices_, triangles_, source_, options};  // replaces a request not started yet
    if (!thread_.joinable()) thread_ = std::thread(&CageMaker::run, this);
  }
  wake_.notify_all();
}

void CageMaker::cancel() {
  if (status_ != Status::Generating) return;
  wanted_ = 0;
  status_ = Status::Cancelled;
}

void CageMaker::close() {
  wanted_ = 0;
  status_ = Status::Closed;
  candidate_.reset();
  ++candidateGeneration_;
  vertices_.reset();
  triangles_.reset();
}

void CageMaker::poll() {
  std::optional<Result> result;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    result.swap(result_);
  }
  if (!result || result->id != wanted_ || status_ != Status::Generating) return;  // superseded or cancelled
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

void CageMaker::wait() {
  {
    std::unique_lock<std::mutex> lock(mutex_);
    wake_.wait(lock, [&] { return wanted_ == 0 || (result_ && result_->id == wanted_); });
  }
  poll();
}

void CageMaker::run() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    wake_.wait(lock, [&] { return stopping_ || pending_.has_value(); });
    if (stopping_) return;
    const Job job = std::move(*pending_);
    pending_.reset();
    const CageGenerator generator = generator_;
    lock.unlock();
    Result result;
    result.id = job.id;
    const auto start = std::chrono::steady_clock::now();
    try {
      CageCandidate candidate;
      candidate.options = job.options;
      candidate.generated = generator(*job.vertices, *job.triangles, job.options, job.source, [&](double done) {
        if (wanted_ != job.id) return false;  // superseded, cancelled or closed
        progress_ = done;
        return true;
      });
      candidate.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      result.candidate = std::move(candidate);
    } catch (const Cancelled&) {
      result.cancelled = true;
    } catch (const std::exception& e) {
      result.error = e.what();
    }
    lock.lock();
    result_ = std::move(result);
    wake_.notify_all();
    if (onFinished_) {  // unlocked: the callback may take its own locks
      lock.unlock();
      onFinished_();
      lock.lock();
    }
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
