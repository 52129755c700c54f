// A named (dimension, method) test parameter, for suites instantiated over every method in 2D and 3D.
#pragma once

#include <gtest/gtest.h>

#include <ostream>
#include <string>

#include "deform/deformer.h"

namespace somicage::test {

struct MethodCase {
  std::string name;
  int dim;
  Method method;
};

inline void PrintTo(const MethodCase& c, std::ostream* os) { *os << c.name; }
inline std::string methodCaseName(const ::testing::TestParamInfo<MethodCase>& info) { return info.param.name; }

}  // namespace somicage::test
