// Small helpers shared by the commands.
#pragma once

#include <Eigen/Core>
#include <chrono>
#include <string>

#include "obj_io.h"

namespace somicage {

using CliClock = std::chrono::steady_clock;

double secondsSince(CliClock::time_point start);

// "0.0123 s", "1.23 s", "12.3 s".
std::string formatSeconds(double seconds);

// %g with the given significant digits.
std::string formatNumber(double value, int digits = 6);

// Sets the OpenMP thread count for everything that follows; 0 keeps the OpenMP default.
void setThreadCount(int threads);

// The points a cage of dimension dim deforms: the mesh's x, y, z (3D) or x, y (2D), #V by dim.
Eigen::MatrixXd meshPoints(const PolygonMesh& mesh, int dim);

}  // namespace somicage
