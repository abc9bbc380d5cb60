// GL errors: the driver's own reports (KHR_debug, core since GL 4.3), one line
// each on stderr, so a bad call shows up where it happens instead of as a
// wrong picture later.
#pragma once

namespace rm {

// Needs a current GL context; reports errors raised in it from now on.
void report_gl_errors();

// How many GL errors this process has reported (tests require none).
int gl_errors_reported();

}  // namespace rm
