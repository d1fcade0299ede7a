#include "io/io.hpp"

#include <fstream>
#include <sstream>

namespace hexdual::io {

static bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

Format formatFromPath(const std::string& path) {
  if (endsWith(path, ".vtk")) return Format::Vtk;
  if (endsWith(path, ".mesh")) return Format::Medit;
  if (endsWith(path, ".hxd")) return Format::Native;
  throw Error(path + ": unknown file extension (use .vtk, .mesh or .hxd)");
}

Format detectFormat(std::string_view data, const std::string& name) {
  size_t i = 0;
  while (i < data.size() && (data[i] == ' ' || data[i] == '\n' || data[i] == '\r' || data[i] == '\t')) ++i;
  auto rest = data.substr(i);
  if (rest.substr(0, 5) == "# vtk") return Format::Vtk;
  if (rest.substr(0, 7) == "hexdual") return Format::Native;
  if (rest.substr(0, 20) == "MeshVersionFormatted" || rest.substr(0, 1) == "#") return Format::Medit;
  if (data.empty()) throw Error(name + ": the file is empty");
  throw Error(name + ": not a VTK legacy, Medit .mesh or hexdual .hxd file");
}

const char* formatName(Format f) {
  switch (f) {
    case Format::Vtk: return "vtk";
    case Format::Medit: return "mesh";
    case Format::Native: return "hxd";
  }
  return "?";
}

Complex readMesh(std::string_view data, const std::string& name) {
  switch (detectFormat(data, name)) {
    case Format::Vtk: return readVtk(data, name);
    case Format::Medit: return readMedit(data, name);
    case Format::Native: return readNative(data, name);
  }
  throw Error(name + ": unknown format");
}

std::string writeMesh(const Complex& cx, Format f, bool binary) {
  switch (f) {
    case Format::Vtk: return writeVtk(cx, binary);
    case Format::Medit: return writeMedit(cx);
    case Format::Native: return writeNative(cx);
  }
  return {};
}

Complex readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path + ": cannot open file");
  std::stringstream ss;
  ss << in.rdbuf();
  return readMesh(ss.str(), path);
}

void writeFile(const Complex& cx, const std::string& path, bool binary) {
  std::string data = writeMesh(cx, formatFromPath(path), binary);
  std::ofstream out(path, std::ios::binary);
  if (!out) throw Error(path + ": cannot open file for writing");
  out << data;
  if (!out) throw Error(path + ": write failed");
}

}  // namespace hexdual::io
