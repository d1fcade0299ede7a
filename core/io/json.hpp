// Minimal JSON writing, and the `info` report shared by the CLI and the wasm module.
#pragma once
#include <string>

#include "complex/complex.hpp"
#include "dual/dual.hpp"
#include "io/io.hpp"

namespace hexdual::io {

class JsonWriter {
 public:
  JsonWriter& beginObject() { return open('{'); }
  JsonWriter& endObject() { return close('}'); }
  JsonWriter& beginArray() { return open('['); }
  JsonWriter& endArray() { return close(']'); }
  JsonWriter& key(const std::string& k) {
    comma();
    out_ += quote(k) + ":";
    afterKey_ = true;
    return *this;
  }
  JsonWriter& value(const std::string& s) { return raw(quote(s)); }
  JsonWriter& value(const char* s) { return raw(quote(s)); }
  JsonWriter& value(bool b) { return raw(b ? "true" : "false"); }
  JsonWriter& value(int64_t v) { return raw(std::to_string(v)); }
  JsonWriter& value(int v) { return raw(std::to_string(v)); }
  JsonWriter& value(double v);
  JsonWriter& raw(const std::string& text) {
    comma();
    out_ += text;
    return *this;
  }
  const std::string& str() const { return out_; }
  static std::string quote(const std::string& s);

 private:
  JsonWriter& open(char c) {
    comma();
    out_ += c;
    first_ = true;
    return *this;
  }
  JsonWriter& close(char c) {
    out_ += c;
    first_ = false;
    return *this;
  }
  void comma() {
    if (afterKey_) {
      afterKey_ = false;
      return;
    }
    if (!first_) out_ += ",";
    first_ = false;
  }
  std::string out_;
  bool first_ = true, afterKey_ = false;
};

// {"vertices":..,"edges":..,"quads":..,"hexes":..,"boundaryQuads":..,"sheets":[..],"chords":[..]},
// and "file": {...} last (what the reader found, see ReadReport) when a report is given.
std::string infoJson(const Complex& cx, const Dual& dual, const ReadReport* file = nullptr);
// The same facts as readable text.
std::string infoText(const Complex& cx, const Dual& dual);

}  // namespace hexdual::io
