// What every binding unit shares: the error channel (no exception crosses into JS: every fallible
// call catches, keeps the message and an error code for lastError/lastErrorCode and returns
// null/false/""; wasm/index.js turns that into a HexdualError, leak-free where throwing through
// Embind is not: see TOOLCHAIN.md) and the conversions to JS values.
#pragma once
#include <emscripten/bind.h>

#include <initializer_list>
#include <new>
#include <string>
#include <utility>
#include <vector>

#include "complex/complex.hpp"

namespace hexdual::wasm {

inline std::string g_lastError, g_lastErrorCode;

// The error code a message belongs to when the call's own code is too coarse.
inline std::string classify(const std::string& message, const char* code) {
  if (message.rfind("oplog:", 0) == 0) return "PARSE";
  if (message.rfind("validate:", 0) == 0 || message.find("would not be a valid complex") != std::string::npos)
    return "INVALID_RESULT";
  if (message.find("more than 2^") != std::string::npos) return "LIMIT";
  return code;
}

// Runs f; on an exception keeps its message and code and returns onError. `code` is the kind of
// failure the call usually has (PARSE for readers, PRECONDITION for operations, ...).
template <class F>
auto guarded(const char* code, F&& f, decltype(f()) onError) -> decltype(f()) {
  g_lastError.clear();
  g_lastErrorCode.clear();
  try {
    return f();
  } catch (const std::bad_alloc&) {
    g_lastError = "out of memory: the WebAssembly heap cannot grow further";
    g_lastErrorCode = "LIMIT";
  } catch (const std::exception& e) {
    g_lastError = e.what();
    g_lastErrorCode = classify(g_lastError, code);
  }
  return onError;
}

// A JS object with these properties.
inline emscripten::val fields(std::initializer_list<std::pair<const char*, emscripten::val>> props) {
  emscripten::val o = emscripten::val::object();
  for (const auto& [name, value] : props) o.set(name, value);
  return o;
}

// A copy of v as a new JS typed array of the given type (views go stale when memory grows).
template <class T>
emscripten::val copyOut(const char* type, const std::vector<T>& v) {
  return emscripten::val::global(type).new_(emscripten::val(emscripten::typed_memory_view(v.size(), v.data())));
}

}  // namespace hexdual::wasm
