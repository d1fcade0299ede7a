// Decompression for compressed mesh files: DEFLATE (RFC 1951) inside zlib (RFC 1950) or gzip
// (RFC 1952) framing. One code path natively and in WebAssembly, where zlib cannot be linked.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

namespace hexdual::io {

// Output larger than this is refused (a small file that inflates to gigabytes is hostile).
constexpr size_t kMaxInflatedBytes = size_t(1) << 30;

// Raw DEFLATE stream; *consumed (if given) receives the number of input bytes used.
// Throws Error("inflate: ...") on malformed data or when the output would exceed maxOut.
std::string inflateRaw(std::string_view in, size_t maxOut = kMaxInflatedBytes, size_t* consumed = nullptr);
// zlib stream (2-byte header, DEFLATE, Adler-32 checked).
std::string inflateZlib(std::string_view in, size_t maxOut = kMaxInflatedBytes);
// gzip file: every member, CRC-32 and length checked.
std::string gunzip(std::string_view in, size_t maxOut = kMaxInflatedBytes);
bool isGzip(std::string_view in);

}  // namespace hexdual::io
