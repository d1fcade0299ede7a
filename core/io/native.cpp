// The native format (.hxd): vertices, hexes and explicit gluings, so that degenerate states
// (two hexes on the same 8 vertices, two quads on the same 4) survive a round trip.
//   hexdual 1
//   vertices N        then N lines "x y z"
//   hexes H           then H lines of 8 vertex indices (VTK corner order)
//   gluings G         then G lines "hexA faceA hexB faceB orient" (each interior quad once)
//   end
#include <cmath>
#include <cstdio>

#include "complex/manifold.hpp"
#include "io/dense.hpp"
#include "io/cells.hpp"
#include "io/io.hpp"
#include "io/lexer.hpp"

namespace hexdual::io {

Complex readNative(std::string_view data, const std::string& name, ReadReport* rep) {
  Lexer lx(data, name);
  lx.expectKeyword("hexdual");
  int64_t version = lx.integer("a format version");
  if (version != 1) lx.fail("format version " + std::to_string(version) + " is not supported (1)");
  Complex cx;
  lx.expectKeyword("vertices");
  int64_t nv = lx.count("number of vertices");
  checkCountFits(name, "vertices", nv, data.size() - lx.offset(), 6);
  cx.reserve(0, size_t(nv));
  for (int64_t i = 0; i < nv; ++i) {
    Vec3 p{lx.real("a coordinate"), lx.real("a coordinate"), lx.real("a coordinate")};
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      lx.fail("vertex " + std::to_string(i) + " has a coordinate that is not a finite number");
    cx.addVertex(p);
  }
  lx.expectKeyword("hexes");
  int64_t nh = lx.count("number of hexes");
  checkCountFits(name, "hexes", nh, data.size() - lx.offset(), 16);
  for (int64_t h = 0; h < nh; ++h) {
    std::array<VertexId, 8> v;
    for (int c = 0; c < 8; ++c) {
      int64_t x = lx.integer("a vertex index");
      if (x < 0 || x >= nv)
        lx.fail("hex " + std::to_string(h) + " uses vertex " + std::to_string(x) + ", out of range (" + std::to_string(nv) +
                " vertices)");
      v[size_t(c)] = VertexId(x);
    }
    cx.addHex(v);
  }
  lx.expectKeyword("gluings");
  int64_t ng = lx.count("number of gluings");
  for (int64_t i = 0; i < ng; ++i) {
    int64_t a = lx.integer("a hex index"), fa = lx.integer("a face"), b = lx.integer("a hex index"),
            fb = lx.integer("a face"), o = lx.integer("an orientation");
    if (a < 0 || a >= nh || b < 0 || b >= nh) lx.fail("gluing " + std::to_string(i) + " names a hex out of range");
    if (fa < 0 || fa > 5 || fb < 0 || fb > 5) lx.fail("gluing " + std::to_string(i) + " names a face out of range (0..5)");
    if (o < 0 || o > 7) lx.fail("gluing " + std::to_string(i) + " has orientation " + std::to_string(o) + " (0..7)");
    if (!cx.gluing(HexId(a), int(fa)).boundary() || !cx.gluing(HexId(b), int(fb)).boundary())
      lx.fail("gluing " + std::to_string(i) + " glues a face that is already glued");
    if (a == b && fa == fb) lx.fail("gluing " + std::to_string(i) + " glues a face to itself");
    cx.glue(HexId(a), int(fa), HexId(b), int(fb), int(o));
  }
  lx.expectKeyword("end");
  try {
    cx.validateAcceptingNonManifoldVertices();
  } catch (const Error& e) {
    throw Error(name + ": " + e.what());
  }
  if (rep) {
    rep->format = "hexdual 1";
    rep->points = nv;
    rep->unusedVertices = nv - cx.numVertices();
    rep->nonManifoldVertices = cx.nonManifoldVertices();
  }
  return cx;
}

std::string writeNative(const Complex& cx) {
  Dense d = denseNumbering(cx);
  std::string out = "hexdual 1\nvertices " + std::to_string(d.vertices.size()) + "\n";
  char buf[128];
  for (VertexId v : d.vertices) {
    Vec3 p = cx.position(v);
    std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g\n", p.x, p.y, p.z);
    out += buf;
  }
  out += "hexes " + std::to_string(d.hexes.size()) + "\n";
  for (HexId h : d.hexes) {
    for (int c = 0; c < 8; ++c) out += (c ? " " : "") + std::to_string(d.vertexIndex[size_t(cx.vertex(h, c))]);
    out += "\n";
  }
  std::string glue;
  int64_t ng = 0;
  for (HexId h : d.hexes)
    for (int f = 0; f < 6; ++f) {
      Gluing g = cx.gluing(h, f);
      if (g.boundary() || QuadSide{g.hex, g.face} < QuadSide{h, f}) continue;
      glue += std::to_string(d.hexIndex[size_t(h)]) + " " + std::to_string(f) + " " +
              std::to_string(d.hexIndex[size_t(g.hex)]) + " " + std::to_string(g.face) + " " + std::to_string(g.orient) +
              "\n";
      ++ng;
    }
  out += "gluings " + std::to_string(ng) + "\n" + glue + "end\n";
  return out;
}

}  // namespace hexdual::io
