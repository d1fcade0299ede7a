// A step's preview (ops/preview.hpp) and a pick's selection (dual/selection.hpp) as JSON and text,
// as `hexdual preview` and `hexdual select` print them and the wasm module returns them.
#pragma once
#include <string>

#include "ops/selection.hpp"
#include "ops/preview.hpp"

namespace hexdual::io {

// {"applies":true,"family":"sheet"|"atomic","hexesRemoved":n,"hexesCreated":n,"report":{step report}}
// or {"applies":false,"family":..,"rule":"self-touching"|null,"error":"..."}.
std::string previewJson(const Preview& p, const OpStep& step);
std::string previewText(const Preview& p, const OpStep& step);

// {"kind":"sheet"|"chord","id":n,"through":"h13e8","topology":..,"closed":..,"hexes":[..],"steps":[..]}
std::string selectionJson(const Selection& s);
std::string selectionText(const Selection& s);

}  // namespace hexdual::io
