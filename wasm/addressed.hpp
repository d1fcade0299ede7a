// Shared by the binding files that read a mesh through the addresses WasmMesh hands out
// (complexAddress/dualAddress: same module, same heap): the casts, typed-array copies, and the
// error convention of returning an object with `error` set instead of throwing (see bindings.cpp).
#pragma once
#include <emscripten/bind.h>

#include <cstdint>
#include <string>
#include <vector>

#include "complex/complex.hpp"
#include "dual/dual.hpp"

namespace hexdual::wasm {

inline const Complex& complexAt(double address) { return *reinterpret_cast<const Complex*>(uintptr_t(address)); }
inline const Dual& dualAt(double address) { return *reinterpret_cast<const Dual*>(uintptr_t(address)); }

template <class T>
emscripten::val copyOut(const char* type, const std::vector<T>& v) {
  return emscripten::val::global(type).new_(emscripten::val(emscripten::typed_memory_view(v.size(), v.data())));
}

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
