#include "jobs/measure_worker.h"

#include <chrono>
#include <exception>
#include <iterator>
#include <limits>
#include <new>
#include <utility>

#include "analysis/deformation_quantities.h"
#include "base/errors.h"
#include "deform/deform_choices.h"
#include "deform/deform_params.h"
#include "deform/memory_estimate.h"
#include "deform/parameter_schema.h"
#include "engine/engine.h"
#include "geometry/cage.h"
#include "geometry/integration_options.h"
#include "tetrahedralization/cage_tetrahedralization.h"

namespace somicage::editor {

namespace {

QuantitySource sourceOf(const MeasureView& v) { return quantityDescriptor(v.quantity).source; }

bool usesGradients(const MeasureView& v) { return sourceOf(v) == QuantitySource::Jacobian && v.deformer; }

bool measuresDifference(const MeasureView& v) {
  return sourceOf(v) == QuantitySource::Difference && v.deformer && v.otherDeformer;
}

MeasureKey::Params paramsKey(const DeformParams& p) { return parameterValues(p); }

std::vector<std::vector<int>> faceLists(const Eigen::MatrixXi& triangles) {
  std::vector<std::vector<int>> faces(static_cast<std::size_t>(triangles.rows()));
  for (Eigen::Index f = 0; f < triangles.rows(); ++f)
    faces[static_cast<std::size_t>(f)] = {triangles(f, 0), triangles(f, 1), triangles(f, 2)};
  return faces;
}

// The J bytes a request still has to allocate are refused before any is, when they would not fit.
void requireGradientMemory(const MeasureRequest& request, const std::vector<const CageDeformer*>& missing) {
  const Scene& scene = *request.scene;
  MemoryEstimate estimate;
  estimate.points = static_cast<std::size_t>(scene.meshVertices.rows());
  for (const CageDeformer* d : missing)
    estimate.gradients +=
        estimateGradientBytes(d->method(), scene.dim(), layoutVertices(d->method(), scene.restCage, d->volumeMesh().get()),
                              scene.restCage.numFaces(), estimate.points, /*floatStorage=*/true);
  requireMemory(estimate, availableMemoryBytes(), scene.isDemo() ? scene.name : scene.meshPath,
                "show shading only, or fewer compare views");
}

// A regular grid over the cage's bounding box, `count` points along its longer side (the arrows of a 2D field).
Eigen::MatrixXd arrowGrid(const Cage& cage, int count) {
  const Eigen::RowVector2d lo = cage.vertices.colwise().minCoeff(), hi = cage.vertices.colwise().maxCoeff();
  const double step = (hi - lo).maxCoeff() / count;
  const int nx = static_cast<int>((hi.x() - lo.x()) / step), ny = static_cast<int>((hi.y() - lo.y()) / step);
  Eigen::MatrixXd grid(static_cast<Eigen::Index>(nx) * ny, 2);
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      grid.row(static_cast<Eigen::Index>(i) * ny + j) << lo.x() + (i + 0.5) * step, lo.y() + (j + 0.5) * step;
  return grid;
}

}  // namespace

bool MeasureKey::operator==(const MeasureKey& o) const {
  return scene == o.scene && poseGeneration == o.poseGeneration && views == o.views && sweep == o.sweep;
}

MeasureKey measureKey(const MeasureRequest& r) {
  MeasureKey key;
  key.scene = r.scene.get();
  key.poseGeneration = r.poseGeneration;
  key.sweep = !r.sweepNus.empty();
  for (const MeasureView& v : r.views)
    key.views.emplace_back(v.deformer.get(), v.quantity, v.fieldVertex, v.fieldFace, paramsKey(v.params),
                           v.otherDeformer.get(), paramsKey(v.otherParams));
  return key;
}

bool needsWorker(const MeasureRequest& r) {
  if (!r.scene) return false;
  if (!r.sweepNus.empty()) return true;
  for (const MeasureView& v : r.views)
    if (usesGradients(v) || measuresDifference(v) || sourceOf(v) == QuantitySource::Field) return true;
  return false;
}

void MeasureWorker::start(MeasureRequest request) {
  std::shared_ptr<Caches> caches = caches_;
  job_.start([request = std::move(request),
              caches](JobContext& context) { return MeasureWorker::run(request, *caches, context); },
             job_.cores() - 1);  // the UI keeps a core for its frames
}

void MeasureWorker::release() {
  job_.cancel();  // a running job keeps the old caches until it ends; never waited for here
  caches_ = std::make_shared<Caches>();
}

std::size_t MeasureWorker::heldBytes() const {
  if (job_.busy()) return 0;
  std::size_t bytes = 0;
  for (const auto& [key, g] : caches_->gradients)
    bytes += (g.gradients ? g.gradients->bytes() : 0) + (g.seams ? g.seams->bytes() : 0);
  if (caches_->field)
    bytes += static_cast<std::size_t>(caches_->field->terms.size() + caches_->field->winding.size()) * sizeof(double);
  return bytes;
}

MeasureOutcome MeasureWorker::run(const MeasureRequest& request, Caches& caches, JobContext& context) {
  const auto t0 = std::chrono::steady_clock::now();
  MeasureOutcome out;
  out.key = measureKey(request);
  out.views.resize(request.views.size());
  try {
    if (context.cancelled()) throw Cancelled();  // superseded while it waited for its cores
    const Scene& scene = *request.scene;
    // Gradients no view of this request uses are freed first (memory), those missing made (the slow part).
    std::map<const CageDeformer*, Caches::Gradients> kept;
    std::vector<const CageDeformer*> missing;
    const bool sweep = !request.sweepNus.empty();
    for (std::size_t v = 0; v < request.views.size(); ++v) {
      const MeasureView& view = request.views[v];
      const bool wanted = sweep ? static_cast<int>(v) == request.sweepView && view.deformer : usesGradients(view);
      if (!wanted) continue;
      const CageDeformer* d = view.deformer.get();
      auto it = caches.gradients.find(d);
      if (it != caches.gradients.end()) {
        kept[d] = std::move(it->second);
        caches.gradients.erase(it);
      } else if (!kept.count(d)) {
        kept[d].deformer = view.deformer;
        kept[d].gradients = view.deformer->keptGradients();  // an export's, kept with the coordinates
        if (!kept[d].gradients) missing.push_back(d);
      }
    }
    for (const auto& [d, unused] : caches.gradients) unused.deformer->releaseGradients();
    caches.gradients = std::move(kept);
    if (!missing.empty()) requireGradientMemory(request, missing);
    for (std::size_t k = 0; k < missing.size(); ++k) {
      context.setStage("J setup " + std::to_string(k + 1) + "/" + std::to_string(missing.size()));
      const double n = static_cast<double>(missing.size());
      Caches::Gradients& g = caches.gradients[missing[k]];
      g.gradients = g.deformer->gradients(scene.meshVertices, context.span(0.8 * k / n, 0.8 * (k + 1) / n));
    }
    const std::vector<std::vector<int>> faces = faceLists(scene.meshTriangles);
    if (sweep) {
      context.setStage("nu sweep");
      const MeasureView& view = request.views[static_cast<std::size_t>(request.sweepView)];
      const DeformationGradients& gradients = *caches.gradients[view.deformer.get()].gradients;
      // The view's own parameters first (its volume line), then each variant's: nu never re-integrates, so a line
      // costs 25 evaluations of the same gradients; the view's own variant is not evaluated twice.
      const std::vector<VariantChoice>& variants = variantChoices();
      const double runs = request.sweepVariants ? 1.0 + static_cast<double>(variants.size()) : 1.0;
      out.sweep = sweepNu(gradients, scene.meshVertices, faces, request.pose, view.params, request.sweepNus,
                          context.span(0.8, 0.8 + 0.2 / runs));
      for (std::size_t k = 0; request.sweepVariants && k < variants.size(); ++k) {
        DeformParams params = view.params;
        params.kind = static_cast<VariantKind>(variants[k].kind);
        params.blend = variants[k].blend;
        context.setStage(std::string("nu sweep: ") + variants[k].name);
        const double at = 0.8 + 0.2 * static_cast<double>(k + 1) / runs;
        out.variantSweeps.push_back(
            {variants[k].name, params == view.params
                                   ? out.sweep
                                   : sweepNu(gradients, scene.meshVertices, faces, request.pose, params,
                                             request.sweepNus, context.span(at, at + 0.2 / runs))});
      }
    } else {
      for (std::size_t v = 0; v < request.views.size(); ++v) {
        const MeasureView& view = request.views[v];
        if (usesGradients(view) || measuresDifference(view)) {
          context.setStage("measuring view " + std::to_string(v + 1));
          if (!context.report(0.8 + 0.2 * static_cast<double>(v) / static_cast<double>(request.views.size())))
            throw Cancelled();
        }
        if (usesGradients(view)) {
          Caches::Gradients& g = caches.gradients[view.deformer.get()];
          if (quantityDescriptor(view.quantity).seams && !g.seams) {  // a second deformer at the crossings
            context.setStage("seams of view " + std::to_string(v + 1));
            PrecomputeOptions options;  // a smooth method's: the tetrahedra a Phong view of the scene would get
            options.volumeMesher = tetrahedralizeCageWithOptions;
            g.seams = prepareSeamJumps(*g.deformer, scene.restCage, scene.meshVertices, faces, options,
                                       scene.isDemo() ? scene.name : scene.meshPath);
          }
          const DeformationAnalysis a = analyzeDeformation(*g.gradients, scene.meshVertices, faces, request.pose,
                                                           view.params,
                                                           quantityDescriptor(view.quantity).seams ? g.seams.get()
                                                                                                   : nullptr);
          out.views[v] = jacobianMeasurement(a, scene.meshTriangles, view.quantity);
        } else if (measuresDifference(view)) {  // both views deformed here, at their own parameters
          ViewMeasurement m;
          m.points = view.deformer->deform(request.pose, view.params);
          m.values = pointDifference(m.points, view.otherDeformer->deform(request.pose, view.otherParams),
                                     cageDiameter(scene.restCage.vertices));
          out.views[v] = std::move(m);
        } else if (sourceOf(view) == QuantitySource::Field && (view.fieldVertex >= 0 || view.fieldFace >= 0)) {
          const ElementTerms::Kind kind = view.fieldVertex >= 0 ? ElementTerms::Kind::Vertex : ElementTerms::Kind::Face;
          const int index = view.fieldVertex >= 0 ? view.fieldVertex : view.fieldFace;
          if (caches.fieldScene != &scene || !caches.field || caches.field->kind != kind ||
              caches.field->index != index) {
            caches.field.reset();  // one element's terms at a time
            context.setStage(std::string("field of cage ") + (view.fieldVertex >= 0 ? "vertex " : "face ") +
                             std::to_string(index));
            IntegrationOptions options;
            caches.field =
                integrateElementTerms(scene.restCage, scene.meshVertices, kind, index, options, context.span(0.0, 0.9));
            if (scene.dim() == 2) {
              caches.fieldGrid = arrowGrid(scene.restCage, 28);
              caches.gridField = integrateElementTerms(scene.restCage, caches.fieldGrid, kind, index, options);
            }
            caches.fieldScene = &scene;
          }
          const Eigen::MatrixXd field = elementCoordinateField(*caches.field, view.params.nu);
          ViewMeasurement m;
          m.values = field.rowwise().norm();
          for (Eigen::Index p = 0; p < m.values.size(); ++p)  // Eq. 8 holds inside the cage only
            if (!(caches.field->winding[p] >= 0.5)) m.values[p] = std::numeric_limits<double>::quiet_NaN();
          if (scene.dim() == 2) {  // the arrows: grid points inside the polygon
            const Eigen::MatrixXd grid = elementCoordinateField(*caches.gridField, view.params.nu);
            std::vector<Eigen::Index> inside;
            for (Eigen::Index p = 0; p < grid.rows(); ++p)
              if (caches.gridField->winding[p] >= 0.5 && grid.row(p).allFinite()) inside.push_back(p);
            m.arrowPoints.resize(static_cast<Eigen::Index>(inside.size()), 2);
            m.arrowVectors.resize(static_cast<Eigen::Index>(inside.size()), 2);
            for (std::size_t k = 0; k < inside.size(); ++k) {
              m.arrowPoints.row(static_cast<Eigen::Index>(k)) = caches.fieldGrid.row(inside[k]);
              m.arrowVectors.row(static_cast<Eigen::Index>(k)) = grid.row(inside[k]);
            }
          }
          out.views[v] = std::move(m);
        }
      }
    }
    context.report(1.0);
  } catch (const Cancelled&) {
    out.cancelled = true;
  } catch (const std::bad_alloc&) {
    out.error = "out of memory while measuring the views (show shading only, or fewer compare views)";
    caches.gradients.clear();
  } catch (const std::exception& e) {
    out.error = e.what();
  }
  for (auto it = caches.gradients.begin(); it != caches.gradients.end();)  // a setup cut short holds nothing
    it = it->second.gradients ? std::next(it) : caches.gradients.erase(it);
  if (out.cancelled || !out.error.empty()) {
    out.views.assign(request.views.size(), std::nullopt);
    out.sweep.clear();
    out.variantSweeps.clear();
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace somicage::editor
