#include <doctest/doctest.h>

#include <cmath>

#include "complex/builders.hpp"
#include "layout/quality.hpp"

using namespace hexdual;

TEST_CASE("quality: a grid of cubes has scaled Jacobian 1 everywhere") {
  Complex cx = makeGrid(2, 2, 2);
  QualityReport q = measureQuality(cx);
  CHECK(q.scaledJacobian.size() == 8);
  for (float v : q.scaledJacobian) CHECK(v == doctest::Approx(1));
  CHECK(q.inverted.empty());
  CHECK(q.min == doctest::Approx(1));
  CHECK(q.max == doctest::Approx(1));
}

TEST_CASE("quality: a sheared hex, an inverted hex and a collapsed corner") {
  Complex cx = makeGrid(1, 1, 1);
  // Shear the top face by 1 along x: the corner frames at the bottom get x-z angle 45 degrees.
  for (int c = 4; c < 8; ++c) {
    VertexId v = cx.vertex(0, c);
    cx.setPosition(v, cx.position(v) + Vec3{1, 0, 0});
  }
  CHECK(scaledJacobian(cx, 0) == doctest::Approx(std::sqrt(0.5)));

  Complex inv = makeGrid(1, 1, 1);
  // Push the top face below the bottom one: every corner's frame is left-handed.
  for (int c = 4; c < 8; ++c) {
    VertexId v = inv.vertex(0, c);
    inv.setPosition(v, inv.position(v) + Vec3{0, 0, -2});
  }
  QualityReport q = measureQuality(inv);
  CHECK(q.scaledJacobian[0] == doctest::Approx(-1));
  CHECK(q.inverted == std::vector<int32_t>{0});

  Complex flat = makeGrid(1, 1, 1);
  flat.setPosition(flat.vertex(0, 4), flat.position(flat.vertex(0, 0)));
  CHECK(scaledJacobian(flat, 0) == doctest::Approx(0));
}
