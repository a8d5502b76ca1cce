#pragma once
// Notes on standard error: what the user should hear that is neither a result nor a fault (the device taken
// by default, a tuned entry used, a shape the frame refused, ...). Every note goes through print_note, so
// that all read "parashade: note: ..." (docs/cli.md); -q silences them (the callers skip the call).
#include <string>

namespace parashade {

// Writes "parashade: note: TEXT" and a newline to std::cerr.
void print_note(const std::string& text);

}  // namespace parashade
