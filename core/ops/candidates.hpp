// Which entities an operation can be applied to, as operation-log steps. Each candidate is
// tried on a private copy and undone exactly, so the list holds only steps that succeed.
#pragma once
#include <string>
#include <vector>

#include "complex/complex.hpp"

namespace hexdual {

// op: pillow, unpillow, chordpush, chordpull, hexpush, hexpull, ringcollapse, facecollapse,
// facesplit. (ringsplit steps come from ringcollapse's inverse; they are not enumerated.)
std::vector<std::string> candidates(const Complex& cx, const std::string& op);

}  // namespace hexdual
