// Shared by the binding files that read a mesh through the addresses WasmMesh hands out
// (complexAddress/dualAddress: same module, same heap): the casts, typed-array copies (copyOut, from
// bindings_common.hpp), and the error convention of returning an object with `error` set instead
// of throwing (see bindings.cpp).
#pragma once
#include <emscripten/bind.h>

#include <cstdint>
#include <string>
#include <vector>

#include "bindings_common.hpp"  // copyOut
#include "complex/complex.hpp"
#include "dual/dual.hpp"

namespace hexdual::wasm {

inline const Complex& complexAt(double address) { return *reinterpret_cast<const Complex*>(uintptr_t(address)); }
inline const Dual& dualAt(double address) { return *reinterpret_cast<const Dual*>(uintptr_t(address)); }

template <class F>
emscripten::val guardedObject(F&& f) {
  try {
    return f();
  } catch (const std::exception& e) {
    emscripten::val out = emscripten::val::object();
    out.set("error", std::string(e.what()));
    return out;
  }
}

}  // namespace hexdual::wasm
