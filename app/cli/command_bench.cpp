// somicage bench: precompute and per-frame timings, accuracy, and the speed-up over the paper's quadrature rule,
// measured on one mesh and cage (median of repeated runs). The same engine calls as the editor: float storage of
// the coordinates, the CPU frame kernel, and every other frame device the executable offers (OpenGL, CUDA).
#include <omp.h>
#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <numeric>
#include <random>

#include "analysis/deformation_analysis.h"
#include "analysis/deformation_quantities.h"
#include "base/cpu_dispatch.h"
#include "cli/arg_parser.h"
#include "cli/cli.h"
#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/json_writer.h"
#include "cli/progress_reporter.h"
#include "coordinates/bem_system.h"
#include "coordinates/elastic_steiner_solve.h"
#include "coordinates/somigliana_coordinates.h"
#include "deform/jacobian.h"
#include "io/obj_io.h"
#include "methods/method_descriptors.h"

namespace somicage {

namespace {

const char* const kCommand = "somicage bench";

ArgParser benchOptions() {
  std::vector<OptionSpec> options{
      {"--mesh", "M.obj", "the points to deform (any readable format)", true},
      {"--cage", "C.obj", "the rest cage", true},
      {"--posed", "P.obj", "a posed cage (default: the rest cage bent and twisted)"},
      {"--frames", "N", "frames timed per backend and variant (default 50)"},
      {"--repeat", "R", "precomputes timed (default 3)"},
      {"--baseline-quadrature", "N", "the paper's rule: 3 N^2 points per triangle (default 50)"},
      {"--baseline-points", "K", "mesh vertices both integrators are timed on (default 2000)"},
      {"--scale-points", "N",
       "also time one precompute of N points: the mesh's vertices repeated, each copy after the first jittered by "
       "up to 0.2% of their bounding box's diagonal (scale_precompute_s; default 0: not timed)"},
      weldOptionSpec(),
      threadsOptionSpec(),
      {"--json", "", "print one JSON object"},
      {"--method", "NAME",
       "time only this method's frame (deform_ms.cpu_NAME; phong: and phong_factor_ms) besides Somigliana's, "
       "which every run times (default: every method)"},
  };
  const std::vector<OptionSpec> methodOptions = methodOptionSpecs();  // Phong's --tets, --tet-level
  options.insert(options.end(), methodOptions.begin(), methodOptions.end());
  return ArgParser(kCommand, options);
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n == 0 ? 0.0 : (n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]));
}

// A smooth pose for meshes given without one: bend about the cage's longest axis plus a twist.
Eigen::MatrixXd defaultPose(const Cage& cage) {
  const Eigen::RowVectorXd low = cage.vertices.colwise().minCoeff(), high = cage.vertices.colwise().maxCoeff();
  Eigen::Index axis;
  (high - low).maxCoeff(&axis);
  const int other = (axis + 1) % cage.dim();
  Eigen::MatrixXd posed = cage.vertices;
  const double length = high(axis) - low(axis);
  for (int i = 0; i < posed.rows(); ++i) {
    const double t = (cage.vertices(i, axis) - low(axis)) / length;
    posed(i, other) += 0.25 * length * t * t;
  }
  return posed;
}

// Median per-frame milliseconds of deform() for the posed cage and params.
double timeFrames(const CageDeformer& deformer, const Eigen::MatrixXd& posed, DeformParams params, int frames,
                  bool alternateNu) {
  Eigen::MatrixXd out;
  deformer.deform(posed, params, out);  // warm-up: first touch of the output
  std::vector<double> times;
  for (int f = 0; f < frames; ++f) {
    if (alternateNu) params.nu = (f % 2) ? 0.1 : 0.4;
    const CliClock::time_point start = CliClock::now();
    deformer.deform(posed, params, out);
    times.push_back(1e3 * secondsSince(start));
  }
  return median(times);
}

// Median per-frame milliseconds on a frame device: the weights built on the host, C already on the device, the
// points copied back (what a frame costs an application that uses the result on the CPU).
double timeEvaluatorFrames(const CageDeformer& deformer, FrameEvaluator& evaluator, const Eigen::MatrixXd& posed,
                           const DeformParams& params, int frames) {
  Eigen::MatrixXd out;
  evaluator.evaluate(deformer.frameWeights(posed, params), out);  // warm-up: weight buffer and kernel load
  std::vector<double> times;
  for (int f = 0; f < frames; ++f) {
    const CliClock::time_point start = CliClock::now();
    evaluator.evaluate(deformer.frameWeights(posed, params), out);
    times.push_back(1e3 * secondsSince(start));
  }
  return median(times);
}

// N points from the mesh's: its vertices, then copies of them each moved by up to 0.2% of their bounding box's
// diagonal per coordinate (the set tests/scale/make_million_points.py writes to a file, from another generator).
Eigen::MatrixXd scalePoints(const Eigen::MatrixXd& vertices, int count) {
  const double jitter = 0.002 * (vertices.colwise().maxCoeff() - vertices.colwise().minCoeff()).norm();
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> offset(-jitter, jitter);
  Eigen::MatrixXd points(count, vertices.cols());
  for (int k = 0; k < count; ++k)
    for (int a = 0; a < vertices.cols(); ++a)
      points(k, a) = vertices(k % vertices.rows(), a) + (k < vertices.rows() ? 0.0 : offset(rng));
  return points;
}

// Bytes per second of a large memcpy: the bandwidth a frame that streams the coordinates can hope for.
double copyBandwidth(std::size_t bytes) {
  std::vector<char> a(bytes, 1), b(bytes);
  std::vector<double> times;
  for (int r = 0; r < 5; ++r) {
    const CliClock::time_point start = CliClock::now();
    std::copy(a.begin(), a.end(), b.begin());
    times.push_back(secondsSince(start));
  }
  volatile char sink = b[bytes / 2];
  (void)sink;
  return 2.0 * bytes / median(times);  // read + write
}

}  // namespace

std::string benchUsage() {
  return std::string("usage: ") + kCommand +
         " --mesh M.obj --cage C.obj [options]\n\n"
         "Times the Somigliana precompute (median of --repeat runs) and the per-frame deformation (median of\n"
         "--frames frames) for the global and local variants on the CPU, and on the GPU when available; measures\n"
         "the partition of unity; and compares the closed-form integrals with the paper's Gauss rule on\n"
         "--baseline-points random mesh vertices.\n\noptions:\n" +
         benchOptions().optionHelp();
}

int runBenchCommand(const std::vector<std::string>& args, const FrameDevices& devices, CommandLog& log) {
  ArgParser options = benchOptions();
  options.parse(args);
  if (options.helpRequested()) {
    std::cout << benchUsage();
    return kExitOk;
  }
  const int frames = options.integer("--frames", 50, 1, 100000);
  const int repeat = options.integer("--repeat", 3, 1, 1000);
  const int quadrature = options.integer("--baseline-quadrature", 50, 1, 200);
  const int baselinePoints = options.integer("--baseline-points", 2000, 0, 1 << 30);
  const int scaleCount = options.integer("--scale-points", 0, 0, 1 << 30);
  const int threads = threadsOption(options);
  const bool json = options.has("--json");
  // --method: that method's frame only (checked before any work), besides Somigliana's.
  const bool everyMethod = !options.has("--method");
  const Method only = methodOption(options);

  const ReadOptions read = readOptions(options);
  const Cage cage = loadUsableCage(options.text("--cage"), log.sink(), read);
  const PolygonMesh mesh = loadAnyMesh(options.text("--mesh"), read);
  const Eigen::MatrixXd points =
      meshPointsFor(cage, mesh.vertices, options.text("--mesh"), options.text("--cage"), log.sink());
  const Eigen::MatrixXd posed =
      options.has("--posed") ? loadPosedVertices(options.text("--posed"), cage, read) : defaultPose(cage);
  PrecomputeOptions precompute = precomputeOptions(threads);
  precompute.floatStorage = true;
  applyMethodOptions(options, methods::somigliana(), cage, precompute, log.sink());

  // Precompute as the editor does: exact integrals, stored in float.
  const Method somigliana = methods::somigliana();
  std::vector<double> precomputeTimes;
  std::unique_ptr<CageDeformer> deformer;
  for (int r = 0; r < repeat; ++r) {
    deformer.reset();
    ProgressReporter progress("precompute " + std::to_string(r + 1) + "/" + std::to_string(repeat));
    const CliClock::time_point start = CliClock::now();
    deformer = somicage::precompute(somigliana, cage, points, precompute, options.text("--mesh"), progress.callback(),
                                    commandMemoryCheck(log));
    precomputeTimes.push_back(secondsSince(start));
  }
  std::vector<double> unity;
  const PrecomputeDiagnostics& diagnostics = deformer->diagnostics();
  for (int p = 0; p < deformer->numPoints(); ++p)
    if (diagnostics.winding(p) >= 0.5) unity.push_back(diagnostics.unityResidual(p));

  // Frames.
  std::vector<std::pair<std::string, double>> deformMs;
  deformMs.emplace_back("cpu_global", timeFrames(*deformer, posed, {0.0, 0.3, 1.0, true}, frames, false));
  deformMs.emplace_back("cpu_local", timeFrames(*deformer, posed, {1.0, 0.3, 1.0, true}, frames, false));
  DeformParams stable{1.0, 0.3, 1.0, true};  // the fold check's cost: its samples made before the timed frames
  stable.kind = VariantKind::Stable;
  deformMs.emplace_back("cpu_stable", timeFrames(*deformer, posed, stable, frames, false));
  // The other devices of this executable (the CPU is timed above, through deform() as the CPU front ends run it).
  std::string deviceNotes;
  for (const FrameDevice& device : devices) {
    if (device.name == "cpu") continue;
    try {
      const std::unique_ptr<FrameEvaluator> evaluator = device.make(*deformer);
      for (const auto& [variant, blend] : {std::pair<const char*, double>{"_global", 0.0}, {"_local", 1.0}})
        deformMs.emplace_back(device.benchKey + variant,
                              timeEvaluatorFrames(*deformer, *evaluator, posed, {blend, 0.3, 1.0, true}, frames));
    } catch (const std::exception& e) {  // no device, no context, or out of its memory: the other timings stand
      deviceNotes += (deviceNotes.empty() ? "" : "; ") + device.name + " skipped (" + e.what() + ")";
    }
  }
  const double nuUpdateMs = timeFrames(*deformer, posed, {1.0, 0.3, 1.0, true}, frames, true);

  // The editor's det J view: the gradients integrated once, then per update positions, J and det J / distortion.
  double gradientSeconds = 0;
  std::size_t gradientBytes = 0;
  std::vector<std::pair<std::string, double>> analyzeMs;
  double editorMeasureMs = 0;
  {
    ProgressReporter progress("coordinate gradients");
    const CliClock::time_point start = CliClock::now();
    const DeformationGradients gradients(*deformer, points, progress.callback());
    gradientSeconds = secondsSince(start);
    gradientBytes = gradients.bytes();
    progress.finish();
    for (const auto& [name, blend] : {std::pair<const char*, double>{"cpu_global", 0.0}, {"cpu_local", 1.0}}) {
      std::vector<double> times;
      for (int f = 0; f < std::max(3, frames / 5); ++f) {
        Eigen::MatrixXd positions, J;
        const CliClock::time_point frameStart = CliClock::now();
        gradients.evaluate(posed, {blend, 0.3, 1.0, true}, positions, J);
        pointQuantities(J, cage.dim());
        times.push_back(1e3 * secondsSince(frameStart));
      }
      analyzeMs.emplace_back(name, median(times));
    }
    // What the editor's measuring worker does per pose (global variant): the whole analysis, with the mesh's
    // area ratios and enclosed volume, and the p95 distortion under the view's label.
    std::vector<double> times;
    for (int f = 0; f < std::max(3, frames / 5); ++f) {
      const CliClock::time_point frameStart = CliClock::now();
      const DeformationAnalysis a = analyzeDeformation(gradients, points, mesh.faces, posed, {0.0, 0.3, 1.0, true});
      volatile double p95 = quantile(a.points.distortion, 0.95);
      (void)p95;
      times.push_back(1e3 * secondsSince(frameStart));
    }
    editorMeasureMs = median(times);
  }

  // Baseline: the same K random mesh vertices integrated in closed form and with the paper's rule.
  std::mt19937 rng(12345);
  std::vector<int> order(points.rows());
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), rng);
  const int K = std::min<int>(baselinePoints, static_cast<int>(points.rows()));
  Eigen::MatrixXd sample(K, cage.dim());
  for (int k = 0; k < K; ++k) sample.row(k) = points.row(order[k]);
  double speedup = 0, baselineUnity = 0;
  if (K > 0) {
    IntegrationOptions exact = precompute.integration, gauss = exact;
    gauss.rule = IntegrationOptions::Rule::Gauss;
    gauss.gaussPointsPerSide = quadrature;
    std::vector<double> exactTimes;
    for (int r = 0; r < 3; ++r) {
      const CliClock::time_point start = CliClock::now();
      computeSomiglianaCoordinates(cage, sample, exact);
      exactTimes.push_back(secondsSince(start));
    }
    ProgressReporter progress("baseline quadrature N = " + std::to_string(quadrature));
    const CliClock::time_point start = CliClock::now();
    const SomiglianaCoordinates baseline = computeSomiglianaCoordinates(cage, sample, gauss, progress.callback());
    const double gaussSeconds = secondsSince(start);
    progress.finish();
    speedup = gaussSeconds / median(exactTimes);
    const Eigen::VectorXd baselineResidual = partitionOfUnityResidual(baseline);
    for (int p = 0; p < K; ++p)
      if (baseline.winding(p) >= 0.5) baselineUnity = std::max(baselineUnity, baselineResidual(p));
  }

  // The precompute at scale (one run, as the editor stores it), before the peak RSS below, which it then includes.
  double scaleSeconds = 0;
  if (scaleCount > 0) {
    const Eigen::MatrixXd many = scalePoints(points, scaleCount);
    ProgressReporter progress("precompute of " + std::to_string(scaleCount) + " points");
    const CliClock::time_point start = CliClock::now();
    const std::unique_ptr<CageDeformer> big = somicage::precompute(
        somigliana, cage, many, precompute, options.text("--mesh"), progress.callback(), commandMemoryCheck(log));
    scaleSeconds = secondsSince(start);
    progress.finish();
  }

  struct rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  const long long peakRss = static_cast<long long>(usage.ru_maxrss) * 1024;
  const std::size_t coordBytes = deformer->frameCoordinates().bytes();
  const double precomputeSeconds = median(precomputeTimes);
  const double pouMax = unity.empty() ? 0.0 : *std::max_element(unity.begin(), unity.end());
  const double pouMedian = median(unity);
  const int usedThreads = threads > 0 ? threads : omp_get_max_threads();

  // The boundary element reference: factoring its boundary matrix (once per cage and nu), then frames (a solve and
  // the product C W). After the peak RSS above, which stays the Somigliana figure.
  std::vector<double> factorTimes;
  {
    const BemSystem system(cage, threads);
    for (int r = 0; r < std::max(3, repeat); ++r) {
      const CliClock::time_point start = CliClock::now();
      system.factor(0.3);
      factorTimes.push_back(1e3 * secondsSince(start));
    }
  }
  const double bemFactorMs = median(factorTimes);
  // Every other registered method's frame (deform_ms.cpu_NAME), at the same nu where it reads one. A method on a
  // volume mesh (Phong) also times the factorisation of its Steiner vertices' elastic system (NAME_factor_ms),
  // once per cage and nu like the BEM's, and reports the bytes of its C (NAME_coord_bytes).
  deformer.reset();
  std::vector<std::pair<std::string, double>> volumeFactorMs;
  for (Method method : allMethods()) {
    if (method == somigliana || (!everyMethod && method != only)) continue;
    PrecomputeOptions methodOptions = precompute;
    if (method->needsVolumeMesh) {
      ProgressReporter progress("volume mesh for " + methodName(method));
      applyMethodOptions(options, method, cage, methodOptions, log.sink());
      progress.finish();
      ElasticSteinerSolver solver(*methodOptions.volumeMesh,
                                  interiorSteinerVertices(*methodOptions.volumeMesh, cage.numVertices()));
      std::vector<double> times;
      for (int r = 0; r < std::max(3, repeat); ++r) {
        const CliClock::time_point start = CliClock::now();
        solver.factor(r % 2 == 0 ? 0.3 : 0.31);  // a new nu each time: factored again
        times.push_back(1e3 * secondsSince(start));
      }
      volumeFactorMs.emplace_back(methodName(method) + "_factor_ms", median(times));
      volumeFactorMs.emplace_back(methodName(method) + "_volume_vertices", methodOptions.volumeMesh->numVertices());
    }
    ProgressReporter progress("precompute " + methodName(method));
    const std::unique_ptr<CageDeformer> other = somicage::precompute(
        method, cage, points, methodOptions, options.text("--mesh"), progress.callback(), commandMemoryCheck(log));
    progress.finish();
    DeformParams params;
    params.nu = 0.3;
    deformMs.emplace_back("cpu_" + methodName(method), timeFrames(*other, posed, params, frames, false));
    if (method->needsVolumeMesh)  // its C, stored as sparse rows (coordinate_layout.h)
      volumeFactorMs.emplace_back(methodName(method) + "_coord_bytes",
                                  static_cast<double>(other->frameCoordinates().bytes()));
  }

  if (json) {
    JsonObjectWriter out(std::cout);
    out.field("mesh_vertices", static_cast<int>(points.rows()));
    out.field("cage_vertices", cage.numVertices());
    out.field("cage_faces", cage.numFaces());
    out.field("threads", usedThreads);
    out.field("cpu_kernels", dispatchedKernelTarget());
    out.field("precompute_s", precomputeSeconds);
    out.field("pou_max", pouMax);
    out.field("pou_median", pouMedian);
    out.field("baseline_quadrature", quadrature);
    out.field("baseline_points", K);
    out.field("baseline_speedup", speedup);
    out.field("baseline_pou_max", baselineUnity);
    if (scaleCount > 0) {
      out.field("scale_points", scaleCount);
      out.field("scale_precompute_s", scaleSeconds);
    }
    out.field("deform_ms", deformMs);
    out.field("nu_update_ms", nuUpdateMs);
    out.field("bem_factor_ms", bemFactorMs);
    for (const auto& [key, value] : volumeFactorMs) out.field(key, value);
    out.field("analyze_ms", analyzeMs);
    out.field("detj_updates_per_s", 1e3 / analyzeMs.back().second);
    out.field("editor_measure_ms", editorMeasureMs);
    out.field("editor_detj_updates_per_s", 1e3 / editorMeasureMs);
    out.field("gradient_precompute_s", gradientSeconds);
    out.field("gradient_bytes", static_cast<long long>(gradientBytes));
    out.field("coord_bytes", static_cast<long long>(coordBytes));
    out.field("peak_rss_bytes", peakRss);
    out.close();
    std::cout << "\n";
    return kExitOk;
  }
  const double bandwidth = copyBandwidth(std::min<std::size_t>(coordBytes, std::size_t(1) << 28));
  std::printf("mesh %d vertices, cage %d vertices / %d faces, %d threads, %s CPU kernels\n",
              static_cast<int>(points.rows()), cage.numVertices(), cage.numFaces(), usedThreads,
              dispatchedKernelTarget());
  std::printf("precompute        %.3f s (median of %d)\n", precomputeSeconds, repeat);
  std::printf("partition of unity max %.3g, median %.3g\n", pouMax, pouMedian);
  std::printf("baseline          N = %d (%d points per triangle) on %d points: %.0fx slower, pou max %.3g\n",
              quadrature, 3 * quadrature * quadrature, K, speedup, baselineUnity);
  if (scaleCount > 0) std::printf("precompute at scale %.3f s (%d points, one run)\n", scaleSeconds, scaleCount);
  for (const auto& [name, ms] : deformMs) {
    const bool cpu = name == "cpu_global" || name == "cpu_local";  // the Somigliana coordinates' bandwidth
    std::printf("deform %-10s %.2f ms", name.c_str(), ms);
    if (cpu)
      std::printf("  (%.1f GB/s reading the coordinates; copy bandwidth %.1f GB/s)", coordBytes / ms * 1e-6,
                  bandwidth * 1e-9);
    std::printf("\n");
  }
  if (!deviceNotes.empty()) std::printf("devices           %s\n", deviceNotes.c_str());
  std::printf("nu update         %.2f ms (a frame at a new nu: only the weights change)\n", nuUpdateMs);
  std::printf("bem factor        %.2f ms (the boundary matrix of %d unknowns, once per cage and nu)\n", bemFactorMs,
              cage.dim() * (cage.numFaces() + 1));
  for (const auto& [key, value] : volumeFactorMs) std::printf("%-17s %.6g\n", key.c_str(), value);
  for (const auto& [name, ms] : analyzeMs)
    std::printf("det J %-11s %.2f ms (%.1f updates/s: positions, J, det J and distortion)\n", name.c_str(), ms,
                1e3 / ms);
  std::printf("editor det J       %.2f ms (%.1f updates/s: the measuring worker's analysis of a pose)\n",
              editorMeasureMs, 1e3 / editorMeasureMs);
  std::printf("coord. gradients  %.3f s, %.1f MB (float; while a J view is shown)\n", gradientSeconds,
              gradientBytes / 1e6);
  std::printf("coordinates       %.1f MB (float), peak RSS %.1f MB\n", coordBytes / 1e6, peakRss / 1e6);
  return kExitOk;
}

}  // namespace somicage
