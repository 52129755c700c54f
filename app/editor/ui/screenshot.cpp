#include "ui/screenshot.h"

#include <stb_image_write.h>

#include <ctime>

#include "base/errors.h"
#include "base/file_util.h"

namespace somicage::editor {

namespace {
void appendBytes(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}
}  // namespace

void writePng(const std::string& path, int width, int height, const std::vector<unsigned char>& rgba) {
  if (width <= 0 || height <= 0 ||
      rgba.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4) {
    throw InputError(path, -1, "no image to write (empty framebuffer)", "make the window larger");
  }
  std::string png;
  if (!stbi_write_png_to_func(appendBytes, &png, width, height, 4, rgba.data(), width * 4)) {
    throw InputError(path, -1, "PNG encoding failed", "try again; report it if it persists");
  }
  writeFileAtomic(path, png);
}

std::string defaultScreenshotName() {
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char buf[64];
  std::strftime(buf, sizeof buf, "somicage-%Y%m%d-%H%M%S.png", &local);
  return buf;
}

}  // namespace somicage::editor
