// A library's message of several lines as one line, for the one-line
// errors the host gives: OIIO's message of a failed read is several lines
// (libpng's words, then its own: "Read error: hit end of file\nPNG read
// error: IDAT: Read error: hit end of file\nPNG library error"). And what
// a message quotes from the user's text, cut to a length a line can hold.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>

namespace rm {

// The lines that say something the others do not, joined with "; ".
std::string one_line(const std::string& message);

// Whether `c` continues a UTF-8 character rather than starting one: a cut
// of the user's text falls before such a byte, never at it.
inline bool continues_a_character(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

// `text` whole when it has at most `most` bytes, else its first `most` bytes
// or fewer (at a UTF-8 character boundary) and "..." (ASCII, as the rest of
// a message on stderr). For quoting a value the user wrote, which may be a
// line of 100,000 characters.
std::string brief(std::string_view text, size_t most = 40);

}  // namespace rm
