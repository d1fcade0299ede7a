// DEFLATE decoder after RFC 1951: canonical Huffman codes decoded by counting code lengths
// (one code length at a time), which is short and needs no tables beyond the symbol order.
#include "io/inflate.hpp"

#include <array>
#include <cstdint>

#include "complex/complex.hpp"

namespace hexdual::io {
namespace {

[[noreturn]] void fail(const std::string& why) { throw Error("inflate: " + why); }

class BitReader {
 public:
  explicit BitReader(std::string_view in) : in_(in) {}
  uint32_t bits(int n) {
    uint32_t v = 0;
    for (int i = 0; i < n; ++i) v |= uint32_t(bit()) << i;
    return v;
  }
  int bit() {
    if (nbits_ == 0) {
      if (pos_ >= in_.size()) fail("compressed data ends early");
      cur_ = uint8_t(in_[pos_++]);
      nbits_ = 8;
    }
    int b = cur_ & 1;
    cur_ >>= 1;
    --nbits_;
    return b;
  }
  void alignToByte() { nbits_ = 0; }
  size_t bytePos() const { return pos_; }
  std::string_view take(size_t n) {
    if (in_.size() - pos_ < n) fail("stored block ends early");
    auto r = in_.substr(pos_, n);
    pos_ += n;
    return r;
  }

 private:
  std::string_view in_;
  size_t pos_ = 0;
  uint32_t cur_ = 0;
  int nbits_ = 0;
};

// A canonical Huffman code: number of codes per length, and symbols sorted by code.
struct Huffman {
  std::array<uint16_t, 16> count{};
  std::array<uint16_t, 320> symbol{};
};

// Builds the code from code lengths; rejects over-subscribed sets (incomplete ones are allowed,
// as RFC 1951 permits a single distance code).
Huffman buildHuffman(const uint8_t* lengths, int n) {
  Huffman h;
  for (int s = 0; s < n; ++s) ++h.count[lengths[s]];
  h.count[0] = 0;
  int left = 1;
  for (int len = 1; len < 16; ++len) {
    left = left * 2 - h.count[size_t(len)];
    if (left < 0) fail("over-subscribed Huffman code");
  }
  std::array<uint16_t, 16> offs{};
  for (int len = 1; len < 15; ++len) offs[size_t(len + 1)] = uint16_t(offs[size_t(len)] + h.count[size_t(len)]);
  for (int s = 0; s < n; ++s)
    if (lengths[s]) h.symbol[offs[lengths[s]]++] = uint16_t(s);
  return h;
}

int decodeSymbol(BitReader& br, const Huffman& h) {
  int code = 0, first = 0, index = 0;
  for (int len = 1; len < 16; ++len) {
    code |= br.bit();
    int count = h.count[size_t(len)];
    if (code - first < count) return h.symbol[size_t(index + code - first)];
    index += count;
    first = (first + count) << 1;
    code <<= 1;
  }
  fail("invalid Huffman code");
}

constexpr uint16_t kLenBase[29] = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23, 27,
                                   31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
constexpr uint8_t kLenExtra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
constexpr uint16_t kDistBase[30] = {1,   2,   3,   4,   5,   7,    9,    13,   17,   25,   33,   49,   65,    97,    129,
                                    193, 257, 385, 513, 769, 1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
constexpr uint8_t kDistExtra[30] = {0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};

void append(std::string& out, char c, size_t maxOut) {
  if (out.size() >= maxOut) fail("output exceeds " + std::to_string(maxOut) + " bytes");
  out.push_back(c);
}

void inflateCodes(BitReader& br, std::string& out, const Huffman& lit, const Huffman& dist, size_t maxOut) {
  for (;;) {
    int sym = decodeSymbol(br, lit);
    if (sym < 256) {
      append(out, char(sym), maxOut);
    } else if (sym == 256) {
      return;
    } else {
      sym -= 257;
      if (sym >= 29) fail("invalid length symbol");
      size_t len = kLenBase[sym] + br.bits(kLenExtra[sym]);
      int ds = decodeSymbol(br, dist);
      if (ds >= 30) fail("invalid distance symbol");
      size_t d = kDistBase[ds] + br.bits(kDistExtra[ds]);
      if (d > out.size()) fail("distance reaches before the start of the output");
      if (len > maxOut - out.size()) fail("output exceeds " + std::to_string(maxOut) + " bytes");
      for (size_t i = 0; i < len; ++i) out.push_back(out[out.size() - d]);
    }
  }
}

void fixedCodes(Huffman& lit, Huffman& dist) {
  uint8_t len[288];
  for (int i = 0; i < 144; ++i) len[i] = 8;
  for (int i = 144; i < 256; ++i) len[i] = 9;
  for (int i = 256; i < 280; ++i) len[i] = 7;
  for (int i = 280; i < 288; ++i) len[i] = 8;
  lit = buildHuffman(len, 288);
  uint8_t dl[30];
  for (auto& x : dl) x = 5;
  dist = buildHuffman(dl, 30);
}

void dynamicCodes(BitReader& br, Huffman& lit, Huffman& dist) {
  static constexpr uint8_t kOrder[19] = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};
  int nlen = int(br.bits(5)) + 257, ndist = int(br.bits(5)) + 1, ncode = int(br.bits(4)) + 4;
  if (nlen > 286 || ndist > 30) fail("bad counts in a dynamic block header");
  uint8_t lengths[320] = {};
  for (int i = 0; i < ncode; ++i) lengths[kOrder[i]] = uint8_t(br.bits(3));
  Huffman lencode = buildHuffman(lengths, 19);
  int index = 0;
  while (index < nlen + ndist) {
    int sym = decodeSymbol(br, lencode);
    if (sym < 16) {
      lengths[index++] = uint8_t(sym);
      continue;
    }
    uint8_t value = 0;
    int repeat;
    if (sym == 16) {
      if (index == 0) fail("repeat with no previous length");
      value = lengths[index - 1];
      repeat = 3 + int(br.bits(2));
    } else if (sym == 17) {
      repeat = 3 + int(br.bits(3));
    } else {
      repeat = 11 + int(br.bits(7));
    }
    if (index + repeat > nlen + ndist) fail("code lengths overrun the header counts");
    while (repeat--) lengths[index++] = value;
  }
  if (lengths[256] == 0) fail("no end-of-block code");
  lit = buildHuffman(lengths, nlen);
  dist = buildHuffman(lengths + nlen, ndist);
}

uint32_t readLE32(std::string_view s, size_t at) {
  uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | uint8_t(s[at + size_t(i)]);
  return v;
}

uint32_t crc32(std::string_view s) {
  static const auto table = [] {
    std::array<uint32_t, 256> t{};
    for (uint32_t n = 0; n < 256; ++n) {
      uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  uint32_t c = 0xFFFFFFFFu;
  for (char ch : s) c = table[(c ^ uint8_t(ch)) & 0xFF] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

uint32_t adler32(std::string_view s) {
  uint32_t a = 1, b = 0;
  for (char ch : s) {
    a = (a + uint8_t(ch)) % 65521;
    b = (b + a) % 65521;
  }
  return (b << 16) | a;
}

}  // namespace

std::string inflateRaw(std::string_view in, size_t maxOut, size_t* consumed) {
  BitReader br(in);
  std::string out;
  int last = 0;
  while (!last) {
    last = br.bit();
    int type = int(br.bits(2));
    if (type == 0) {
      br.alignToByte();
      auto hdr = br.take(4);
      unsigned len = uint8_t(hdr[0]) | unsigned(uint8_t(hdr[1])) << 8;
      unsigned nlen = uint8_t(hdr[2]) | unsigned(uint8_t(hdr[3])) << 8;
      if (len != (~nlen & 0xFFFFu)) fail("stored block length check failed");
      if (len > maxOut - out.size()) fail("output exceeds " + std::to_string(maxOut) + " bytes");
      out += br.take(len);
    } else if (type == 1 || type == 2) {
      Huffman lit, dist;
      if (type == 1) fixedCodes(lit, dist);
      else dynamicCodes(br, lit, dist);
      inflateCodes(br, out, lit, dist, maxOut);
    } else {
      fail("invalid block type 3");
    }
  }
  if (consumed) *consumed = br.bytePos();
  return out;
}

std::string inflateZlib(std::string_view in, size_t maxOut) {
  if (in.size() < 6) fail("zlib stream too short");
  unsigned cmf = uint8_t(in[0]), flg = uint8_t(in[1]);
  if ((cmf & 0x0F) != 8 || (cmf * 256 + flg) % 31 != 0) fail("not a zlib stream (bad header)");
  if (flg & 0x20) fail("zlib preset dictionaries are not supported");
  size_t used = 0;
  std::string out = inflateRaw(in.substr(2), maxOut, &used);
  if (in.size() < 2 + used + 4) fail("zlib stream ends before its checksum");
  uint32_t want = 0;
  for (int i = 0; i < 4; ++i) want = (want << 8) | uint8_t(in[2 + used + size_t(i)]);
  if (adler32(out) != want) fail("Adler-32 checksum mismatch");
  return out;
}

bool isGzip(std::string_view in) { return in.size() >= 2 && uint8_t(in[0]) == 0x1F && uint8_t(in[1]) == 0x8B; }

std::string gunzip(std::string_view in, size_t maxOut) {
  std::string out;
  size_t pos = 0;
  while (pos < in.size()) {
    std::string_view m = in.substr(pos);
    if (!isGzip(m) || m.size() < 18) {
      if (pos > 0) break;  // trailing garbage after a member is ignored, as gzip does
      fail("not a gzip stream");
    }
    if (uint8_t(m[2]) != 8) fail("gzip compression method is not DEFLATE");
    unsigned flg = uint8_t(m[3]);
    size_t at = 10;
    auto need = [&](size_t n) {
      if (m.size() < at + n) fail("gzip header ends early");
    };
    if (flg & 4) {  // FEXTRA
      need(2);
      size_t xlen = uint8_t(m[at]) | size_t(uint8_t(m[at + 1])) << 8;
      at += 2;
      need(xlen);
      at += xlen;
    }
    for (unsigned bit : {8u, 16u})  // FNAME, FCOMMENT: zero-terminated
      if (flg & bit) {
        while (at < m.size() && m[at] != 0) ++at;
        need(1);
        ++at;
      }
    if (flg & 2) at += 2;  // FHCRC
    need(0);
    size_t used = 0;
    std::string part = inflateRaw(m.substr(at), maxOut - out.size(), &used);
    at += used;
    need(8);
    if (crc32(part) != readLE32(m, at)) fail("gzip CRC-32 mismatch");
    if (uint32_t(part.size()) != readLE32(m, at + 4)) fail("gzip length mismatch");
    out += part;
    pos += at + 8;
  }
  return out;
}

}  // namespace hexdual::io
