// json_text.hpp — private: the small text helpers the preset reader, writer
// and validator share. JSON pointers (RFC 6901), line:column of a byte
// offset, UTF-8 checks, and the canonical forms of numbers and strings that
// savePreset writes (so messages quote values exactly as a file holds them).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace aerial::detail {

/// A JSON pointer token with '~' and '/' escaped ("~0", "~1").
std::string escapePointerToken(std::string_view token);
/// base + "/" + the escaped token (or the array index).
std::string pointerJoin(const std::string& base, std::string_view token);
std::string pointerJoin(const std::string& base, std::size_t index);

/// 1-based line and column (in UTF-8 code points) of a byte offset.
void lineColumn(std::string_view text, std::size_t offset, int& line, int& column);

/// True when `s` is well-formed UTF-8 (no overlong forms, no surrogates).
bool validUtf8(std::string_view s);

/// `text` with every byte that is not part of valid UTF-8 written as \xNN,
/// so messages quoting a broken file stay valid text.
std::string printable(std::string_view text);

/// The shortest text that reads back to the same double ("-0.0" for -0;
/// "nan" and "inf" only ever appear in messages).
std::string formatDouble(double v);

/// `s` as a JSON string literal (quotes, escapes; bytes passed through).
std::string quoteString(std::string_view s);

}  // namespace aerial::detail
