#include "gpu_deformer.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <numeric>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "base/errors.h"
#include "gl_compute.h"

namespace somicage::render {

namespace {

constexpr int kNormalGroup = 64;  // local_size_x of face_normals / vertex_normals.comp.glsl
constexpr int kBlendGroup = 64;   // local_size_x of exterior_blend.comp.glsl
constexpr int kQueryRing = 4;     // timer queries in flight before timing skips a frame

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

GLint64 glInteger64(GLenum name) {
  GLint64 value = 0;
  glGetInteger64v(name, &value);
  return value;
}

// Throws with `what` when the driver reports an error (used after the large, once-per-precompute upload, where an
// out-of-memory must not pass silently even without SOMICAGE_GL_DEBUG).
void throwOnGlError(const std::string& what) {
  const GLenum error = glGetError();
  if (error == GL_OUT_OF_MEMORY) throw std::runtime_error(what + ": the GPU is out of memory");
  if (error != GL_NO_ERROR) throw std::runtime_error(what + ": OpenGL error " + std::to_string(error));
}

// Groups for `groups` work groups: x up to the guaranteed minimum of GL_MAX_COMPUTE_WORK_GROUP_COUNT (65535),
// the rest in y (the shaders linearise gl_WorkGroupID).
void dispatchLinear(GLuint groups) {
  if (groups == 0) return;
  const GLuint x = std::min<GLuint>(groups, 65535u);
  glDispatchCompute(x, (groups + x - 1) / x, 1);
}

GLuint ceilDiv(std::size_t n, std::size_t d) { return static_cast<GLuint>((n + d - 1) / d); }

}  // namespace

struct GpuDeformer::Impl {
  GpuDeformerLayout layout;
  const CageDeformer* deformer = nullptr;
  int numPoints = 0, dim = 0, mainColumns = 0, tailColumns = 0;
  int numBlends = 0;  // exterior points #E: C has #P + 2 #E rows (core/deform/frame_evaluation.h)
  int rowEntries = 0;  // C in sparse rows (core/deform/coordinate_layout.h): the entries per row; 0: dense

  // Row chunks of C, each small enough for one storage block binding (GL_MAX_SHADER_STORAGE_BLOCK_SIZE) and
  // starting at an offset the driver accepts (GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT).
  struct Chunk {
    int first = 0, count = 0;
  };
  std::vector<Chunk> chunks;

  GlBuffer coordinates, weights, faceNormals, adjacencyOffsets, adjacencyFaces;
  GlBuffer entryColumns;  // sparse rows: each stored entry's column of C, laid out as `coordinates`
  GlBuffer blends, extraRows;  // the exterior blends (point, weight) and their proxy and anchor rows (2 #E by 3)
  std::vector<float> weightStaging;
  std::map<std::tuple<int, int, int, bool>, GlComputeProgram> kernels;  // (dim, outputs, mainOffset, sparse)
  std::unique_ptr<GlComputeProgram> facePass, vertexPass, blendPass;

  // The triangles the adjacency was built for (compared every frame: cheap next to the frame itself).
  Eigen::MatrixXi adjacencyTriangles;
  int adjacencyVertices = -1;

  std::array<GlQuery, kQueryRing> queries;
  std::array<bool, kQueryRing> pending{};
  int nextQuery = 0;
  bool finishTiming = false;  // software renderer: time with glFinish (see lastGpuMilliseconds)
  double lastCpuMs = std::numeric_limits<double>::quiet_NaN();
  double lastGpuMs = std::numeric_limits<double>::quiet_NaN();

  // The shader's FINISH is the frame's (core/deform/frame_finish.h); OUTPUTS follows from it.
  const GlComputeProgram& kernel(int d, FrameFinish finish, int mainOffset, bool sparse) {
    const int outputs = frameOutputs(finish, d);
    const auto key = std::make_tuple(d, outputs, mainOffset, sparse);
    auto it = kernels.find(key);
    if (it != kernels.end()) return it->second;
    const std::string defines = "#define DIM " + std::to_string(d) + "\n#define OUTPUTS " + std::to_string(outputs) +
                                "\n#define FINISH " + std::to_string(static_cast<int>(finish)) +
                                "\n#define MAIN_OFFSET " + std::to_string(mainOffset) + "\n#define ROW_THREADS " +
                                std::to_string(layout.rowThreads) + "\n#define GROUP_POINTS " +
                                std::to_string(layout.groupPoints) + "\n#define SPARSE " + (sparse ? "1" : "0") +
                                "\n";
    return kernels.try_emplace(key, "deform_frame.comp.glsl", defines).first->second;
  }

  // The vertex -> face adjacency (CSR, faces ascending per vertex; a face listed once per corner, as the CPU sum
  // in mesh_normals.cpp adds it) for `triangles` over `vertices` vertices. Faces with an index out of range are
  // left out, as on the CPU.
  void ensureAdjacency(const Eigen::MatrixXi& triangles, int vertices) {
    if (vertices == adjacencyVertices && triangles.rows() == adjacencyTriangles.rows() &&
        triangles.cols() == adjacencyTriangles.cols() &&
        std::memcmp(triangles.data(), adjacencyTriangles.data(),
                    sizeof(int) * static_cast<std::size_t>(triangles.size())) == 0) {
      return;
    }
    const Eigen::Index numFaces = triangles.rows();
    auto valid = [&](Eigen::Index f) {
      for (int c = 0; c < 3; ++c)
        if (triangles(f, c) < 0 || triangles(f, c) >= vertices) return false;
      return true;
    };
    std::vector<GLuint> offsets(static_cast<std::size_t>(vertices) + 1, 0);
    for (Eigen::Index f = 0; f < numFaces; ++f)
      if (valid(f))
        for (int c = 0; c < 3; ++c) ++offsets[static_cast<std::size_t>(triangles(f, c)) + 1];
    std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
    std::vector<GLuint> faces(std::max<std::size_t>(offsets.back(), 1), 0), fill(offsets.begin(), offsets.end() - 1);
    for (Eigen::Index f = 0; f < numFaces; ++f)
      if (valid(f))
        for (int c = 0; c < 3; ++c) faces[fill[static_cast<std::size_t>(triangles(f, c))]++] = static_cast<GLuint>(f);
    adjacencyOffsets.upload(GL_SHADER_STORAGE_BUFFER, offsets.data(), sizeof(GLuint) * offsets.size(), GL_STATIC_DRAW);
    adjacencyFaces.upload(GL_SHADER_STORAGE_BUFFER, faces.data(), sizeof(GLuint) * faces.size(), GL_STATIC_DRAW);
    const std::size_t faceBytes = sizeof(float) * 3 * static_cast<std::size_t>(std::max<Eigen::Index>(numFaces, 1));
    if (faceNormals.size() != faceBytes)
      faceNormals.upload(GL_SHADER_STORAGE_BUFFER, nullptr, faceBytes, GL_DYNAMIC_COPY);
    throwOnGlError("uploading the mesh adjacency for the GPU normals");
    adjacencyTriangles = triangles;
    adjacencyVertices = vertices;
  }

  void collectQueries() {
    // In issue order: the oldest pending query finishes first.
    for (int i = 0; i < kQueryRing; ++i) {
      const int q = (nextQuery + i) % kQueryRing;
      if (!pending[static_cast<std::size_t>(q)]) continue;
      GLint available = GL_FALSE;
      glGetQueryObjectiv(queries[static_cast<std::size_t>(q)].id(), GL_QUERY_RESULT_AVAILABLE, &available);
      if (available != GL_TRUE) break;
      GLuint64 nanoseconds = 0;
      glGetQueryObjectui64v(queries[static_cast<std::size_t>(q)].id(), GL_QUERY_RESULT, &nanoseconds);
      lastGpuMs = static_cast<double>(nanoseconds) * 1e-6;
      pending[static_cast<std::size_t>(q)] = false;
    }
  }
};

bool GpuDeformer::available(std::string* reason) {
  auto fail = [&](const std::string& why) {
    if (reason) *reason = why;
    return false;
  };
  if (!GLAD_GL_VERSION_4_3) {
    const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    return fail(std::string("the OpenGL context is ") + (version ? version : "unknown") +
                "; compute shaders need OpenGL 4.3 (update the graphics driver; Mesa's llvmpipe has them)");
  }
  GLint invocations = 0;
  glGetIntegerv(GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS, &invocations);
  if (invocations < 256)
    return fail("the driver allows only " + std::to_string(invocations) + " compute invocations per group");
  if (reason) reason->clear();
  return true;
}

bool GpuDeformer::softwareRenderer() {
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const std::string name = renderer ? renderer : "";
  return name.find("llvmpipe") != std::string::npos || name.find("softpipe") != std::string::npos ||
         name.find("SwiftShader") != std::string::npos;
}

// Measured on FIREHYDRANT (39k points; C 880 columns for Somigliana, 143 for Green) with Mesa 22.3 llvmpipe on two
// cores, median frame in ms (global Somigliana / local Somigliana / Green), invocations per point x points per group:
//   1 x 64: 1664 / 4960 / 280    4 x 64: 776 / 2028 / 146    8 x 32: 600 / 1475 / 123
//   16 x 16: 820 / 1640 / 193    32 x 8: 1391 / 1144 / 350
// (W staged through shared memory with one invocation per point was slower still: 4563 / 9416.) llvmpipe runs
// the invocations of a group as SIMD lanes of one CPU thread, so neither coalescing nor shared memory pays off
// there; on GPUs a warp of 32 reading one row of C is the coalesced pattern, and W stays in the cache.
GpuDeformerLayout GpuDeformer::chooseLayout() {
  GpuDeformerLayout layout;
  const bool software = softwareRenderer();
  layout.rowThreads = software ? 8 : 32;
  layout.groupPoints = software ? 32 : 8;
  return layout;
}

GpuDeformer::GpuDeformer(GpuDeformerLayout layout) : impl_(std::make_unique<Impl>()) {
  std::string reason;
  if (!available(&reason)) throw std::runtime_error("GPU deformer: " + reason);
  const GpuDeformerLayout automatic = chooseLayout();
  if (layout.rowThreads <= 0) layout.rowThreads = automatic.rowThreads;
  if (layout.groupPoints <= 0)
    layout.groupPoints =
        layout.rowThreads == automatic.rowThreads ? automatic.groupPoints : std::max(1, 256 / layout.rowThreads);
  if (layout.rowThreads > 64 || (layout.rowThreads & (layout.rowThreads - 1)) != 0)
    throw std::invalid_argument("GpuDeformer: rowThreads must be a power of two <= 64");
  if (layout.rowThreads * layout.groupPoints > 256)
    throw std::invalid_argument("GpuDeformer: rowThreads x groupPoints must be <= 256");
  impl_->layout = layout;
  impl_->finishTiming = softwareRenderer();
}

GpuDeformer::~GpuDeformer() = default;
GpuDeformer::GpuDeformer(GpuDeformer&&) noexcept = default;
GpuDeformer& GpuDeformer::operator=(GpuDeformer&&) noexcept = default;

GpuDeformerLayout GpuDeformer::layout() const { return impl_->layout; }
bool GpuDeformer::uploaded() const { return impl_->deformer != nullptr; }
int GpuDeformer::numPoints() const { return impl_->numPoints; }

void GpuDeformer::upload(const CageDeformer& deformer) {
  Impl& m = *impl_;
  m.deformer = nullptr;
  const FrameCoordinates& C = deformer.frameCoordinates();
  // A sparse C (core/deform/coordinate_layout.h) is stored as its entries per row, their columns in a second buffer of
  // the same layout: the chunks below fit both.
  const int rows = C.rows(), columns = C.columns(), stored = C.storedColumns();

  // ---- chunks that fit one storage block binding each ----
  const std::size_t rowBytes = sizeof(float) * static_cast<std::size_t>(std::max(stored, 1));
  const std::size_t maxBlock = static_cast<std::size_t>(glInteger64(GL_MAX_SHADER_STORAGE_BLOCK_SIZE));
  GLint alignment = 1;
  glGetIntegerv(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT, &alignment);
  const std::size_t align = static_cast<std::size_t>(std::max(alignment, 1));
  const std::size_t rowStep = align / std::gcd(rowBytes, align);  // chunk starts at multiples of this many rows
  const std::size_t chunkRows = (maxBlock / rowBytes) / rowStep * rowStep;
  if (chunkRows == 0) {
    throw std::runtime_error("GPU deformer: one row of coordinates (" + std::to_string(rowBytes) +
                             " bytes) exceeds the driver's storage block limit of " + std::to_string(maxBlock) +
                             " bytes");
  }
  m.chunks.clear();
  for (std::size_t first = 0; first < static_cast<std::size_t>(rows); first += chunkRows)
    m.chunks.push_back(
        {static_cast<int>(first), static_cast<int>(std::min(chunkRows, static_cast<std::size_t>(rows) - first))});

  // ---- C in float, once ----
  const std::size_t bytes = sizeof(float) * static_cast<std::size_t>(rows) * static_cast<std::size_t>(stored);
  for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i) {
  }  // stale errors of earlier calls are not this upload's
  if (C.isFloat()) {
    m.coordinates.upload(GL_SHADER_STORAGE_BUFFER, C.floats.data(), bytes, GL_STATIC_DRAW);
  } else {
    // Convert in slices of rows, so the float copy never doubles the host memory.
    m.coordinates.upload(GL_SHADER_STORAGE_BUFFER, nullptr, bytes, GL_STATIC_DRAW);
    const int sliceRows = std::max(1, (1 << 22) / std::max(stored, 1));
    CoordinateMatrix<float> slice;
    for (int first = 0; first < rows; first += sliceRows) {
      const int count = std::min(sliceRows, rows - first);
      slice = C.doubles.middleRows(first, count).cast<float>();
      glBufferSubData(GL_SHADER_STORAGE_BUFFER, static_cast<GLintptr>(rowBytes * static_cast<std::size_t>(first)),
                      static_cast<GLsizeiptr>(sizeof(float) * static_cast<std::size_t>(slice.size())), slice.data());
    }
  }
  static_assert(sizeof(std::int32_t) == sizeof(float), "an entry's column takes the bytes of its value");
  if (C.isSparse())  // non-negative int32 columns read as the shader's uint
    m.entryColumns.upload(GL_SHADER_STORAGE_BUFFER, C.entryColumns.data(), bytes, GL_STATIC_DRAW);
  else
    m.entryColumns = GlBuffer();
  // ---- the exterior blends, and room for their rows (never a 0-byte buffer) ----
  struct GpuBlend {
    GLuint point;
    float weight;
  };
  std::vector<GpuBlend> blends(std::max<std::size_t>(C.exteriorBlends.size(), 1), GpuBlend{0, 0.0f});
  for (std::size_t e = 0; e < C.exteriorBlends.size(); ++e)
    blends[e] = {static_cast<GLuint>(C.exteriorBlends[e].point), static_cast<float>(C.exteriorBlends[e].weight)};
  m.blends.upload(GL_SHADER_STORAGE_BUFFER, blends.data(), sizeof(GpuBlend) * blends.size(), GL_STATIC_DRAW);
  m.extraRows.upload(GL_SHADER_STORAGE_BUFFER, nullptr, sizeof(float) * 6 * blends.size(), GL_DYNAMIC_COPY);
  throwOnGlError("uploading " + std::to_string(bytes >> 20) + " MiB of coordinates to the GPU");
  m.numPoints = C.numPoints();
  m.numBlends = static_cast<int>(C.exteriorBlends.size());
  m.dim = deformer.dim();
  m.mainColumns = C.mainColumns;
  m.tailColumns = columns - C.mainColumns;
  m.rowEntries = C.isSparse() ? stored : 0;
  m.deformer = &deformer;
}

void GpuDeformer::deform(const Eigen::MatrixXd& posedVertices, const DeformParams& params, MeshRenderer& target) {
  if (!impl_->deformer) throw std::logic_error("GpuDeformer::deform before upload()");
  const Clock::time_point t0 = Clock::now();
  submit(impl_->deformer->frameWeights(posedVertices, params), target, t0);
}

void GpuDeformer::deform(const FrameWeights& W, MeshRenderer& target) {
  if (!impl_->deformer) throw std::logic_error("GpuDeformer::deform before upload()");
  submit(W, target, Clock::now());
}

void GpuDeformer::submit(const FrameWeights& W, MeshRenderer& target, std::chrono::steady_clock::time_point t0) {
  Impl& m = *impl_;
  m.collectQueries();

  // ---- W (small) on the CPU, as float, row-major: W_main then W_tail ----
  const int d = m.dim, mainOutputs = W.outputs - W.mainOffset;
  SOMICAGE_ASSERT(W.outputs == frameOutputs(W.finish, d), "a frame has the outputs of its finish");
  SOMICAGE_ASSERT(W.main.rows() == m.mainColumns && W.main.cols() == mainOutputs, "W_main shape");
  SOMICAGE_ASSERT(W.tail.rows() == m.tailColumns && (m.tailColumns == 0 || W.tail.cols() == W.outputs), "W_tail shape");
  m.weightStaging.resize(static_cast<std::size_t>(W.main.size() + W.tail.size()) + 1);  // +1: never a 0-byte buffer
  std::size_t at = 0;
  for (Eigen::Index k = 0; k < W.main.rows(); ++k)
    for (Eigen::Index j = 0; j < W.main.cols(); ++j) m.weightStaging[at++] = static_cast<float>(W.main(k, j));
  for (Eigen::Index k = 0; k < W.tail.rows(); ++k)
    for (Eigen::Index j = 0; j < W.tail.cols(); ++j) m.weightStaging[at++] = static_cast<float>(W.tail(k, j));

  const MeshRenderer::DeviceBuffers out = target.deviceBuffers(m.numPoints);
  const Clock::time_point submitted = Clock::now();
  const int query = m.nextQuery;
  const bool timed = !m.finishTiming && !m.pending[static_cast<std::size_t>(query)];
  if (timed) glBeginQuery(GL_TIME_ELAPSED, m.queries[static_cast<std::size_t>(query)].id());
  m.weights.upload(GL_SHADER_STORAGE_BUFFER, m.weightStaging.data(), sizeof(float) * m.weightStaging.size(),
                   GL_STREAM_DRAW);

  // ---- pass 1: positions ----
  const GlComputeProgram& kernel = m.kernel(d, W.finish, W.mainOffset, m.rowEntries > 0);
  kernel.use();
  glUniform1ui(kernel.uniform("uMainColumns"), static_cast<GLuint>(m.mainColumns));
  glUniform1ui(kernel.uniform("uTailColumns"), static_cast<GLuint>(m.tailColumns));
  if (m.rowEntries > 0) glUniform1ui(kernel.uniform("uRowEntries"), static_cast<GLuint>(m.rowEntries));
  glUniform1ui(kernel.uniform("uMeshPoints"), static_cast<GLuint>(m.numPoints));
  float origin[3] = {0, 0, 0};
  for (int a = 0; a < d && a < W.origin.size(); ++a) origin[a] = static_cast<float>(W.origin(a));
  glUniform3f(kernel.uniform("uOrigin"), origin[0], origin[1], origin[2]);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, m.weights.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, out.positions);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, m.extraRows.id());
  const std::size_t rowBytes =
      sizeof(float) * static_cast<std::size_t>(m.rowEntries > 0 ? m.rowEntries : m.mainColumns + m.tailColumns);
  for (const Impl::Chunk& chunk : m.chunks) {
    if (rowBytes > 0) {
      const auto offset = static_cast<GLintptr>(rowBytes * static_cast<std::size_t>(chunk.first));
      const auto size = static_cast<GLsizeiptr>(rowBytes * static_cast<std::size_t>(chunk.count));
      glBindBufferRange(GL_SHADER_STORAGE_BUFFER, 0, m.coordinates.id(), offset, size);
      if (m.rowEntries > 0) glBindBufferRange(GL_SHADER_STORAGE_BUFFER, 4, m.entryColumns.id(), offset, size);
    }
    glUniform1ui(kernel.uniform("uFirstPoint"), static_cast<GLuint>(chunk.first));
    glUniform1ui(kernel.uniform("uNumPoints"), static_cast<GLuint>(chunk.count));
    dispatchLinear(ceilDiv(static_cast<std::size_t>(chunk.count), static_cast<std::size_t>(m.layout.groupPoints)));
  }

  // ---- pass 2: exterior points, x~ = S(x) + w (phi(x_in) - S(x_in)) ----
  if (m.numBlends > 0) {
    if (!m.blendPass) m.blendPass = std::make_unique<GlComputeProgram>("exterior_blend.comp.glsl");
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    m.blendPass->use();
    glUniform1ui(m.blendPass->uniform("uNumBlends"), static_cast<GLuint>(m.numBlends));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, m.blends.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, m.extraRows.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, out.positions);
    dispatchLinear(ceilDiv(static_cast<std::size_t>(m.numBlends), kBlendGroup));
  }

  // ---- passes 3 and 4: smooth vertex normals ----
  const Eigen::MatrixXi& triangles = target.triangles();
  m.ensureAdjacency(triangles, m.numPoints);
  if (!m.facePass) m.facePass = std::make_unique<GlComputeProgram>("face_normals.comp.glsl");
  if (!m.vertexPass) m.vertexPass = std::make_unique<GlComputeProgram>("vertex_normals.comp.glsl");
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  if (triangles.rows() > 0) {
    m.facePass->use();
    glUniform1ui(m.facePass->uniform("uNumFaces"), static_cast<GLuint>(triangles.rows()));
    glUniform1ui(m.facePass->uniform("uNumVertices"), static_cast<GLuint>(m.numPoints));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, out.positions);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.triangles);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, m.faceNormals.id());
    dispatchLinear(ceilDiv(static_cast<std::size_t>(triangles.rows()), kNormalGroup));
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  m.vertexPass->use();
  glUniform1ui(m.vertexPass->uniform("uNumVertices"), static_cast<GLuint>(m.numPoints));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, m.faceNormals.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, m.adjacencyOffsets.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, m.adjacencyFaces.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, out.normals);
  dispatchLinear(ceilDiv(static_cast<std::size_t>(m.numPoints), kNormalGroup));

  // The draw reads both as vertex attributes; readBack() reads them with glGetBufferSubData.
  glMemoryBarrier(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  for (GLuint binding = 0; binding < 5; ++binding) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, 0);
  glUseProgram(0);
  if (timed) {
    glEndQuery(GL_TIME_ELAPSED);
    m.pending[static_cast<std::size_t>(query)] = true;
    m.nextQuery = (query + 1) % kQueryRing;
  }
  SOMICAGE_GL_CHECK("GpuDeformer::deform");
  m.lastCpuMs = millisecondsSince(t0);
  if (m.finishTiming) {
    glFinish();
    m.lastGpuMs = millisecondsSince(submitted);
  }
}

namespace {
Eigen::MatrixXd readFloats(unsigned int buffer, int rows, int keepColumns) {
  std::vector<float> data(static_cast<std::size_t>(rows) * 3);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glBindBuffer(GL_COPY_READ_BUFFER, buffer);
  glGetBufferSubData(GL_COPY_READ_BUFFER, 0, static_cast<GLsizeiptr>(sizeof(float) * data.size()), data.data());
  glBindBuffer(GL_COPY_READ_BUFFER, 0);
  SOMICAGE_GL_CHECK("GpuDeformer::readBack");
  Eigen::MatrixXd out(rows, keepColumns);
  for (int p = 0; p < rows; ++p)
    for (int c = 0; c < keepColumns; ++c) out(p, c) = data[static_cast<std::size_t>(3 * p + c)];
  return out;
}
}  // namespace

Eigen::MatrixXd GpuDeformer::readBack(MeshRenderer& target) const {
  return readFloats(target.deviceBuffers(impl_->numPoints).positions, impl_->numPoints, impl_->dim);
}

Eigen::MatrixXd GpuDeformer::readBackNormals(MeshRenderer& target) const {
  return readFloats(target.deviceBuffers(impl_->numPoints).normals, impl_->numPoints, 3);
}

double GpuDeformer::lastCpuMilliseconds() const { return impl_->lastCpuMs; }

double GpuDeformer::lastGpuMilliseconds() {
  impl_->collectQueries();
  return impl_->lastGpuMs;
}

}  // namespace somicage::render
