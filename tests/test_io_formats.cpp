// Every reader on small files written here: VTK legacy 5.1, VTK XML (.vtu) in each encoding,
// Gmsh 2.2/4.1 ASCII and binary, Medit binary, gzip; mixed cells; and inflate against zlib.
#include <doctest/doctest.h>
#include <zlib.h>

#include <cstring>
#include <random>

#include "complex/builders.hpp"
#include "complex/manifold.hpp"
#include "dual/dual.hpp"
#include "helpers.hpp"
#include "io/inflate.hpp"
#include "io/io.hpp"
#include "ops/ops.hpp"

using namespace hexdual;
using namespace hexdual::test;

namespace {
// A 2x1x1 grid: 12 points, 2 hexes (VTK order).
const double kPts[12][3] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0},
                            {0, 0, 1}, {1, 0, 1}, {2, 0, 1}, {0, 1, 1}, {1, 1, 1}, {2, 1, 1}};
const int kHex[2][8] = {{0, 1, 4, 3, 6, 7, 10, 9}, {1, 2, 5, 4, 7, 8, 11, 10}};

std::string zlibCompress(const std::string& s, int level = 6) {
  uLongf n = compressBound(uLong(s.size()));
  std::string out(n, '\0');
  REQUIRE(compress2(reinterpret_cast<Bytef*>(out.data()), &n, reinterpret_cast<const Bytef*>(s.data()), uLong(s.size()),
                    level) == Z_OK);
  out.resize(n);
  return out;
}
std::string gzipCompress(const std::string& s) {
  z_stream z{};
  REQUIRE(deflateInit2(&z, 9, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) == Z_OK);
  std::string out(deflateBound(&z, uLong(s.size())) + 64, '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(s.data()));
  z.avail_in = uInt(s.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = uInt(out.size());
  REQUIRE(deflate(&z, Z_FINISH) == Z_STREAM_END);
  out.resize(z.total_out);
  deflateEnd(&z);
  return out;
}
std::string base64(const std::string& s) {
  static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  size_t i = 0;
  for (; i + 2 < s.size(); i += 3) {
    uint32_t v = uint32_t(uint8_t(s[i])) << 16 | uint32_t(uint8_t(s[i + 1])) << 8 | uint8_t(s[i + 2]);
    for (int k2 = 3; k2 >= 0; --k2) out += k[(v >> (6 * k2)) & 63];
  }
  if (s.size() - i == 1) {
    uint32_t v = uint32_t(uint8_t(s[i])) << 16;
    out += std::string{k[v >> 18], k[(v >> 12) & 63], '=', '='};
  } else if (s.size() - i == 2) {
    uint32_t v = uint32_t(uint8_t(s[i])) << 16 | uint32_t(uint8_t(s[i + 1])) << 8;
    out += std::string{k[v >> 18], k[(v >> 12) & 63], k[(v >> 6) & 63], '='};
  }
  return out;
}
template <class T>
std::string le(T v) {
  std::string s(sizeof(T), '\0');
  std::memcpy(s.data(), &v, sizeof(T));
  return s;
}
template <class T>
std::string be(T v) {
  std::string s = le(v);
  return std::string(s.rbegin(), s.rend());
}

// One DataArray's raw bytes in the .vtu encodings: with a UInt32 size header, or zlib blocks.
std::string vtuBlock(const std::string& raw, bool compressed) {
  if (!compressed) return le<uint32_t>(uint32_t(raw.size())) + raw;
  std::string sizes, blocks;  // blocks of 40 bytes, the last one shorter
  uint32_t n = 0;
  for (size_t at = 0; at < raw.size(); at += 40, ++n) {
    std::string c = zlibCompress(raw.substr(at, 40));
    sizes += le<uint32_t>(uint32_t(c.size()));
    blocks += c;
  }
  return le<uint32_t>(n) + le<uint32_t>(40) + le<uint32_t>(uint32_t(raw.size() % 40)) + sizes + blocks;
}

std::string vtu(const std::string& format, bool compressed) {
  std::string pts, conn, offs, types;
  for (auto& p : kPts)
    for (double x : p) pts += le(x);
  for (auto& h : kHex)
    for (int v : h) conn += le<int64_t>(v);
  offs = le<int64_t>(8) + le<int64_t>(16);
  types = std::string("\x0C\x0C", 2);
  std::string head = std::string("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
                                  "byte_order=\"LittleEndian\" header_type=\"UInt32\"") +
                     (compressed ? " compressor=\"vtkZLibDataCompressor\"" : "") +
                     ">\n<UnstructuredGrid><Piece NumberOfPoints=\"12\" NumberOfCells=\"2\">\n";
  std::vector<std::pair<std::string, std::string>> arrays = {
      {"<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\"", pts},
      {"<Cells><DataArray type=\"Int64\" Name=\"connectivity\"", conn},
      {"<DataArray type=\"Int64\" Name=\"offsets\"", offs},
      {"<DataArray type=\"UInt8\" Name=\"types\"", types}};
  std::string body, appended;
  for (size_t i = 0; i < arrays.size(); ++i) {
    std::string close = i == 0 ? "</DataArray></Points>\n" : i == 3 ? "</DataArray></Cells>\n" : "</DataArray>\n";
    std::string block = vtuBlock(arrays[i].second, compressed);
    if (format == "binary") {
      // VTK encodes the header and the data separately (padding in the middle).
      size_t hdr = compressed ? 4 * (3 + (arrays[i].second.size() + 39) / 40) : 4;
      body += arrays[i].first + " format=\"binary\">" + base64(block.substr(0, hdr)) + base64(block.substr(hdr)) + close;
    } else {
      body += arrays[i].first + " format=\"appended\" offset=\"" + std::to_string(appended.size()) + "\"/>" +
              close.substr(std::string("</DataArray>").size());
      appended += block;
    }
  }
  std::string out = head + body + "</Piece></UnstructuredGrid>\n";
  if (format == "appended") out += "<AppendedData encoding=\"raw\">\n_" + appended + "\n</AppendedData>\n";
  return out + "</VTKFile>\n";
}

void checkTwoHexes(const Complex& cx) {
  CHECK(cx.numHexes() == 2);
  CHECK(cx.numVertices() == 12);
  CHECK(cx.counts() == makeGrid(2, 1, 1).counts());
}
}  // namespace

TEST_CASE("inflate agrees with zlib on random and structured data (fixed seeds)") {
  for (uint32_t seed = 1; seed <= 40; ++seed) {
    std::mt19937 rng(seed);
    size_t n = rng() % 200000;
    std::string s(n, '\0');
    int alphabet = 1 + int(rng() % 255);
    for (auto& c : s) c = char(rng() % uint32_t(alphabet));
    if (seed % 3 == 0)  // long repeats exercise lengths and distances
      for (size_t i = 300; i < n; ++i) s[i] = s[i - 1 - (rng() % 290)];
    for (int level : {0, 1, 6, 9}) {
      std::string z = zlibCompress(s, level);
      INFO("seed " << seed << " level " << level << " size " << n);
      CHECK(io::inflateZlib(z) == s);
    }
    CHECK(io::gunzip(gzipCompress(s)) == s);
  }
  MESSAGE("inflate vs zlib: seeds 1..40, levels 0/1/6/9 and gzip");
}

TEST_CASE("inflate refuses corrupt streams and outputs over the limit") {
  std::string s(100000, 'a');
  std::string z = zlibCompress(s);
  CHECK(io::inflateZlib(z) == s);
  CHECK(errorOf([&] { io::inflateZlib(z, 1000); }) == "inflate: output exceeds 1000 bytes");
  std::string bad = z;
  bad[bad.size() - 1] ^= 1;
  CHECK(errorOf([&] { io::inflateZlib(bad); }) == "inflate: Adler-32 checksum mismatch");
  CHECK(errorOf([&] { io::inflateZlib(z.substr(0, z.size() / 2)); }) == "inflate: compressed data ends early");
  CHECK(errorOf([] { io::inflateRaw(std::string("\x07", 1)); }) == "inflate: invalid block type 3");
  std::string gz = gzipCompress("hello");
  gz[gz.size() - 8] ^= 1;
  CHECK(errorOf([&] { io::gunzip(gz); }) == "inflate: gzip CRC-32 mismatch");
}

TEST_CASE("gzipped files of every format read transparently") {
  Complex ring = makeRing(6, 1, 2);
  for (std::string text : {io::writeVtk(ring), io::writeMedit(ring), io::writeNative(ring)}) {
    io::ReadReport rep;
    Complex cx = io::readMesh(gzipCompress(text), "z.gz", {}, &rep);
    CHECK(rep.gzipped);
    CHECK(cx.counts() == ring.counts());
  }
}

TEST_CASE("VTK legacy 5.1: OFFSETS/CONNECTIVITY with 32- and 64-bit ids, ASCII and binary") {
  for (std::string type : {"vtktypeint64", "vtktypeint32"}) {
    std::string a = "# vtk DataFile Version 5.1\nvtk output\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 12 double\n";
    for (auto& p : kPts) a += std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) + "\n";
    a += "METADATA\nINFORMATION 1\n\nNAME L2_NORM_RANGE LOCATION vtkDataArray\nDATA 2 0 1\n\n";
    a += "CELLS 3 16\nOFFSETS " + type + "\n0 8 16\nCONNECTIVITY " + type + "\n";
    for (auto& h : kHex)
      for (int v : h) a += std::to_string(v) + " ";
    a += "\nCELL_TYPES 2\n12\n12\nCELL_DATA 2\nFIELD FieldData 1\nq 1 2 double\n1 2\n";
    io::ReadReport rep;
    checkTwoHexes(io::readVtk(a, "a51.vtk", {}, &rep));
    CHECK(rep.format == "vtk 5.1 ascii");

    bool wide = type == "vtktypeint64";
    auto id = [&](int64_t v) { return wide ? be<int64_t>(v) : be<int32_t>(int32_t(v)); };
    std::string b = "# vtk DataFile Version 5.1\nvtk output\nBINARY\nDATASET UNSTRUCTURED_GRID\n"
                    "FIELD FieldData 1\nTIME 1 1 double\n" + be<double>(0.5) + "\nPOINTS 12 double\n";
    for (auto& p : kPts)
      for (double x : p) b += be(x);
    b += "\nCELLS 3 16\nOFFSETS " + type + "\n" + id(0) + id(8) + id(16) + "\nCONNECTIVITY " + type + "\n";
    for (auto& h : kHex)
      for (int v : h) b += id(v);
    b += "\nCELL_TYPES 2\n" + be<int32_t>(12) + be<int32_t>(12) + "\n";
    checkTwoHexes(io::readVtk(b, "b51.vtk", {}, &rep));
    CHECK(rep.format == "vtk 5.1 binary");
  }
}

TEST_CASE("VTK XML .vtu: ascii, inline base64, appended raw, each plain and zlib-compressed") {
  for (std::string format : {"binary", "appended"})
    for (bool compressed : {false, true}) {
      INFO(format << (compressed ? " zlib" : ""));
      io::ReadReport rep;
      checkTwoHexes(io::readMesh(vtu(format, compressed), "t.vtu", {}, &rep));
      CHECK(rep.format == (compressed ? "vtu zlib" : "vtu"));
    }
  std::string ascii = "<VTKFile type=\"UnstructuredGrid\"><UnstructuredGrid><Piece NumberOfPoints=\"12\" NumberOfCells=\"2\">"
                      "<Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">";
  for (auto& p : kPts) ascii += std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) + " ";
  ascii += "</DataArray></Points><Cells><DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">";
  for (auto& h : kHex)
    for (int v : h) ascii += std::to_string(v) + " ";
  ascii += "</DataArray><DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">8 16</DataArray>"
           "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">12 12</DataArray></Cells></Piece>"
           "</UnstructuredGrid></VTKFile>";
  checkTwoHexes(io::readMesh(ascii, "a.vtu"));
  CHECK(errorOf([&] { io::readMesh(replaced(ascii, "UnstructuredGrid\"", "PolyData\""), "p.vtu"); }) ==
        "p.vtu: byte 0: VTK XML type 'PolyData' is not supported (UnstructuredGrid)");
}

namespace {
std::string gmsh22(bool binary) {
  std::string s = std::string("$MeshFormat\n2.2 ") + (binary ? "1" : "0") + " 8\n";
  if (binary) s += le<int32_t>(1) + "\n";
  s += "$EndMeshFormat\n$PhysicalNames\n1\n3 1 \"vol\"\n$EndPhysicalNames\n$Nodes\n12\n";
  for (int i = 0; i < 12; ++i) {
    if (binary) s += le<int32_t>(i + 101) + le(kPts[i][0]) + le(kPts[i][1]) + le(kPts[i][2]);
    else s += std::to_string(i + 101) + " " + std::to_string(kPts[i][0]) + " " + std::to_string(kPts[i][1]) + " " +
              std::to_string(kPts[i][2]) + "\n";
  }
  s += std::string(binary ? "\n" : "") + "$EndNodes\n$Elements\n3\n";
  if (binary) {
    s += le<int32_t>(3) + le<int32_t>(1) + le<int32_t>(2) + le<int32_t>(1) + le<int32_t>(0) + le<int32_t>(0);
    for (int v : {0, 1, 4, 3}) s += le<int32_t>(v + 101);
    s += le<int32_t>(5) + le<int32_t>(2) + le<int32_t>(2);
    for (int e = 0; e < 2; ++e) {
      s += le<int32_t>(e + 2) + le<int32_t>(1) + le<int32_t>(1);
      for (int v : kHex[e]) s += le<int32_t>(v + 101);
    }
    s += "\n";
  } else {
    s += "1 3 2 0 0 101 102 105 104\n";
    for (int e = 0; e < 2; ++e) {
      s += std::to_string(e + 2) + " 5 2 1 1";
      for (int v : kHex[e]) s += " " + std::to_string(v + 101);
      s += "\n";
    }
  }
  return s + "$EndElements\n";
}
std::string gmsh41(bool binary) {
  std::string s = std::string("$MeshFormat\n4.1 ") + (binary ? "1" : "0") + " 8\n";
  if (binary) s += le<int32_t>(1) + "\n";
  s += "$EndMeshFormat\n$Entities\n0 0 0 1\n1 0 0 0 2 1 1 0 0\n$EndEntities\n$Nodes\n";
  auto sz = [&](uint64_t v) { return binary ? le<uint64_t>(v) : std::to_string(v) + " "; };
  auto in = [&](int32_t v) { return binary ? le<int32_t>(v) : std::to_string(v) + " "; };
  auto re = [&](double v) { return binary ? le<double>(v) : std::to_string(v) + " "; };
  s += sz(1) + sz(12) + sz(1) + sz(12) + in(3) + in(1) + in(0) + sz(12);
  for (int i = 0; i < 12; ++i) s += sz(uint64_t(i + 1));
  for (auto& p : kPts) s += re(p[0]) + re(p[1]) + re(p[2]);
  s += "\n$EndNodes\n$Elements\n" + sz(2) + sz(3) + sz(1) + sz(3);
  s += in(2) + in(1) + in(3) + sz(1) + sz(1) + sz(1) + sz(2) + sz(5) + sz(4);
  s += in(3) + in(1) + in(5) + sz(2);
  for (int e = 0; e < 2; ++e) {
    s += sz(uint64_t(e + 2));
    for (int v : kHex[e]) s += sz(uint64_t(v + 1));
  }
  return s + "\n$EndElements\n";
}
}  // namespace

TEST_CASE("Gmsh 2.2 and 4.1, ASCII and binary: hexes read, the quad skipped and counted") {
  for (bool binary : {false, true}) {
    io::ReadReport rep;
    checkTwoHexes(io::readMesh(gmsh22(binary), "a.msh", {}, &rep));
    CHECK(rep.format == std::string("gmsh 2.2 ") + (binary ? "binary" : "ascii"));
    CHECK(rep.quadCells == 1);
    checkTwoHexes(io::readMesh(gmsh41(binary), "b.msh", {}, &rep));
    CHECK(rep.format == std::string("gmsh 4.1 ") + (binary ? "binary" : "ascii"));
    CHECK(rep.quadCells == 1);
  }
  CHECK(errorOf([] { io::readMesh(replaced(gmsh22(false), "2 5 2 1 1 101", "2 5 2 1 1 999"), "c.msh"); }) ==
        "c.msh: element 2 uses node 999, which $Nodes does not define");
}

TEST_CASE("Medit binary (.meshb) versions 1 to 4") {
  for (int version = 1; version <= 4; ++version) {
    auto pos = [&](int64_t v) { return version >= 3 ? le<int64_t>(v) : le<int32_t>(int32_t(v)); };
    auto idx = [&](int64_t v) { return version == 4 ? le<int64_t>(v) : le<int32_t>(int32_t(v)); };
    auto real = [&](double v) { return version == 1 ? le<float>(float(v)) : le<double>(v); };
    std::string s = le<int32_t>(1) + le<int32_t>(version);
    auto section = [&](int kw, const std::string& body) {
      size_t next = s.size() + 4 + (version >= 3 ? 8 : 4) + body.size();
      s += le<int32_t>(kw) + pos(int64_t(next)) + body;
    };
    section(3, le<int32_t>(3));
    std::string v = idx(12);
    for (auto& p : kPts) v += real(p[0]) + real(p[1]) + real(p[2]) + idx(0);
    section(4, v);
    std::string q = idx(1) + idx(1) + idx(2) + idx(5) + idx(4) + idx(7);
    section(7, q);
    std::string h = idx(2);
    for (auto& hx : kHex) {
      for (int c : hx) h += idx(c + 1);
      h += idx(0);
    }
    section(10, h);
    s += le<int32_t>(54);
    io::ReadReport rep;
    checkTwoHexes(io::readMesh(s, "m.meshb", {}, &rep));
    CHECK(rep.format == "medit binary v" + std::to_string(version));
    CHECK(rep.quadCells == 1);
  }
}

TEST_CASE("mixed files: lower-dimensional cells skipped and counted; tets refused or dropped with hexesOnly") {
  std::string vtk = "# vtk DataFile Version 3.0\nm\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 13 double\n";
  for (auto& p : kPts) vtk += std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) + "\n";
  vtk += "5 5 5\nCELLS 7 37\n8 0 1 4 3 6 7 10 9\n8 1 2 5 4 7 8 11 10\n1 0\n2 0 1\n3 0 1 4\n4 0 1 4 3\n4 2 5 8 11\n"
         "CELL_TYPES 7\n12\n12\n1\n3\n5\n9\n10\n";
  CHECK(errorOf([&] { io::readVtk(vtk, "mix.vtk"); }) ==
        "mix.vtk: the file holds 1 tetrahedron, 0 prisms and 0 pyramids besides 2 hexahedra; hexdual reads hex meshes "
        "(--hexes-only, or { hexesOnly: true } in the package, reads the hex part)");
  io::ReadReport rep;
  io::ReadOptions opt;
  opt.hexesOnly = true;
  checkTwoHexes(io::readVtk(vtk, "mix.vtk", opt, &rep));
  CHECK(rep.vertexCells == 1);
  CHECK(rep.lineCells == 1);
  CHECK(rep.triangleCells == 1);
  CHECK(rep.quadCells == 1);
  CHECK(rep.tetrahedra == 1);
  CHECK(rep.points == 13);
  CHECK(rep.unusedVertices == 1);
  CHECK(io::reportText(rep) ==
        "file vtk 3.0 ascii, 13 points (1 used by no hex, not in the complex)\n"
        "skipped lower-dimensional cells: 1 vertices, 1 lines, 1 triangles, 1 quads\n"
        "dropped (--hexes-only): 1 tetrahedra, 0 prisms, 0 pyramids\n");
  CHECK(io::reportJson(rep) ==
        "{\"format\":\"vtk 3.0 ascii\",\"gzipped\":false,\"points\":13,\"unusedVertices\":1,\"skipped\":{\"vertices\":1,"
        "\"lines\":1,\"triangles\":1,\"quads\":1},\"dropped\":{\"tetrahedra\":1,\"prisms\":0,\"pyramids\":0},"
        "\"nonManifoldVertices\":[]}");
}

TEST_CASE("a non-manifold vertex: the mesh opens, validate names it, operations touching it are refused") {
  // A 3x1x1 row of cubes and one more cube touching the last at its corner (3,1,1) only.
  std::vector<Vec3> pts;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 4; ++i) pts.push_back({double(i), double(j), double(k)});
  for (Vec3 p : {Vec3{4, 1, 1}, Vec3{4, 2, 1}, Vec3{3, 2, 1}, Vec3{3, 1, 2}, Vec3{4, 1, 2}, Vec3{4, 2, 2}, Vec3{3, 2, 2}})
    pts.push_back(p);
  std::vector<std::array<VertexId, 8>> hexes;
  for (int i = 0; i < 3; ++i) hexes.push_back({i, i + 1, i + 5, i + 4, i + 8, i + 9, i + 13, i + 12});
  hexes.push_back({15, 16, 17, 18, 19, 20, 21, 22});
  CHECK(contains(errorOf([&] { fromConnectivity(pts, hexes); }), "vertex 15 is non-manifold: its link has 2 components"));
  Complex cx = fromConnectivity(pts, hexes, true);
  CHECK(cx.nonManifoldVertices() == std::vector<VertexId>{15});
  cx.validate();
  auto issues = vertexLinkIssues(cx);
  REQUIRE(issues.size() == 1);
  CHECK(describeLinkIssue(cx, issues[0]) == "vertex 15 at (3, 1, 1) in hexes 2, 3 is non-manifold: its link has 2 components");
  // A pillow between hexes 1 and 2 touches the vertex: refused, nothing changed.
  std::string before = io::writeNative(cx);
  CHECK(errorOf([&] { pillow(cx, {1, 1}); }) ==
        "pillow: touches non-manifold vertex 15 at (3, 1, 1) (its link is not a sphere or a disk; see hexdual validate)");
  CHECK(io::writeNative(cx) == before);
  // One between hexes 0 and 1 does not: it applies.
  CHECK(pillow(cx, {0, 1}).createdHexes.size() == 2);
  cx.validate();
  // The native format keeps it; the dual is defined (sheets and chords).
  Complex back = io::readNative(io::writeNative(cx), "nm.hxd");
  CHECK(back.nonManifoldVertices() == std::vector<VertexId>{15});
  CHECK(extractDual(back).sheets.size() > 0);
}
