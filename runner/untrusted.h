// What a submission controls, made harmless before the grader uses it: the text of its
// compiler errors, its output, its reports and its file names (any bytes at all), the
// replay tokens its reports name (pasted into a shell), and the files it leaves behind
// (which may be FIFOs, links or far too large).
//
// The rule: text a student controls goes through safe_text() before it reaches
// results.json, junit.xml, report.txt, steps.tsv, class.csv or a terminal, and text of
// several lines goes there through quoted_lines() (every line marked "| "); a command
// built from it goes through shell_quote(); a file from a submission or a scratch folder
// is opened only by read_untrusted_file() or copy_untrusted_file().
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace runner {

// Any bytes as valid UTF-8 that shows the same to everyone: each invalid sequence becomes
// U+FFFD (never dropped silently); terminal controls (ESC, CR, BEL, ..., C1, bidi
// overrides) are shown as text ("\x1b", "\u009b"), so they cannot move a cursor, hide a
// line or reorder one. Newlines and tabs stay; "\r\n" becomes "\n". Idempotent.
std::string safe_text(std::string_view bytes);

// safe_text for text that must stay on one line (a file or test name in a note): a
// newline or tab in it is shown as "\x0a" or "\x09" too, so it cannot forge a line.
std::string safe_line(std::string_view bytes);

// Text a student controls (compiler errors, what its code printed, exception messages)
// as a block of lines that cannot pass for the kit's own: safe_text, after which a
// newline is the only line break left (CR, VT, FF, NEL, U+2028 and U+2029 are shown as
// text), then every line starts with `indent` and kQuote. No final newline. The one
// quoting function: every output (terminal, report.txt, results.json, junit.xml, the
// class page) puts multi-line student text on its own lines only through it.
inline constexpr std::string_view kQuote = "| ";
std::string quoted_lines(std::string_view text, const std::string& indent = "");

// A value after a label of the kit's ("got       " + value): its first line stays on
// the label's line (nothing can start a line there), and every further line is
// quoted_lines(), under `indent`.
std::string quoted_after_label(std::string_view text, const std::string& indent);

// One word for a POSIX shell that stands for `text` exactly: 'it'\''s'.
std::string shell_quote(std::string_view text);

// True when `token` has the shape the harness gives replay tokens
// (common/harness/codec.cpp): "query:v1,v2,..." with a query of letters, digits, '_',
// '.', ' ' or '-', and each value a number, "inf", "-inf" or "nan".
bool is_replay_token(std::string_view token);

// "./labkit check 02 --case 'query:1,2'" (verb "check" or "view"), quoted for a shell;
// "" when `token` is not a replay token, so a crafted one never becomes a command.
std::string replay_command(const std::string& verb, const std::string& lab_id, std::string_view token);

struct UntrustedRead {
  std::string text;   // the file's bytes, when error is ""
  std::string error;  // why it was not read, said of the file: "is a FIFO, not a regular
                      // file", "is larger than 1 MB", "cannot be opened (...)"
};

// A file the graded code may have replaced or left behind: opened without following a
// final symlink and without waiting (O_NOFOLLOW | O_NONBLOCK: a FIFO would block open()
// forever), then read only if it is a regular file of at most `max_bytes`.
UntrustedRead read_untrusted_file(const std::string& path, std::uintmax_t max_bytes);

// The same checks, streamed into a new file `to` (mode 0644) that the grader owns;
// returns "" or why it was not copied, said of the file as above.
std::string copy_untrusted_file(const std::string& from, const std::string& to, std::uintmax_t max_bytes);

}  // namespace runner
