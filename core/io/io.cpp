#include "io/io.hpp"
#include "io/dense.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "io/inflate.hpp"
#include "io/json.hpp"

namespace hexdual::io {

static bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

Format formatFromPath(const std::string& path) {
  if (endsWith(path, ".vtk")) return Format::Vtk;
  if (endsWith(path, ".mesh")) return Format::Medit;
  if (endsWith(path, ".hxd")) return Format::Native;
  throw Error(path + ": unknown file extension for writing (use .vtk, .mesh or .hxd)");
}

// Medit binary files start with the 32-bit code 1 in the writer's byte order.
static bool isMeditBinary(std::string_view d) {
  if (d.size() < 8) return false;
  return (d[0] == 1 && d[1] == 0 && d[2] == 0 && d[3] == 0) || (d[0] == 0 && d[1] == 0 && d[2] == 0 && d[3] == 1);
}

Format detectFormat(std::string_view data, const std::string& name) {
  if (isMeditBinary(data)) return Format::MeditBinary;
  size_t i = 0;
  if (data.substr(0, 3) == "\xEF\xBB\xBF") i = 3;  // UTF-8 byte-order mark
  while (i < data.size() && (data[i] == ' ' || data[i] == '\n' || data[i] == '\r' || data[i] == '\t')) ++i;
  auto rest = data.substr(i);
  auto startsNoCase = [&](std::string_view word) {
    if (rest.size() < word.size()) return false;
    for (size_t k = 0; k < word.size(); ++k)
      if (std::tolower((unsigned char)rest[k]) != std::tolower((unsigned char)word[k])) return false;
    return true;
  };
  if (rest.substr(0, 5) == "# vtk") return Format::Vtk;
  if (rest.substr(0, 5) == "<?xml" || rest.substr(0, 8) == "<VTKFile") return Format::Vtu;
  if (rest.substr(0, 11) == "$MeshFormat") return Format::Gmsh;
  if (rest.substr(0, 7) == "hexdual") return Format::Native;
  if (startsNoCase("MeshVersionFormatted") || rest.substr(0, 1) == "#") return Format::Medit;
  if (data.empty()) throw Error(name + ": the file is empty");
  throw Error(name + ": not a mesh file hexdual reads (VTK legacy or .vtu, Gmsh .msh, Medit .mesh/.meshb, .hxd; "
                     "gzipped or not)");
}

const char* formatName(Format f) {
  switch (f) {
    case Format::Vtk: return "vtk";
    case Format::Vtu: return "vtu";
    case Format::Gmsh: return "msh";
    case Format::Medit: return "mesh";
    case Format::MeditBinary: return "meshb";
    case Format::Native: return "hxd";
  }
  return "?";
}

Complex readMesh(std::string_view data, const std::string& name, const ReadOptions& opt, ReadReport* rep) {
  if (isGzip(data)) {
    std::string plain;
    try {
      plain = gunzip(data);
    } catch (const Error& e) {
      throw Error(name + ": " + e.what());
    }
    Complex cx = readMesh(plain, name, opt, rep);
    if (rep) rep->gzipped = true;
    return cx;
  }
  switch (detectFormat(data, name)) {
    case Format::Vtk: return readVtk(data, name, opt, rep);
    case Format::Vtu: return readVtu(data, name, opt, rep);
    case Format::Gmsh: return readGmsh(data, name, opt, rep);
    case Format::Medit: return readMedit(data, name, opt, rep);
    case Format::MeditBinary: return readMeditBinary(data, name, opt, rep);
    case Format::Native: return readNative(data, name, rep);
  }
  throw Error(name + ": unknown format");
}

std::string writeMesh(const Complex& cx, Format f, bool binary) {
  if (binary && f != Format::Vtk)
    throw Error(std::string("--binary applies to .vtk only, not .") + formatName(f) + " (hexdual writes .mesh and .hxd as text)");
  switch (f) {
    case Format::Vtk: return writeVtk(cx, binary);
    case Format::Medit: return writeMedit(cx);
    case Format::Native: return writeNative(cx);
    default: throw Error(std::string("writing .") + formatName(f) + " is not supported (use .vtk, .mesh or .hxd)");
  }
}

std::string readBytes(const std::string& path, size_t maxBytes) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) throw Error(path + ": cannot open file");
  if (S_ISDIR(st.st_mode)) throw Error(path + ": is a directory, not a file");
  if (S_ISREG(st.st_mode) && uint64_t(st.st_size) > maxBytes)
    throw Error(path + ": the file has " + std::to_string(st.st_size) + " bytes, more than the limit of " +
                std::to_string(maxBytes));
  FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) throw Error(path + ": cannot open file (" + std::strerror(errno) + ")");
  std::string data;
  char buf[1 << 16];
  for (;;) {
    size_t n = std::fread(buf, 1, sizeof buf, f);
    if (n == 0) break;
    if (data.size() + n > maxBytes) {
      std::fclose(f);
      throw Error(path + ": more than " + std::to_string(maxBytes) + " bytes; refusing to read further");
    }
    data.append(buf, n);
  }
  bool err = std::ferror(f);
  std::fclose(f);
  if (err) throw Error(path + ": read error");
  return data;
}

// A stream (device, pipe) is read only when its first bytes look like a mesh, so that
// /dev/zero or /dev/urandom fail at once instead of filling memory.
static std::string readMeshBytes(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode)) {
    FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) throw Error(path + ": cannot open file (" + std::strerror(errno) + ")");
    char head[4096];
    size_t n = std::fread(head, 1, sizeof head, f);
    std::fclose(f);
    std::string_view h(head, n);
    if (!isGzip(h)) detectFormat(h, path);
  }
  return readBytes(path);
}

Complex readFile(const std::string& path, const ReadOptions& opt, ReadReport* rep) {
  return readMesh(readMeshBytes(path), path, opt, rep);
}

void writeTextFile(const std::string& path, const std::string& data) {
  std::string tmp = path + ".tmp-XXXXXX";
  int fd = ::mkstemp(tmp.data());
  if (fd < 0) throw Error(path + ": cannot create a temporary file next to it (" + std::strerror(errno) + ")");
  FILE* f = ::fdopen(fd, "wb");
  bool ok = f && std::fwrite(data.data(), 1, data.size(), f) == data.size();
  ok = f && std::fclose(f) == 0 && ok;
  struct stat st {};
  if (ok && ::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) {
    std::remove(tmp.c_str());
    throw Error(path + ": is a directory; nothing was written");
  }
  if (!ok || std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::string why = std::strerror(errno);
    std::remove(tmp.c_str());
    throw Error(path + ": write failed (" + why + "); the target is unchanged");
  }
  ::chmod(path.c_str(), 0644);
}

void writeFile(const Complex& cx, const std::string& path, bool binary) {
  writeTextFile(path, writeMesh(cx, formatFromPath(path), binary));
}

std::optional<OpStep> numberedAsWritten(const Complex& cx, const OpStep& step) {
  const Dense d = denseNumbering(cx);
  auto renumber = [&](HexId& h) {
    if (!cx.isHex(h)) return false;
    h = d.hexIndex[size_t(h)];
    return true;
  };
  OpStep out = step;
  for (OpArg& a : out.args) {
    if (a.kind == OpArg::Number) continue;
    if (!renumber(a.hex)) return std::nullopt;
    if (a.kind == OpArg::Pair && !renumber(a.second.hex)) return std::nullopt;
  }
  return out;
}

std::string reportText(const ReadReport& r) {
  std::string out = "file " + r.format + (r.gzipped ? ", gzipped" : "") + ", " + std::to_string(r.points) + " points";
  if (r.unusedVertices) out += " (" + std::to_string(r.unusedVertices) + " used by no hex, not in the complex)";
  out += "\n";
  int64_t skipped = r.vertexCells + r.lineCells + r.triangleCells + r.quadCells;
  if (skipped)
    out += "skipped lower-dimensional cells: " + std::to_string(r.vertexCells) + " vertices, " +
           std::to_string(r.lineCells) + " lines, " + std::to_string(r.triangleCells) + " triangles, " +
           std::to_string(r.quadCells) + " quads\n";
  if (r.tetrahedra + r.prisms + r.pyramids)
    out += "dropped (--hexes-only): " + std::to_string(r.tetrahedra) + " tetrahedra, " + std::to_string(r.prisms) +
           " prisms, " + std::to_string(r.pyramids) + " pyramids\n";
  if (!r.nonManifoldVertices.empty())
    out += "non-manifold vertices: " + std::to_string(r.nonManifoldVertices.size()) +
           " (operations refuse to touch them; hexdual validate lists them)\n";
  return out;
}

std::string reportJson(const ReadReport& r) {
  JsonWriter w;
  w.beginObject().key("format").value(r.format).key("gzipped").value(r.gzipped).key("points").value(r.points);
  w.key("unusedVertices").value(r.unusedVertices);
  w.key("skipped").beginObject().key("vertices").value(r.vertexCells).key("lines").value(r.lineCells);
  w.key("triangles").value(r.triangleCells).key("quads").value(r.quadCells).endObject();
  w.key("dropped").beginObject().key("tetrahedra").value(r.tetrahedra).key("prisms").value(r.prisms);
  w.key("pyramids").value(r.pyramids).endObject();
  w.key("nonManifoldVertices").beginArray();
  for (VertexId v : r.nonManifoldVertices) w.value(int64_t(v));
  w.endArray().endObject();
  return w.str();
}

}  // namespace hexdual::io
