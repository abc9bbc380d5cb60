// JSON text made fit for the host's one-line messages. nlohmann's parse
// errors quote the whole token they last read, and for a string left open
// (a JSON saved half-written) that is the rest of the file: a shader's code,
// thousands of characters. A value a warning quotes may be as long.
#pragma once
#include <cstddef>
#include <string>

namespace rm {

// `what` with its "last read: '...'" cut to its first and last few
// characters around "..." (ASCII: the window's font has no ellipsis), at
// UTF-8 character boundaries; unchanged when the token is short or not there.
std::string short_json_error(const std::string& what);

// `text` whole when it has at most `most` bytes, else its first `most` bytes
// or fewer (at a UTF-8 character boundary) and "...".
std::string brief(const std::string& text, size_t most = 40);

}  // namespace rm
