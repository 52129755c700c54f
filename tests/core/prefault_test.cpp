// prefaultForWriting (core/base/prefault.h): advice only, so what it must guarantee is that a buffer's contents,
// and the bytes around it, are what they were, for any start and length (whole pages, a part of one, none).
#include "base/prefault.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace somicage {
namespace {

TEST(Prefault, KeepsContentsForAnyStartAndLength) {
  constexpr std::size_t kBytes = (std::size_t(1) << 22) + 12345;  // two 2 MB slices and a partial page
  std::vector<unsigned char> buffer(kBytes + 64);
  for (std::size_t i = 0; i < buffer.size(); ++i) buffer[i] = static_cast<unsigned char>(i * 131 + 7);
  const std::vector<unsigned char> expected = buffer;
  for (std::size_t offset : {std::size_t(0), std::size_t(1), std::size_t(4095), std::size_t(33)})
    for (std::size_t bytes : {std::size_t(0), std::size_t(1), std::size_t(4096), kBytes})
      for (int threads : {1, 2}) {
        prefaultForWriting(buffer.data() + offset, bytes, threads);
        ASSERT_EQ(buffer, expected) << "offset " << offset << ", " << bytes << " bytes, " << threads << " threads";
      }
}

}  // namespace
}  // namespace somicage
