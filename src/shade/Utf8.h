#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace termshade {

/// The code points of UTF-8 text, or nothing when it is not valid UTF-8
/// (overlong forms, surrogates and values past U+10FFFF are invalid).
std::optional<std::vector<char32_t>> DecodeUtf8(std::string_view text);

/// Bytes in the UTF-8 sequence a lead byte starts: 1 for ASCII, 0 for a byte
/// that cannot lead one.
int Utf8SequenceLength(unsigned char lead);

/// The cells a code point beyond ASCII takes when it may go to a terminal as
/// it is: 1 or 2 (wide, CJK) by the current locale (wcwidth, so none in the
/// C locale); 0 for one that may not: C1 controls, invisible format
/// characters (bidirectional overrides, zero-width spaces, tags), combining
/// marks, and anything the locale cannot show.
int SafeCodePointCells(char32_t codePoint);

/// A control character (C0, DEL, C1) or a format character that reorders or
/// hides text (those SafeCodePointCells refuses before asking wcwidth): never
/// sent to a terminal as it is. Does not depend on the locale.
bool IsControlOrFormat(char32_t codePoint);

/// Appends the UTF-8 bytes of one code point.
void AppendUtf8(std::string& out, char32_t codePoint);

/// True for the glyphs a shade ramp may use: printable ASCII but the blank,
/// printable Latin-1, box drawing, block elements, geometric shapes and
/// braille. Terminals show these one cell wide (block elements and some
/// shapes are two wide in East Asian "ambiguous width" settings).
bool IsRampGlyph(char32_t codePoint);

}  // namespace termshade
