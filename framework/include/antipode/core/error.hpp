#pragma once
/// @file
/// The one exception type of antipode. Every error carries the context a user needs to fix
/// the input: where (file, line, column) and what (a one-line message, optionally a hint).

#include <stdexcept>
#include <string>
#include <vector>

namespace antipode {

/// A position in a user-supplied file. `line` and `column` are 1-based; 0 means unknown.
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;

  bool known() const { return !file.empty(); }
  /// "file:line:column", "file:line", "file" or "" depending on what is known.
  std::string str() const;
};

/// An error that reaches the user as one line: `file:line:column: message (hint)`.
///
/// Contract: what() is always a single line (newlines in the message are replaced by spaces)
/// and never empty. Throw it for bad input; the CLI prints what() and exits non-zero.
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message, SourceLocation where = {}, std::string hint = {});

  const std::string& message() const { return message_; }
  const SourceLocation& where() const { return where_; }
  const std::string& hint() const { return hint_; }

 private:
  std::string message_;
  SourceLocation where_;
  std::string hint_;
};

/// An unexpected failure inside antipode or a plugin (a bug, not bad input): a standard
/// exception or anything else thrown where an Error was expected. The CLI exits with code 3
/// for it instead of 2.
class InternalError : public Error {
 public:
  using Error::Error;
};

/// A tree names a node or plugin type that no loaded library provides: a misspelling, or the
/// type of a library the plugin host refused (the CLI then says so).
class UnknownTypeError : public Error {
 public:
  using Error::Error;
};

/// Called inside a catch block: rethrows the exception being handled with `who` and `where`
/// added when it has no location yet. Errors stay Errors (InternalErrors stay internal);
/// any other exception becomes an InternalError.
[[noreturn]] void rethrow_with_context(const std::string& who, const SourceLocation& where);

/// Returns the candidate nearest to `name` by edit distance if it is close enough to be a
/// plausible misspelling (distance <= max(2, |name| / 3)), otherwise "".
std::string closest_match(const std::string& name, const std::vector<std::string>& candidates);

/// " (did you mean 'x'?)" for the closest candidate, or "" when none is close.
std::string did_you_mean(const std::string& name, const std::vector<std::string>& candidates);

}  // namespace antipode
