// PNG files of the window. No GL here: the pixels come from render::readPixelsRgba.
#pragma once

#include <string>
#include <vector>

namespace somicage::editor {

// rgba: width * height * 4 bytes, rows top to bottom. Written atomically (temporary file + rename);
// throws InputError on failure.
void writePng(const std::string& path, int width, int height, const std::vector<unsigned char>& rgba);

// "somicage-YYYYMMDD-HHMMSS.png" in the current folder.
std::string defaultScreenshotName();

}  // namespace somicage::editor
