// The host a search must keep: a snapshot of the host hexes (vertices, gluings among them, edges)
// and the check that a state kept it (locality, flips/search.hpp); the region of a state and its
// canonical labelling.
#include "flips/search_parts.hpp"

#include <algorithm>

#include "flips/fourcube.hpp"

namespace hexdual::flipsearch {
using namespace tables;

std::vector<EdgeRef> hostIncidences(const Complex& cx, const std::vector<HexId>& host, EdgeRef e) {
  std::vector<EdgeRef> out;
  for (EdgeRef x : cx.edgeCycle(e))
    if (isHost(host, x.hex)) out.push_back(x);
  std::sort(out.begin(), out.end());
  return out;
}

HostSnapshot snapshot(const Complex& cx, std::vector<HexId> host) {
  HostSnapshot s;
  std::sort(host.begin(), host.end());
  s.host = host;
  for (HexId h : host) {
    s.verts.push_back(cx.hexVertices(h));
    std::array<Gluing, 6> g;
    for (int f = 0; f < 6; ++f) {
      g[size_t(f)] = cx.gluing(h, f);
      if (!g[size_t(f)].boundary() && !isHost(host, g[size_t(f)].hex)) g[size_t(f)] = Gluing{-2, 0, 0};
    }
    s.hostGlue.push_back(g);
    std::vector<std::vector<EdgeRef>> es;
    for (int e = 0; e < 12; ++e) es.push_back(hostIncidences(cx, host, {h, e}));
    s.edges.push_back(es);
  }
  return s;
}

// Why a state is not local, or "" when it is.
std::string localityViolation(const Complex& cx, const HostSnapshot& s) {
  for (size_t i = 0; i < s.host.size(); ++i) {
    HexId h = s.host[i];
    if (!cx.isHex(h)) return "host hex " + std::to_string(h) + " was removed";
    if (cx.hexVertices(h) != s.verts[i]) return "host hex " + std::to_string(h) + " changed its vertices";
    for (int f = 0; f < 6; ++f) {
      Gluing g = cx.gluing(h, f), was = s.hostGlue[i][size_t(f)];
      bool toHost = !g.boundary() && isHost(s.host, g.hex);
      if (was.hex >= 0 || toHost) {
        if (g.hex != was.hex || g.face != was.face || g.orient != was.orient)
          return "host hex " + std::to_string(h) + " face " + std::to_string(f) + " changed its host gluing";
      } else if ((was.hex == -1) != g.boundary()) {  // -1: was boundary, -2: was glued to the region
        return "host hex " + std::to_string(h) + " face " + std::to_string(f) + " changed between boundary and region";
      }
    }
    for (int e = 0; e < 12; ++e)
      if (hostIncidences(cx, s.host, {h, e}) != s.edges[i][size_t(e)])
        return "host hex " + std::to_string(h) + " edge " + std::to_string(e) + " was split or merged";
  }
  return "";
}

std::vector<HexId> regionOf(const Complex& cx, const std::vector<HexId>& host) {
  std::vector<HexId> r;
  for (HexId h : cx.hexes())
    if (!isHost(host, h)) r.push_back(h);
  return r;
}

CanonicalLabelling regionLabelling(const Complex& cx, const std::vector<HexId>& host) {
  return canonicalLabelling(subcomplex(cx, regionOf(cx, host)), true);
}

}  // namespace hexdual::flipsearch
