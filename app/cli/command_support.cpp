#include "cli/command_support.h"

#include <omp.h>

#include <cstdio>

namespace somicage {

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

Eigen::MatrixXd meshPoints(const PolygonMesh& mesh, int dim) { return mesh.vertices.leftCols(dim); }

}  // namespace somicage
