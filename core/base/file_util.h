// Whole-file reads and atomic writes (temporary file in the same folder, flushed, then renamed over the
// target), so that a crash or a full disk never leaves a half-written session or screenshot.
#pragma once

#include <string>

namespace somicage {

// Throws InputError(path, -1, reason, hint) when the file cannot be read.
std::string readTextFile(const std::string& path);

// Throws InputError with the system's reason; on failure the temporary file is removed and an existing
// file at `path` is left as it was.
void writeFileAtomic(const std::string& path, const std::string& bytes);

// Whether two paths name the same file, however each is spelled ("m.obj" from its folder, "/abs/m.obj", "./a/../m.obj",
// a symbolic link): compares the canonical absolute paths; paths of files that do not exist compare by that too.
// Two empty paths (no file) are the same; an empty and a non-empty one are not.
bool samePath(const std::string& a, const std::string& b);

}  // namespace somicage
