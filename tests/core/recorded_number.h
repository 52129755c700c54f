// How the engine tests write a measured number into the test report (RecordProperty): the stream's shortest form,
// so "3.4e-13" reads as measured.
#pragma once

#include <sstream>
#include <string>

namespace somicage::test {

inline std::string scientific(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

}  // namespace somicage::test
