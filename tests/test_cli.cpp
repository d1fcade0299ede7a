// The CLI as a user runs it: exit status and output.
#include <doctest/doctest.h>

#include <array>
#include <cstdio>
#include <string>

#include "helpers.hpp"

using namespace hexdual::test;

namespace {
struct Run {
  int status;
  std::string out;
};
Run run(const std::string& args) {
  std::string cmd = std::string(HEXDUAL_CLI) + " " + args + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  REQUIRE(p);
  std::string out;
  std::array<char, 4096> buf;
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) out.append(buf.data(), n);
  int st = pclose(p);
  return {WEXITSTATUS(st), out};
}
}  // namespace

TEST_CASE("cli: grid, info --json, validate, convert") {
  CHECK(run("grid 3x3x3 -o /tmp/hexdual_cli_g.vtk").status == 0);
  Run info = run("info /tmp/hexdual_cli_g.vtk --json");
  CHECK(info.status == 0);
  CHECK(contains(info.out, "{\"vertices\":64,\"edges\":144,\"quads\":108,\"hexes\":27,\"boundaryQuads\":54,\"sheets\":["));
  CHECK(contains(info.out, "{\"id\":0,\"hexes\":9,\"topology\":\"disk\",\"boundaryLoops\":1,\"euler\":1,\"selfIntersecting\":false}"));
  CHECK(contains(info.out, "{\"id\":26,\"hexes\":3,\"closed\":false,\"selfIntersecting\":false}]}"));
  CHECK(run("convert /tmp/hexdual_cli_g.vtk /tmp/hexdual_cli_g.mesh").status == 0);
  CHECK(run("convert /tmp/hexdual_cli_g.mesh /tmp/hexdual_cli_g.hxd").status == 0);
  Run v = run("validate /tmp/hexdual_cli_g.hxd");
  CHECK(v.status == 0);
  CHECK(v.out == "/tmp/hexdual_cli_g.hxd: valid (27 hexes)\n");
  CHECK(run("ring 8x2x2 -o /tmp/hexdual_cli_r.vtk --binary").status == 0);
  CHECK(contains(run("info /tmp/hexdual_cli_r.vtk").out, "sheet 0: 16 hexes, annulus, 2 boundary loop(s), euler 0"));
}

TEST_CASE("cli: bad input gives a one-line error and a non-zero status") {
  Run missing = run("info /tmp/does-not-exist.vtk");
  CHECK(missing.status == 1);
  CHECK(missing.out == "hexdual: /tmp/does-not-exist.vtk: cannot open file\n");
  Run dims = run("grid 3x3 -o /tmp/x.vtk");
  CHECK(dims.status == 1);
  CHECK(dims.out == "hexdual: dimensions must look like 3x3x3, not '3x3'\n");
  CHECK(run("frobnicate").status == 1);
  CHECK(run("").status == 2);
}
