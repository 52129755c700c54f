// somicage cage: makes a cage for a mesh (core/generation/cage_generation.h) and writes it as OBJ, with how tight it
// is.
#include <iostream>
#include <sstream>

#include "base/errors.h"
#include "cage/cage_validation.h"
#include "cli/arg_parser.h"
#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/json_writer.h"
#include "cli/progress_reporter.h"
#include "cli/tightness_report.h"
#include "generation/cage_generation.h"
#include "io/obj_io.h"

namespace somicage {

namespace {

const char* const kCommand = "somicage cage";

ArgParser cageOptions() {
  return ArgParser(kCommand,
                   withScriptOptions({
                       {"--mesh", "MESH.obj", "the mesh to enclose (any readable format, with faces)", true},
                       weldOptionSpec(),
                       {"--out", "CAGE.obj", "where to write the cage", true},
                       {"--faces", "N", "at most N triangles (default 200, at least 12)"},
                       {"--margin", "M", "distance from the mesh, in bounding-box diagonals (default: automatic)"},
                       {"--json", "", "print one JSON object instead of the readable report"},
                   }));
}

}  // namespace

std::string cageUsage() {
  std::ostringstream out;
  out << "usage: " << kCommand << " --mesh MESH.obj --out CAGE.obj [--faces N] [--margin M] [--json]\n\n"
      << "Makes a closed, edge-manifold, outward cage of at most N triangles, free of self-intersections, that\n"
      << "strictly encloses MESH (every vertex inside, no edge crossing it; checked with exact predicates), and\n"
      << "writes it atomically. Works on open meshes, several components and non-manifold input. Reports the\n"
      << "faces, the smallest triangle angle, the one-sided Hausdorff distance cage -> mesh and, for a closed\n"
      << "mesh, the volume ratio cage / mesh.\n\n"
      << "options:\n"
      << cageOptions().optionHelp();
  return out.str();
}

int runCageCommand(const std::vector<std::string>& rawArgs, CommandLog& log) {
  ArgParser args = cageOptions();
  args.parse(rawArgs);
  log.configure(args);
  if (args.helpRequested()) {
    std::cout << cageUsage();
    return kExitOk;
  }
  CageGenerationOptions options;
  options.maxFaces = args.integer("--faces", options.maxFaces, CageGenerationOptions::kMinFaces, 100000);
  options.margin = args.number("--margin", 0.0);
  if (args.has("--margin") && !(options.margin > 0 && options.margin < 1))
    throw InputError("--margin", -1, "must be in (0, 1) bounding-box diagonals", "give e.g. --margin 0.02");
  const std::string meshPath = args.text("--mesh"), outPath = args.text("--out");

  const PolygonMesh mesh = loadAnyMesh(meshPath, readOptions(args));
  const Eigen::MatrixXi triangles = triangulatePolygons(mesh.vertices, mesh.faces);
  const CliClock::time_point start = CliClock::now();
  GeneratedCage generated;
  {
    ProgressReporter progress = log.progress("making the cage");
    generated = generateCage(mesh.vertices, triangles, options, meshPath, progress.callback());
  }
  const double seconds = secondsSince(start);
  saveObj(outPath, generated.cage.vertices, cageTopology(generated.cage));
  if (args.has("--margin") && generated.margin > options.margin * (1 + 1e-9))
    log.notice({Notice::Kind::Warning, outPath,
                "the cage was made at a margin of " + formatNumber(generated.margin, 3) + " diagonals, not the " +
                    formatNumber(options.margin, 3) + " asked for (--margin): none of at most " +
                    std::to_string(options.maxFaces) + " faces fits closer; ask for more faces (--faces)"});

  const CageTightness& tightness = generated.tightness;
  const bool valid = validateCage(generated.cage).valid();
  if (args.has("--json")) {
    JsonObjectWriter json(std::cout);
    json.field("mesh", meshPath);
    json.field("cage", outPath);
    json.field("faces", generated.cage.numFaces());
    json.field("vertices", generated.cage.numVertices());
    json.field("max_faces", options.maxFaces);
    json.field("margin", generated.margin);
    json.field("min_angle_deg", generated.minAngleDegrees);
    writeTightness(json, tightness);
    json.field("attempts", generated.attempts);
    json.field("repair_rounds", generated.repairRounds);
    json.field("seconds", seconds);
    json.field("valid", valid);
    json.close();
  } else {
    std::ostringstream out;
    out << "cage   " << outPath << ": " << generated.cage.numVertices() << " vertices, " << generated.cage.numFaces()
        << " triangles (at most " << options.maxFaces << "), smallest angle "
        << formatNumber(generated.minAngleDegrees, 3) << " deg\n"
        << "fit    margin " << formatNumber(generated.margin, 3) << " diagonals, " << describeTightness(tightness)
        << "\n"
        << "result " << (valid ? "valid" : "NOT VALID") << ", encloses every vertex and edge of " << meshPath << " ("
        << formatSeconds(seconds) << ")\n";
    std::cout << out.str();
  }
  return valid ? kExitOk : kExitFailure;
}

}  // namespace somicage
