// The development-set meshes (published meshes hexdual did not make, in ../shared/meshes next to
// the repository, or $HEXDUAL_MESHES): where they are and how to read one.
#pragma once
#include <cstdlib>
#include <filesystem>
#include <string>

#include "io/io.hpp"

namespace hexdual::test {

inline std::filesystem::path devMeshDir() {
  if (const char* dir = std::getenv("HEXDUAL_MESHES")) return dir;  // for worktrees not next to ../shared
  return std::filesystem::path(__FILE__).parent_path().parent_path().parent_path() / "shared" / "meshes";
}

// The mesh, gunzipped into a temporary file when needed; throws Error when it is refused.
inline Complex readDevMesh(const std::filesystem::path& file) {
  namespace fs = std::filesystem;
  if (file.extension() != ".gz") return io::readFile(file.string());
  fs::path tmp = fs::temp_directory_path() / ("hexdual-devset-" + file.stem().string());
  std::string cmd = "gzip -dc '" + file.string() + "' > '" + tmp.string() + "'";
  if (std::system(cmd.c_str()) != 0) throw Error(file.string() + ": gzip -dc failed");
  try {
    Complex cx = io::readFile(tmp.string());
    fs::remove(tmp);
    return cx;
  } catch (...) {
    fs::remove(tmp);
    throw;
  }
}

}  // namespace hexdual::test
