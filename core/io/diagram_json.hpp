// A sheet diagram as JSON (the format `hexdual sheets --json` writes and the wasm module returns).
#pragma once
#include <string>

#include "layout/diagram.hpp"

namespace hexdual {

std::string diagramJson(const SheetDiagram& d);

}  // namespace hexdual
