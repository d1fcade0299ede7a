// A sheet diagram as a standalone SVG picture (`hexdual sheets --svg`), coloured by layout/palette.hpp.
#pragma once
#include <string>

#include "layout/diagram.hpp"

namespace hexdual {

std::string diagramSvg(const SheetDiagram& d);

}  // namespace hexdual
