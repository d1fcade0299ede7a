// A whitespace tokenizer over a byte buffer that knows its line and byte offset, for error messages.
#pragma once
#include <cstdint>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>

#include "complex/complex.hpp"

namespace hexdual::io {

class Lexer {
 public:
  Lexer(std::string_view data, std::string name) : data_(data), name_(std::move(name)) {}

  // At most 40 bytes of a token, for error messages (a garbage token may be megabytes long).
  static std::string excerpt(std::string_view t) {
    std::string s(t.substr(0, 40));
    for (char& c : s)
      if ((unsigned char)c < 32 || (unsigned char)c > 126) c = '?';
    return s + (t.size() > 40 ? "..." : "");
  }
  [[noreturn]] void fail(const std::string& why) const {
    throw Error(name_ + ":" + std::to_string(line_) + ": " + why);
  }
  [[noreturn]] void failAtByte(size_t offset, const std::string& why) const {
    throw Error(name_ + ": byte " + std::to_string(offset) + ": " + why);
  }
  bool atEnd() {
    skipSpace();
    return pos_ >= data_.size();
  }
  // Next token, or empty at end of input. `#` starts a comment only when commentChar is set.
  std::string_view token() {
    skipSpace();
    size_t b = pos_;
    while (pos_ < data_.size() && !isSpace(data_[pos_])) ++pos_;
    return data_.substr(b, pos_ - b);
  }
  std::string_view expectToken(const char* what) {
    auto t = token();
    if (t.empty()) fail(std::string("unexpected end of file; expected ") + what);
    return t;
  }
  void expectKeyword(std::string_view kw) {
    auto t = token();
    if (!equalsIgnoreCase(t, kw)) fail("expected '" + std::string(kw) + "' but found '" + excerpt(t) + "'");
  }
  int64_t integer(const char* what) {
    auto t = expectToken(what);
    int64_t v = 0;
    size_t i = 0;
    bool neg = false;
    if (i < t.size() && (t[i] == '-' || t[i] == '+')) neg = t[i++] == '-';
    if (i == t.size()) fail(std::string("expected ") + what + " but found '" + excerpt(t) + "'");
    for (; i < t.size(); ++i) {
      if (t[i] < '0' || t[i] > '9' || v > (int64_t(1) << 50))
        fail(std::string("expected ") + what + " but found '" + excerpt(t) + "'");
      v = v * 10 + (t[i] - '0');
    }
    return neg ? -v : v;
  }
  int64_t count(const char* what, int64_t max = int64_t(1) << 31) {
    int64_t v = integer(what);
    if (v < 0 || v > max) fail(std::string(what) + " " + std::to_string(v) + " is out of range");
    return v;
  }
  double real(const char* what) {
    auto t = expectToken(what);
    std::string s(t);
    char* end = nullptr;
    double v = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size()) fail(std::string("expected ") + what + " but found '" + excerpt(s) + "'");
    return v;
  }
  // The rest of the current line (without the newline), moving to the next line.
  std::string_view restOfLine() {
    size_t b = pos_;
    while (pos_ < data_.size() && data_[pos_] != '\n') ++pos_;
    auto r = data_.substr(b, pos_ - b);
    if (pos_ < data_.size()) {
      ++pos_;
      ++line_;
    }
    if (!r.empty() && r.back() == '\r') r.remove_suffix(1);
    return r;
  }
  // Raw bytes (binary sections); fails with the byte offset when the file is too short.
  std::string_view bytes(size_t n, const char* what) {
    if (data_.size() - pos_ < n)
      failAtByte(pos_, std::string("file ends inside ") + what + " (" + std::to_string(n) + " bytes needed, " +
                           std::to_string(data_.size() - pos_) + " left)");
    auto r = data_.substr(pos_, n);
    pos_ += n;
    return r;
  }
  size_t offset() const { return pos_; }
  int line() const { return line_; }
  const std::string& name() const { return name_; }

  static bool equalsIgnoreCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
      if (std::tolower((unsigned char)a[i]) != std::tolower((unsigned char)b[i])) return false;
    return true;
  }

 private:
  static bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }
  void skipSpace() {
    while (pos_ < data_.size() && isSpace(data_[pos_])) {
      if (data_[pos_] == '\n') ++line_;
      ++pos_;
    }
  }
  std::string_view data_;
  std::string name_;
  size_t pos_ = 0;
  int line_ = 1;
};

}  // namespace hexdual::io
