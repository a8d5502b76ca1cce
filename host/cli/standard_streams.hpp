#pragma once
// parashade's standard output and error (issue 46):
// - Nothing a terminal would interpret is printed raw: a scene name or a path holding an escape sequence
//   (a title change, a screen clear) is printed with its control characters escaped ("\x1b"); newline,
//   tab and carriage return (the progress line) pass.
// - Results printed to stdout are part of the work: when stdout cannot take them (/dev/full, a closed
//   descriptor, a full disk), the run says so and exits non-zero instead of 0 with the results lost. A
//   pipe whose reader went away ends the run by SIGPIPE, as for any Unix tool.
namespace parashade::cli {

// First thing in main: a closed descriptor 1 or 2 is opened on /dev/full or /dev/null (so no file the
// command opens takes it), and stdout, stderr, std::cout and std::cerr print through the escaping.
void guard_standard_streams();

// Last thing in main: flushes stdout and checks every write to it. On a failure prints
// "parashade: error: cannot write the results to standard output: <reason>" and returns 3 (or `code`
// when it is already an error); else `code`.
int finish_standard_output(int code);

}  // namespace parashade::cli
