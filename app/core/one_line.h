// A library's message of several lines as one line, for the one-line
// errors the host gives: OIIO's message of a failed read is several lines
// (libpng's words, then its own: "Read error: hit end of file\nPNG read
// error: IDAT: Read error: hit end of file\nPNG library error").
#pragma once
#include <string>

namespace rm {

// The lines that say something the others do not, joined with "; ".
std::string one_line(const std::string& message);

}  // namespace rm
