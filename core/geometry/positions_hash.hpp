// A hash of every live vertex's id and position bits: equal hashes = bitwise-equal positions (up
// to collisions). Compares the geometry the CLI and the package reach from the same log.
#pragma once
#include <string>

#include "complex/complex.hpp"

namespace hexdual {

// FNV-1a 64 over (id, x, y, z bit patterns) of the live vertices in id order, as 16 hex digits.
std::string positionsHash(const Complex& cx);

}  // namespace hexdual
