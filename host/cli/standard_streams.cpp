// parashade's standard output and error: escaped and checked (standard_streams.hpp).
#include "standard_streams.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ext/stdio_sync_filebuf.h>
#include <iostream>
#include <string>

#include "parashade/errors.hpp"

namespace parashade::cli {
namespace {

bool g_stdout_closed = false;
int g_stdout_errno = 0;  // the first failed write's reason

// The descriptor a stream writes to, as fopencookie's cookie.
struct Sink {
  int fd;
};

void append_escaped(std::string& out, unsigned char c) {
  static const char hex[] = "0123456789abcdef";
  out += "\\x";
  out += hex[c >> 4];
  out += hex[c & 15];
}

// C0 controls but newline, tab and carriage return, DEL, and C1 controls as UTF-8 (C2 80 to C2 9F) are
// escaped; every other byte, UTF-8 text included, passes. (A C1 pair split across two writes passes.)
std::string escaped(const char* buf, std::size_t size) {
  std::string out;
  out.reserve(size);
  for (std::size_t i = 0; i < size; ++i) {
    const unsigned char c = static_cast<unsigned char>(buf[i]);
    if ((c < 0x20 && c != '\n' && c != '\t' && c != '\r') || c == 0x7f) {
      append_escaped(out, c);
    } else if (c == 0xc2 && i + 1 < size && (static_cast<unsigned char>(buf[i + 1]) & 0xe0) == 0x80) {
      append_escaped(out, static_cast<unsigned char>(buf[++i]));
    } else {
      out += char(c);
    }
  }
  return out;
}

ssize_t write_escaped(void* cookie, const char* buf, std::size_t size) {
  const int fd = static_cast<Sink*>(cookie)->fd;
  const std::string text = escaped(buf, size);
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {  // stdio marks the stream; the reason is kept for the message
      if (fd == 1 && g_stdout_errno == 0) g_stdout_errno = n < 0 ? errno : EIO;
      return -1;
    }
    done += std::size_t(n);
  }
  return ssize_t(size);
}

// A closed descriptor gets a stand-in: writes to /dev/full fail, so results printed to a closed stdout
// are reported at exit; errors printed to a closed stderr have nowhere to go (/dev/null).
bool stand_in(int fd, const char* device) {
  if (::fcntl(fd, F_GETFD) != -1 || errno != EBADF) return false;
  int opened = ::open(device, O_WRONLY | O_CLOEXEC);
  if (opened < 0) opened = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
  if (opened >= 0 && opened != fd) {
    ::dup2(opened, fd);
    ::close(opened);
  }
  return true;
}

std::FILE* escaping_stream(Sink* sink, int mode) {
  cookie_io_functions_t io{};
  io.write = write_escaped;
  std::FILE* f = ::fopencookie(sink, "w", io);
  if (f) std::setvbuf(f, nullptr, mode, mode == _IONBF ? 0 : BUFSIZ);
  return f;
}

}  // namespace

void guard_standard_streams() {
  stand_in(2, "/dev/null");
  g_stdout_closed = stand_in(1, "/dev/full");
  static Sink out_sink{1}, err_sink{2};
  std::FILE* out = escaping_stream(&out_sink, ::isatty(1) ? _IOLBF : _IOFBF);
  std::FILE* err = escaping_stream(&err_sink, _IONBF);
  if (!out || !err) return;  // no memory for two streams: print unescaped
  std::fflush(stdout);
  stdout = out;
  stderr = err;
  // Never destroyed: every ios_base::Init destructor (one per library that includes <iostream>) flushes
  // std::cout at exit, after function-local statics are gone; a static buffer here was read after its
  // destruction (AddressSanitizer: SEGV in ostream::flush from a library's __cxa_finalize).
  static auto* const cout_buf = new __gnu_cxx::stdio_sync_filebuf<char>(out);
  static auto* const cerr_buf = new __gnu_cxx::stdio_sync_filebuf<char>(err);
  std::cout.rdbuf(cout_buf);
  std::cerr.rdbuf(cerr_buf);
}

int finish_standard_output(int code) {
  std::cout.flush();
  const bool flushed = std::fflush(stdout) == 0;
  if (flushed && !std::ferror(stdout) && std::cout.good()) return code;
  const std::string reason = g_stdout_closed      ? std::string("it is closed")
                             : g_stdout_errno != 0 ? std::string(std::strerror(g_stdout_errno))
                                                   : std::string("a write failed");
  std::fprintf(stderr, "parashade: error: cannot write the results to standard output: %s (what was printed is lost)\n",
               reason.c_str());
  return code != 0 ? code : int(ExitCode::bad_input);
}

}  // namespace parashade::cli
