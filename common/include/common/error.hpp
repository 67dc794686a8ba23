#pragma once
// Errors that reach the user. A bad input is a value that says where it went wrong;
// a broken invariant is an assert, not one of these.
//
// The program prints an InputError as one line and exits with status 2:
//   worlds/x.txt:7:13: error: cell (3,4): east wall missing on the west side of (4,4)
//   error: --p-occ must be greater than --prior (got 0.4 <= 0.5)

#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include <fmt/format.h>

namespace common {

// `text` with every control byte (below 0x20, and 0x7f: an ESC, a newline, a carriage return
// that an input file or a path may hold) written as \xNN, so that a message stays one line
// and cannot drive the terminal. Other bytes (UTF-8 included) are kept.
inline std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7f) {
      out += fmt::format("\\x{:02x}", byte);
    } else {
      out += c;
    }
  }
  return out;
}

// Where in an input file something is; line and column count from 1, 0 means "not known".
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;
};

// A user's input (file, option, sensor value) is unusable. Exit status 2.
class InputError : public std::runtime_error {
 public:
  explicit InputError(std::string message)
      : std::runtime_error(message), message_(std::move(message)) {}
  InputError(SourceLocation where, std::string message)
      : std::runtime_error(message), where_(std::move(where)), message_(std::move(message)) {}

  const SourceLocation &where() const { return where_; }
  const std::string &message() const { return message_; }

  // The one line the user sees: "FILE:LINE:COL: error: WHAT", or "error: WHAT", control
  // bytes escaped (printable()).
  std::string diagnostic() const {
    if (where_.file.empty()) return printable(fmt::format("error: {}", message_));
    if (where_.line == 0) return printable(fmt::format("{}: error: {}", where_.file, message_));
    if (where_.column == 0) return printable(fmt::format("{}:{}: error: {}", where_.file, where_.line, message_));
    return printable(fmt::format("{}:{}:{}: error: {}", where_.file, where_.line, where_.column, message_));
  }

 private:
  SourceLocation where_;
  std::string message_;
};

// Throws InputError(message) unless `ok`: a check of a user's value, in one line.
inline void require_input(bool ok, const std::string &message) {
  if (!ok) throw InputError(message);
}

// Something the program itself could not do (a write failed, a robot made no progress).
// Exit status 1.
class RuntimeFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace common
