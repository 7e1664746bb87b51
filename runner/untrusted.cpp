#include "untrusted.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace runner {

namespace {

constexpr std::string_view kReplacement = "\xEF\xBF\xBD";  // U+FFFD in UTF-8

struct Decoded {
  char32_t code = 0;
  std::size_t length = 1;  // bytes used: the sequence, or its longest invalid start
  bool valid = false;
};

// The UTF-8 sequence at bytes[at]. An invalid one reports its longest start that could
// have begun a valid sequence (the "maximal subpart" of Unicode's chapter 3), so that
// each is replaced by one U+FFFD and the next character is still read.
Decoded decode(std::string_view bytes, std::size_t at) {
  const unsigned char lead = bytes[at];
  if (lead < 0x80) return {lead, 1, true};
  // The lead byte fixes the length and the range of the second byte; that range rules
  // out overlong forms (E0, F0), surrogates (ED) and code points past U+10FFFF (F4).
  std::size_t length = 0;
  unsigned char low = 0x80, high = 0xBF;
  char32_t code = 0;
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
    code = lead & 0x1F;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    code = lead & 0x0F;
    if (lead == 0xE0) low = 0xA0;
    if (lead == 0xED) high = 0x9F;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    code = lead & 0x07;
    if (lead == 0xF0) low = 0x90;
    if (lead == 0xF4) high = 0x8F;
  } else {
    return {};  // a continuation byte, or a lead byte UTF-8 never uses (C0, C1, F5-FF)
  }
  for (std::size_t k = 1; k < length; ++k) {
    if (at + k >= bytes.size()) return {0, k, false};  // cut short: output kept from its middle
    const unsigned char next = bytes[at + k];
    // Not a continuation byte this sequence can have.
    if (next < (k == 1 ? low : 0x80) || next > (k == 1 ? high : 0xBF)) return {0, k, false};
    code = (code << 6) | (next & 0x3F);
  }
  return {code, length, true};
}

// Characters a terminal or a reader acts on instead of showing: C0 controls but newline
// and tab (ESC starts escape sequences, CR overwrites a line, VT and FF start one), DEL,
// C1 controls (0x9B is a one-byte CSI, 0x85 is NEL), U+2028 and U+2029 (line breaks to
// browsers and some editors), bidi marks, embeddings, overrides and isolates (they reorder what is
// shown), and U+FFFE and U+FFFF, which XML refuses.
bool shown_as_text(char32_t c) {
  if (c < 0x20) return c != '\n' && c != '\t';
  if (c >= 0x7F && c <= 0x9F) return true;
  if (c == 0x061C || c == 0x200E || c == 0x200F) return true;
  if ((c >= 0x202A && c <= 0x202E) || (c >= 0x2066 && c <= 0x2069)) return true;
  if (c == 0x2028 || c == 0x2029) return true;  // line and paragraph separators: a new line to some readers
  return c == 0xFFFE || c == 0xFFFF;
}

std::string as_text(char32_t c) {
  char buffer[12];
  std::snprintf(buffer, sizeof buffer, c < 0x80 ? "\\x%02x" : "\\u%04x", unsigned(c));
  return buffer;
}

bool is_number(std::string_view item) {
  // codec.cpp writes these by hand; every other value is std::to_chars's.
  if (item == "inf" || item == "-inf" || item == "nan") return true;
  return !item.empty() && item.find_first_not_of("0123456789.eE+-") == std::string_view::npos;
}

std::string size_text(std::uintmax_t bytes) {
  if (bytes >= (1u << 20) && bytes % (1u << 20) == 0) return std::to_string(bytes >> 20) + " MB";
  return std::to_string(bytes) + " bytes";
}

std::string error_text(int error) { return std::error_code(error, std::generic_category()).message(); }

std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  return "not a regular file";
}

// A file descriptor that closes itself.
struct Descriptor {
  int fd = -1;
  Descriptor() = default;
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  ~Descriptor() {
    if (fd >= 0) close(fd);
  }
};

// Opens `path` for reading when it is a regular file of at most `max_bytes`; else why not.
std::string open_untrusted(const std::string& path, std::uintmax_t max_bytes, Descriptor& file) {
  // O_NOFOLLOW: a symlink put in its place is refused, never followed. O_NONBLOCK: a
  // FIFO put in its place cannot make open() wait for a writer that never comes.
  file.fd = open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (file.fd < 0) return errno == ELOOP ? "is a symbolic link" : "cannot be opened (" + error_text(errno) + ")";
  struct stat st {};
  if (fstat(file.fd, &st) != 0) return "cannot be read (" + error_text(errno) + ")";
  // A FIFO, socket or device could block a read forever, or never end.
  if (!S_ISREG(st.st_mode)) return "is " + kind_of(st.st_mode) + ", not a regular file";
  // Too large as it stands (the reads stop at the cap too, in case it grows meanwhile).
  if (std::uintmax_t(st.st_size) > max_bytes) return "is larger than " + size_text(max_bytes);
  return "";
}

// Reads up to `room` bytes; 0 at the end; -1 (errno set) on error.
ssize_t read_some(int fd, char* buffer, std::size_t room) {
  for (;;) {
    const ssize_t n = read(fd, buffer, room);
    if (n >= 0 || errno != EINTR) return n;
  }
}

bool write_all(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = write(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data += n;
    size -= std::size_t(n);
  }
  return true;
}

}  // namespace

std::string safe_line(std::string_view bytes) {
  std::string out;
  for (const char c : safe_text(bytes)) {
    if (c == '\n' || c == '\t')
      out += as_text(static_cast<unsigned char>(c));
    else
      out += c;
  }
  return out;
}

std::string safe_text(std::string_view bytes) {
  std::string out;
  out.reserve(bytes.size());
  for (std::size_t at = 0; at < bytes.size();) {
    const Decoded d = decode(bytes, at);
    const bool windows_line_end = d.valid && d.code == '\r' && at + 1 < bytes.size() && bytes[at + 1] == '\n';
    if (!d.valid)
      out += kReplacement;
    else if (windows_line_end) {
    }  // its "\n" comes next
    else if (shown_as_text(d.code))
      out += as_text(d.code);
    else
      out.append(bytes.substr(at, d.length));
    at += d.length;
  }
  return out;
}

std::string quoted_lines(std::string_view text, const std::string& indent) {
  const std::string safe = safe_text(text);
  std::string_view rest = safe;
  if (!rest.empty() && rest.back() == '\n') rest.remove_suffix(1);
  std::string out;
  for (;;) {
    const std::size_t end = rest.find('\n');
    const std::string_view line = rest.substr(0, end);
    out += indent;
    out += line.empty() ? kQuote.substr(0, 1) : kQuote;
    out += line;
    if (end == std::string_view::npos) break;
    out += '\n';
    rest.remove_prefix(end + 1);
  }
  return out;
}

std::string quoted_after_label(std::string_view text, const std::string& indent) {
  const std::string safe = safe_text(text);
  const std::size_t end = safe.find('\n');
  if (end == std::string::npos) return safe;
  return safe.substr(0, end) + "\n" + quoted_lines(std::string_view(safe).substr(end + 1), indent);
}

std::string shell_quote(std::string_view text) {
  // Inside single quotes a POSIX shell gives every character its literal meaning; a
  // quote itself ends the quoted part, is written escaped, and a new part begins.
  std::string out = "'";
  for (const char c : text) {
    if (c == '\'')
      out += "'\\''";
    else
      out += c;
  }
  return out + "'";
}

bool is_replay_token(std::string_view token) {
  const std::size_t colon = token.find(':');
  if (colon == std::string_view::npos || colon == 0) return false;  // no query in front
  const std::string_view query = token.substr(0, colon);
  const std::string_view query_characters = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_. -";
  if (query.find_first_not_of(query_characters) != std::string_view::npos) return false;  // no query is named so
  std::string_view rest = token.substr(colon + 1);
  while (!rest.empty()) {
    const std::size_t comma = rest.find(',');
    const std::string_view item = rest.substr(0, comma);
    if (!is_number(item)) return false;  // codec.cpp never writes this value
    if (comma == std::string_view::npos) break;
    rest.remove_prefix(comma + 1);
    if (rest.empty()) return false;  // a trailing comma: an empty value
  }
  return true;
}

std::string replay_command(const std::string& verb, const std::string& lab_id, std::string_view token) {
  if (!is_replay_token(token)) return "";  // not what the harness writes: never a command
  return "./labkit " + verb + " " + lab_id + " --case " + shell_quote(token);
}

UntrustedRead read_untrusted_file(const std::string& path, std::uintmax_t max_bytes) {
  Descriptor file;
  UntrustedRead r;
  r.error = open_untrusted(path, max_bytes, file);
  if (!r.error.empty()) return r;
  char buffer[1 << 16];
  for (;;) {
    // One byte past the cap at most: enough to tell that it grew past it.
    const std::uintmax_t room = std::min<std::uintmax_t>(sizeof buffer, max_bytes + 1 - r.text.size());
    const ssize_t n = read_some(file.fd, buffer, std::size_t(room));
    if (n < 0) return {"", "cannot be read (" + error_text(errno) + ")"};
    if (n == 0) return r;
    r.text.append(buffer, std::size_t(n));
    if (r.text.size() > max_bytes) return {"", "is larger than " + size_text(max_bytes)};
  }
}

std::string copy_untrusted_file(const std::string& from, const std::string& to, std::uintmax_t max_bytes) {
  Descriptor in, out;
  const std::string why = open_untrusted(from, max_bytes, in);
  if (!why.empty()) return why;
  out.fd = open(to.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (out.fd < 0 || fchmod(out.fd, 0644) != 0) return "cannot be copied to " + to + " (" + error_text(errno) + ")";
  char buffer[1 << 16];
  std::uintmax_t copied = 0;
  for (;;) {
    const std::uintmax_t room = std::min<std::uintmax_t>(sizeof buffer, max_bytes + 1 - copied);
    const ssize_t n = read_some(in.fd, buffer, std::size_t(room));
    if (n < 0) return "cannot be read (" + error_text(errno) + ")";
    if (n == 0) return "";
    copied += std::uintmax_t(n);
    if (copied > max_bytes) return "is larger than " + size_text(max_bytes);  // it grew while copied
    if (!write_all(out.fd, buffer, std::size_t(n))) return "cannot be copied to " + to + " (" + error_text(errno) + ")";
  }
}

}  // namespace runner
