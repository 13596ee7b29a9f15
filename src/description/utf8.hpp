#pragma once
// UTF-8: appending a code point (xacro's XML character references and Python string escapes),
// and checking that text is well-formed (YAML and XML files are Unicode text; what mechsim
// writes as JSON must be).

#include <cstddef>
#include <string>
#include <string_view>

namespace mechsim::description {

inline void append_utf8(std::string& out, unsigned long cp) {
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (cp >> 18));
    out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  }
}

// The offset of the first byte of `text` that is not well-formed UTF-8 (Unicode 15, table 3-7:
// no overlong forms, no surrogates, nothing past U+10FFFF), or npos. yaml-cpp (which decodes
// UTF-16/32 files to UTF-8) and tinyxml2 pass the stray bytes of an 8-bit file through, and the
// JSON a run writes (summary.json, a sweep's plan.json, the replay) cannot hold them. Written here
// because neither they nor the standard library offers a locale-free check.
inline std::size_t invalid_utf8_at(std::string_view text) {
  std::size_t i = 0;
  while (i < text.size()) {
    const auto b = static_cast<unsigned char>(text[i]);
    if (b < 0x80) {
      ++i;
      continue;
    }
    std::size_t n = 0;
    unsigned char lo = 0x80, hi = 0xBF;  // the allowed range of the second byte
    if (b >= 0xC2 && b <= 0xDF) {
      n = 1;
    } else if (b >= 0xE0 && b <= 0xEF) {
      n = 2;
      if (b == 0xE0) lo = 0xA0;
      if (b == 0xED) hi = 0x9F;
    } else if (b >= 0xF0 && b <= 0xF4) {
      n = 3;
      if (b == 0xF0) lo = 0x90;
      if (b == 0xF4) hi = 0x8F;
    } else {
      return i;
    }
    if (i + n >= text.size()) return i;  // cut short by the end of the text
    for (std::size_t k = 1; k <= n; ++k) {
      const auto c = static_cast<unsigned char>(text[i + k]);
      if (k == 1 ? (c < lo || c > hi) : (c < 0x80 || c > 0xBF)) return i;
    }
    i += n + 1;
  }
  return std::string_view::npos;
}

// "byte 0xFF": the byte at `at`, for messages.
inline std::string utf8_byte_name(std::string_view text, std::size_t at) {
  static const char* const hex = "0123456789ABCDEF";
  const auto b = static_cast<unsigned char>(text[at]);
  return std::string("byte 0x") + hex[b >> 4] + hex[b & 0xF];
}

}  // namespace mechsim::description
