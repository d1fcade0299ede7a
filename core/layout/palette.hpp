// The colour rule shared by every view (the SVG writer here, web/colors.js in the demo):
// sheet k and chord k get golden-angle hues, so consecutive ids differ and a stable id keeps its
// colour between steps. A chord has one colour everywhere (3D view and sheet diagrams). The
// constants are mirrored in web/colors.js; tests/node/palette.test.mjs checks they agree.
#pragma once
#include <cmath>
#include <cstdio>
#include <string>

namespace hexdual::palette {

inline constexpr double kGoldenAngle = 137.508;  // degrees
inline constexpr int kSaturation = 65;           // percent
inline constexpr int kLightness = 50;            // percent
inline constexpr int kChordIdOffset = 1000;      // chord k takes the hue of id k + 1000, unlike sheet k

inline double hue(int id) { return std::fmod(double(id) * kGoldenAngle, 360.0); }

inline std::string hsl(double h, int s, int l) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "hsl(%.1f, %d%%, %d%%)", h, s, l);
  return buf;
}
inline std::string sheetColor(int id) { return hsl(hue(id), kSaturation, kLightness); }
inline std::string chordColor(int id) { return hsl(hue(id + kChordIdOffset), kSaturation, kLightness); }
// The seams of a fundamental polygon: dark, so they stand apart from chords.
inline std::string seamColor(int pair) { return hsl(hue(pair), 80, 30); }

}  // namespace hexdual::palette
