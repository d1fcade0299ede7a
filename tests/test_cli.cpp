// The CLI as a user runs it: exit status and output.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cstdio>
#include <string>

#include "helpers.hpp"

using namespace hexdual::test;

namespace {
using Run = CliRun;
Run run(const std::string& args) { return runCli(args); }
}  // namespace

TEST_CASE("cli: grid, info --json, validate, convert") {
  CHECK(run("grid 3x3x3 -o /tmp/hexdual_cli_g.vtk").status == 0);
  Run info = run("info /tmp/hexdual_cli_g.vtk --json");
  CHECK(info.status == 0);
  CHECK(contains(info.out, "{\"vertices\":64,\"edges\":144,\"quads\":108,\"hexes\":27,\"boundaryQuads\":54,\"sheets\":["));
  CHECK(contains(info.out, "{\"id\":0,\"hexes\":9,\"topology\":\"disk\",\"boundaryLoops\":1,\"euler\":1,\"selfIntersecting\":false}"));
  // The singularity graph of the block: its 12 edges of 3 unit edges each (valence 1 on the
  // boundary) and its 8 corners.
  CHECK(contains(info.out, "{\"id\":26,\"hexes\":3,\"closed\":false,\"selfIntersecting\":false}],\"singularities\":{\"interiorEdges\":0,"
                           "\"boundaryEdges\":36,\"interiorByValence\":{},\"boundaryByValence\":{\"1\":36},\"vertices\":8,"
                           "\"boundaryVertices\":8,\"curves\":12},\"file\":{\"format\":\"vtk 3.0 ascii\""));
  CHECK(run("convert /tmp/hexdual_cli_g.vtk /tmp/hexdual_cli_g.mesh").status == 0);
  CHECK(run("convert /tmp/hexdual_cli_g.mesh /tmp/hexdual_cli_g.hxd").status == 0);
  Run v = run("validate /tmp/hexdual_cli_g.hxd");
  CHECK(v.status == 0);
  CHECK(v.out == "/tmp/hexdual_cli_g.hxd: valid (27 hexes)\n");
  CHECK(run("ring 8x2x2 -o /tmp/hexdual_cli_r.vtk --binary").status == 0);
  CHECK(contains(run("info /tmp/hexdual_cli_r.vtk").out, "sheet 0: 16 hexes, annulus, 2 boundary loop(s), euler 0"));
}

TEST_CASE("cli: validate names each non-manifold vertex and exits 1; a valid file exits 0") {
  // Two unit cubes touching at one corner (vertex 6 of the first is vertex 0 of the second): the
  // reader accepts the file and keeps the vertex; validate explains it.
  {
    std::FILE* f = std::fopen("/tmp/hexdual_cli_touch.vtk", "w");
    REQUIRE(f);
    std::fputs("# vtk DataFile Version 3.0\ntouch\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 15 double\n", f);
    const char* pts[] = {"0 0 0", "1 0 0", "1 1 0", "0 1 0", "0 0 1", "1 0 1", "1 1 1", "0 1 1",
                         "2 1 1", "2 2 1", "1 2 1", "1 1 2", "2 1 2", "2 2 2", "1 2 2"};
    for (const char* p : pts) std::fprintf(f, "%s\n", p);
    std::fputs("CELLS 2 18\n8 0 1 2 3 4 5 6 7\n8 6 8 9 10 11 12 13 14\nCELL_TYPES 2\n12\n12\n", f);
    std::fclose(f);
  }
  Run touch = run("validate /tmp/hexdual_cli_touch.vtk");
  CHECK(touch.status == 1);
  CHECK(touch.out ==
        "/tmp/hexdual_cli_touch.vtk: vertex 6 at (1, 1, 1) in hexes 0, 1 is non-manifold: its link has 2 components\n"
        "/tmp/hexdual_cli_touch.vtk: 1 non-manifold vertices; otherwise valid (2 hexes); operations refuse to touch "
        "these vertices\n");
  CHECK(run("grid 2x2x2 -o /tmp/hexdual_cli_g2.vtk").status == 0);
  CHECK(run("validate /tmp/hexdual_cli_g2.vtk").out == "/tmp/hexdual_cli_g2.vtk: valid (8 hexes)\n");
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

TEST_CASE("cli: apply writes the result and reports each step; a failing step writes nothing") {
  CHECK(run("grid 3x3x3 -o /tmp/hexdual_cli_a.hxd").status == 0);
  std::remove("/tmp/hexdual_cli_a2.hxd");
  Run ok = run("apply /tmp/hexdual_cli_a.hxd --ops 'v1;pillow h13f5;hexpush h13f5' -o /tmp/hexdual_cli_a2.hxd --json");
  CHECK(ok.status == 0);
  CHECK(contains(ok.out, "\"step\":1,\"op\":\"pillow\",\"text\":\"pillow h13f5\",\"createdHexes\":[27,28]"));
  CHECK(contains(ok.out, "\"delta\":{\"V\":4,\"E\":8,\"F\":6,\"H\":2}"));
  CHECK(contains(ok.out, "\"delta\":{\"V\":4,\"E\":12,\"F\":12,\"H\":4}"));
  CHECK(contains(ok.out, "\"sheets\":{\"created\":[9],\"removed\":[],\"changed\":[3,5]}"));
  CHECK(contains(ok.out, "\"counts\":{\"vertices\":72,\"edges\":164,\"quads\":126,\"hexes\":33}"));
  CHECK(contains(run("info /tmp/hexdual_cli_a2.hxd").out, "hexes 33"));
  // The URL form gives the same result.
  Run url = run("apply /tmp/hexdual_cli_a.hxd --ops 1.P13f5.H13f5 -o /tmp/hexdual_cli_a3.hxd");
  CHECK(url.status == 0);
  CHECK(contains(url.out, "delta (V,E,F,H) = (+4,+12,+12,+4)"));
  std::remove("/tmp/hexdual_cli_a4.hxd");
  Run bad = run("apply /tmp/hexdual_cli_a.hxd --ops 'v1;pillow h13f5;hexpush h0f0' -o /tmp/hexdual_cli_a4.hxd");
  CHECK(bad.status == 1);
  CHECK(bad.out ==
        "hexdual: step 2 (hexpush h0f0): hexpush: quad h0f0 is on the boundary; hex push needs an interior quad; "
        "nothing was written\n");
  CHECK(run("info /tmp/hexdual_cli_a4.hxd").status == 1);
  Run parse = run("apply /tmp/hexdual_cli_a.hxd --ops 'v1;pilow h1f1' -o /tmp/x.hxd");
  CHECK(parse.out == "hexdual: oplog: position 3: unknown operation at 'pilow'\n");
}

TEST_CASE("cli: apply -o gives the last step's inverse in the written file's numbering; it applies to that file") {
  CHECK(run("grid 4x4x4 -o /tmp/hexdual_cli_inv.vtk").status == 0);
  // Extracting the i = 1 layer removes hexes 1, 5, 9, ...: the file numbers the 48 left densely.
  Run x = run("apply /tmp/hexdual_cli_inv.vtk --ops 'v1;sheet-extract h1e0' -o /tmp/hexdual_cli_inv_x.vtk --json");
  CHECK(x.status == 0);
  CHECK(contains(x.out, "\"inverse\":\"sheet-insert h0f1 h4f1 h8f1 h12f1 "));
  CHECK(contains(x.out, "\"inverseInOutput\":\"sheet-insert h0f1 h3f1 h6f1 h9f1 h12f1 h15f1 h18f1 h21f1 h24f1 h27f1 h30f1 h33f1 "
                        "h36f1 h39f1 h42f1 h45f1\"}"));
  Run text = run("apply /tmp/hexdual_cli_inv.vtk --ops 'v1;sheet-extract h1e0' -o /tmp/hexdual_cli_inv_x.hxd");
  CHECK(contains(text.out, "inverse of the last step in /tmp/hexdual_cli_inv_x.hxd (which numbers hexes densely): sheet-insert h0f1 h3f1 "));
  // Applied to the file, it gives the grid back: 64 hexes, 12 layers of 16, none inverted (the
  // merged vertices moved, so the hexes are not all cubes again).
  Run back = run("apply /tmp/hexdual_cli_inv_x.vtk --ops 'v1;sheet-insert h0f1 h3f1 h6f1 h9f1 h12f1 h15f1 h18f1 h21f1 h24f1 h27f1 "
                 "h30f1 h33f1 h36f1 h39f1 h42f1 h45f1' -o /tmp/hexdual_cli_inv_b.vtk --json");
  CHECK(back.status == 0);
  CHECK(contains(back.out, "\"counts\":{\"vertices\":125,\"edges\":300,\"quads\":240,\"hexes\":64}"));
  Run info = run("info /tmp/hexdual_cli_inv_b.vtk");
  CHECK(contains(info.out, "sheet 11: 16 hexes, disk"));
  CHECK(contains(run("quality /tmp/hexdual_cli_inv_b.vtk").out, "; 0 <= 0\n"));
  // A preview names a long step by its first 8 arguments.
  Run pv = run("preview /tmp/hexdual_cli_inv_x.vtk --ops 'v1;sheet-insert h0f1 h3f1 h6f1 h9f1 h12f1 h15f1 h18f1 h21f1 h24f1 "
               "h27f1 h30f1 h33f1 h36f1 h39f1 h42f1 h45f1'");
  CHECK(pv.out.rfind("preview: sheet-insert h0f1 h3f1 h6f1 h9f1 h12f1 h15f1 h18f1 h21f1 ... (16 arguments) would remove 0 hexes "
                     "and create 16; nothing was changed\n", 0) == 0);
  // Nothing written: no inverse in the output's numbering.
  CHECK(contains(run("apply /tmp/hexdual_cli_inv.vtk --ops 'v1;sheet-extract h1e0' --dry-run --json").out, "\"inverseInOutput\":null}"));
  // --binary is for VTK only: refused for .mesh, and nothing is written.
  std::remove("/tmp/hexdual_cli_inv.mesh");
  Run bin = run("convert /tmp/hexdual_cli_inv.vtk /tmp/hexdual_cli_inv.mesh --binary");
  CHECK(bin.status == 1);
  CHECK(bin.out == "hexdual: --binary applies to .vtk only, not .mesh (hexdual writes .mesh and .hxd as text)\n");
  CHECK(run("info /tmp/hexdual_cli_inv.mesh").status == 1);
}

TEST_CASE("cli: candidates lists only steps that apply") {
  CHECK(run("grid 3x3x3 -o /tmp/hexdual_cli_c.hxd").status == 0);
  Run hp = run("candidates /tmp/hexdual_cli_c.hxd hexpush");
  CHECK(hp.status == 0);
  CHECK(std::count(hp.out.begin(), hp.out.end(), '\n') == 54);  // every interior quad of a 3x3x3 grid
  CHECK(run("candidates /tmp/hexdual_cli_c.hxd ringcollapse").out.empty());  // a grid has no closed chord
  CHECK(run("candidates /tmp/hexdual_cli_c.hxd unpillow").out.empty());
  CHECK(run("apply /tmp/hexdual_cli_c.hxd --ops 'v1;pillow h13f5' -o /tmp/hexdual_cli_c2.hxd").status == 0);
  CHECK(run("candidates /tmp/hexdual_cli_c2.hxd unpillow").out == "unpillow h27\nunpillow h28\n");
  CHECK(run("candidates /tmp/hexdual_cli_c.hxd frob").out == "hexdual: candidates: unknown operation 'frob'\n");
}

TEST_CASE("cli: sheets writes SVG and JSON diagrams; bad arguments are one-line errors") {
  CHECK(run("grid 3x3x3 -o /tmp/hexdual_cli_s.hxd").status == 0);
  CHECK(std::system("rm -rf /tmp/hexdual_cli_sd && mkdir -p /tmp/hexdual_cli_sd") == 0);
  Run all = run("sheets /tmp/hexdual_cli_s.hxd --all --svg /tmp/hexdual_cli_sd --json /tmp/hexdual_cli_sd");
  CHECK(all.status == 0);
  CHECK(std::count(all.out.begin(), all.out.end(), '\n') == 18);  // 9 sheets x (json + svg)
  Run local = run("sheets /tmp/hexdual_cli_s.hxd --sheet 2 --local 4 --rings 1 --json /tmp/hexdual_cli_sd");
  CHECK(local.out == "/tmp/hexdual_cli_sd/sheet-2-local.json\n");
  FILE* f = std::fopen("/tmp/hexdual_cli_sd/sheet-2-local.json", "r");
  REQUIRE(f);
  std::string text(4096, '\0');
  text.resize(std::fread(text.data(), 1, text.size(), f));
  std::fclose(f);
  CHECK(contains(text, "{\"sheet\":2,\"topology\":\"disk\",\"method\":\"local\",\"local\":true"));
  CHECK(run("sheets /tmp/hexdual_cli_s.hxd --sheet 2").out == "hexdual: sheets needs --json OUTDIR or --svg OUTDIR\n");
  CHECK(run("sheets /tmp/hexdual_cli_s.hxd --sheet 99 --svg /tmp/hexdual_cli_sd").out ==
        "hexdual: sheet diagram: sheet 99 does not exist\n");
  // A missing output directory is made (as mkdir -p); one that cannot be made is named with the reason.
  std::remove("/tmp/hexdual_cli_sd_new/deeper/sheet-1.svg");
  CHECK(run("sheets /tmp/hexdual_cli_s.hxd --sheet 1 --svg /tmp/hexdual_cli_sd_new/deeper").out ==
        "/tmp/hexdual_cli_sd_new/deeper/sheet-1.svg\n");
  CHECK(run("sheets /tmp/hexdual_cli_s.hxd --sheet 1 --svg /tmp/hexdual_cli_s.hxd/dir").out ==
        "hexdual: /tmp/hexdual_cli_s.hxd/dir: cannot create the output directory (Not a directory)\n");
}

TEST_CASE("cli: flip search stopped at a cap writes a checkpoint; --resume finishes it with the uninterrupted result") {
  const std::string search = "flip search 3-5e --max-depth 4 --symmetry --threads 1";
  // The record without its seconds field (field 7 of 8).
  auto record = [](const std::string& out) {
    std::string line = out.substr(out.rfind("3-5e|"));
    line = line.substr(0, line.find('\n'));
    size_t end = line.rfind('|'), start = line.rfind('|', end - 1);
    return line.substr(0, start) + line.substr(end);
  };
  Run whole = run(search);
  CHECK(whole.status == 0);
  CHECK(record(whole.out) == "3-5e|found|v1;hexpush h0f0;facecollapse h1e8 h9f2 h4f1;facesplit h6f4 h12f2;chordpull h4|4|4|896|all");
  std::remove("/tmp/hexdual_cli_search.ckpt");
  Run capped = run(search + " --max-states 100 --checkpoint /tmp/hexdual_cli_search.ckpt");
  CHECK(capped.status == 0);
  CHECK(contains(capped.out, "stopped at the state cap (--max-states 100) during depth 3; checkpoint in /tmp/hexdual_cli_search.ckpt\n"));
  CHECK(contains(capped.out, "1 checkpoint(s) written to /tmp/hexdual_cli_search.ckpt\n"));
  Run resumed = run(search + " --resume /tmp/hexdual_cli_search.ckpt");
  CHECK(resumed.status == 0);
  CHECK(record(resumed.out) == record(whole.out));
  CHECK(contains(whole.out, "depth 1 from the start"));
  CHECK_FALSE(contains(resumed.out, "depth 1 from the start"));  // it went on from the checkpoint
  CHECK(run(search + " --checkpoint-every 5").out == "hexdual: --checkpoint-every needs --checkpoint FILE\n");
  Run missing = run(search + " --resume /tmp/hexdual_cli_no_such.ckpt");
  CHECK(missing.status == 1);
  CHECK(missing.out == "hexdual: resume: cannot read /tmp/hexdual_cli_no_such.ckpt\n");
  // A checkpoint of the stored mode is not resumed by a search with the last level by lookup.
  Run other = run(search + " --lookup-last --resume /tmp/hexdual_cli_search.ckpt");
  CHECK(other.status == 1);
  CHECK(contains(other.out, "belongs to another search (3-5e; depth 4;"));
  CHECK(contains(other.out, "chunk 512), not this one (3-5e; depth 4;"));
  CHECK(contains(other.out, "chunk 512; last level by lookup)\n"));
}

TEST_CASE("cli: flip search --lookup-last: the last level looked up, not stored; the same answer") {
  Run r = run("flip search 4-4v --max-depth 5 --symmetry --lookup-last");
  CHECK(r.status == 0);
  CHECK(contains(r.out, "depth 2 from the goal: 333 new states, 682 stored,"));
  CHECK(contains(r.out, "depth 3 from the start: looked up (not stored), 682 stored,"));
  CHECK(contains(r.out, "4-4v|none|-|5|5|682|"));
  CHECK(contains(r.out, "none found; stopped by depth after 682 states,"));
  CHECK(contains(r.out, ", 24 symmetries, 6746 image keys looked up\n"));
  Run found = run("flip search 3-5e --max-depth 4 --symmetry --lookup-last");
  CHECK(contains(found.out, "3-5e|found|v1;hexpush h0f0;facecollapse h1e8 h9f2 h4f1;facesplit h6f4 h12f2;chordpull h4|4|4|487|"));
  CHECK(contains(found.out, "found 4 steps (verified)"));
}
