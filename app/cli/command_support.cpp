#include "cli/command_support.h"

#include <omp.h>

#include <algorithm>
#include <cstdio>

#include "base/errors.h"
#include "deform/memory_estimate.h"
#include "deform/parameter_schema.h"
#include "tetrahedralization/cage_tetrahedralization.h"

namespace somicage {

constexpr std::size_t kBigPrecomputeBytes = 1000000000;  // 1 GB

double secondsSince(CliClock::time_point start) {
  return std::chrono::duration<double>(CliClock::now() - start).count();
}

std::string formatSeconds(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, seconds < 0.1 ? "%.4f s" : seconds < 10 ? "%.3f s" : "%.1f s", seconds);
  return text;
}

std::string formatNumber(double value, int digits) {
  char text[40];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}

void setThreadCount(int threads) {
  if (threads > 0) omp_set_num_threads(threads);
}

OptionSpec threadsOptionSpec() { return {"--threads", "N", "OpenMP threads (default: all cores)"}; }

int threadsOption(const ArgParser& args) {
  const int threads = args.integer("--threads", 0, 0, kMaxThreads);
  setThreadCount(threads);
  return threads;
}

OptionSpec weldOptionSpec() {
  return {"--weld", "", "join vertices at equal positions when reading non-OBJ files (STL has none shared)"};
}

ReadOptions readOptions(const ArgParser& args) {
  ReadOptions read;
  read.weld = args.has("--weld");
  return read;
}

PrecomputeOptions precomputeOptions(int threads) {
  PrecomputeOptions options;
  options.threads = threads;
  options.integration.threads = threads;
  return options;
}

Method methodOption(const ArgParser& args) {
  try {
    return parseMethod(args.text("--method", methodName(Method())));
  } catch (const InputError& e) {
    throw InputError("--method", -1, e.problem(), e.hint());
  }
}

std::vector<OptionSpec> withDeformParams(std::vector<OptionSpec> before, const std::vector<OptionSpec>& after) {
  const auto forMethods = [](DeformParameter p) { return "; " + methodsReading(p); };
  before.push_back({"--method", "NAME", methodNameList() + " (default " + methodName(Method()) + ")"});
  for (const ParameterFlag& f : parameterFlags()) {  // parameter_schema.h: a row's flag and its aliases
    const bool rowFlag = f.flag == cliFlag(*f.spec);
    before.push_back({f.flag, f.fixedValue ? "" : cliValueName(*f.spec),
                      parameterFlagHelp(f) + (rowFlag ? forMethods(f.spec->parameter) : "")});
  }
  const std::vector<OptionSpec> own = methodOptionSpecs();
  before.insert(before.end(), own.begin(), own.end());
  before.insert(before.end(), after.begin(), after.end());
  return before;
}

std::vector<OptionSpec> methodOptionSpecs() {
  std::vector<OptionSpec> specs;
  for (const MethodOptionFlag& f : methodOptionFlags()) specs.push_back({f.flag, f.spec->value, f.help});
  return specs;
}

void applyMethodOptions(const ArgParser& args, Method method, const Cage& cage, PrecomputeOptions& options,
                        const NoticeSink& notices) {
  for (const MethodOptionFlag& f : methodOptionFlags())
    if (args.has(f.flag)) options.methodOptions[f.spec->key] = args.text(f.flag);
  options.volumeMesher = tetrahedralizeCageWithOptions;
  prepareVolumeMesh(method, cage, options, notices);
}

std::string methodsHelp() {
  std::size_t width = 0;
  for (Method m : allMethods()) width = std::max(width, std::string(m->name).size());
  std::string text = "methods (--method):\n";
  for (Method m : allMethods()) {
    std::string name = m->name;
    name.resize(width, ' ');
    text += "  " + name + "  " + m->displayName + ": " + m->description + "\n";
  }
  return text;
}

DeformParams deformParamsOptions(const ArgParser& args, Method method) {
  DeformParams params;
  for (const ParameterFlag& f : parameterFlags())
    if (args.has(f.flag))
      setParameter(*f.spec, params, parseParameter(*f.spec, f.fixedValue ? f.fixedValue : args.text(f.flag), f.flag));
  try {
    method->validateParams(params);
  } catch (const InputError& e) {  // the method names the parameter ("nu"); here it is the option
    const std::string source = e.source().rfind("--", 0) == 0 ? e.source() : "--" + e.source();
    throw InputError(source, -1, e.problem(), e.hint());
  }
  return params;
}

void noteIgnoredParameters(const CommandLog& log, const ArgParser& args, Method method, bool volumeMeshUsed) {
  std::string ignored;
  const auto note = [&](const std::string& option, DeformParameter parameter) {
    if (args.has(option) && !readsParameter(method, parameter))
      ignored += (ignored.empty() ? "" : ", ") + option + " (" + methodsReading(parameter) + ")";
  };
  for (const ParameterFlag& f : parameterFlags()) note(f.flag, f.spec->parameter);
  for (Method m : allMethods())
    for (const MethodOptionSpec& o : m->options)
      if (m != method && !(volumeMeshUsed && m->needsVolumeMesh) && args.has(std::string("--") + o.key))
        ignored += (ignored.empty() ? "" : ", ") + std::string("--") + o.key + " (" + m->name + " only)";
  if (!ignored.empty()) log.note(methodName(method) + " ignores " + ignored);
}

MemoryCheck commandMemoryCheck(const CommandLog& log, bool withGradients) {
  return {memoryHint(false), withGradients, [&log](const MemoryEstimate& estimate) {
            const std::optional<std::size_t> available = availableMemoryBytes();
            // Small runs keep their one summary line; a big one says what it is about to take before it takes a while.
            const bool big =
                estimate.total() >= kBigPrecomputeBytes || (available && estimate.total() * 10 >= *available);
            if (big)
              log.status("estimated memory: " + formatBytes(estimate.coordinates) + " of coordinates, " +
                         formatBytes(estimate.total()) + " in all (" +
                         (available ? formatBytes(*available) + " free" : std::string("free memory unknown")) + ")");
          }};
}

bool gradientsFitForNormals(const CommandLog& log, Method method, const Cage& cage, std::size_t points,
                            const PrecomputeOptions& options, const std::string& meshPath) {
  try {
    requirePrecomputeMemory(method, cage, points, options, meshPath, memoryHint(false), true);
    return true;
  } catch (const InputError&) {
    log.note(meshPath + ": the normals are recomputed from the deformed faces: carrying them by the deformation's " +
             "gradient would not fit in the free memory");
    return false;
  }
}

}  // namespace somicage
