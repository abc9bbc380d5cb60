// JSON text made fit for the host's one-line messages. nlohmann's parse
// errors quote the whole token they last read, and for a string left open
// (a JSON saved half-written) that is the rest of the file: a shader's code,
// thousands of characters. (A value a warning quotes: brief, in one_line.h.)
#pragma once
#include <string>

namespace rm {

// `what` with its "last read: '...'" cut to its first and last few
// characters around "..." (ASCII, as the rest of the message), at
// UTF-8 character boundaries; unchanged when the token is short or not there.
std::string short_json_error(const std::string& what);

}  // namespace rm
