// The development-set meshes (published meshes hexdual did not make, in ../shared/meshes next to
// the repository, or $HEXDUAL_MESHES): where they are and how to read one.
#pragma once
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <unistd.h>

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
  // A name of this process's own: ctest runs test cases in parallel processes.
  static int serial = 0;
  fs::path tmp = fs::temp_directory_path() / ("hexdual-devset-" + std::to_string(::getpid()) + "-" +
                                              std::to_string(serial++) + "-" + file.stem().string());
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

// The development-set mesh `name`, or nothing (saying so) where the set is not here: the test
// that asked returns early then.
inline std::optional<Complex> devMeshOrSkip(const std::string& name) {
  const auto file = devMeshDir() / name;
  if (!std::filesystem::exists(file)) {
    MESSAGE("skipped: no development-set meshes at " << devMeshDir().string());
    return std::nullopt;
  }
  return readDevMesh(file);
}

}  // namespace hexdual::test
