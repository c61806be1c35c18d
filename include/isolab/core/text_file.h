// Bounded text input for every reader of isolab's text formats (records, cyclic-test and
// shake-table CSV, YAML files). A line is read only up to a limit: a file that is not text (a
// header followed by a gigabyte of NUL bytes) is refused at its first overlong line, located,
// having read at most one block of it (64 KiB, or the limit if larger), instead of being buffered
// whole (which cost `run --record` 2 GB
// of memory and `shaketable` 8 GB). A UTF-8 byte-order mark, which editors on Windows put before
// the first line, is removed: kept, it turned a CSV's comment line into its header.
#pragma once

#include <cstddef>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace isolab {

// No line of a record or a CSV table comes near this: a hundred channels of 15-digit numbers are
// 1,600 characters.
inline constexpr std::size_t kMaxLineLength = 65536;
// A model of 10^5 components is about 10 MB of YAML.
inline constexpr std::size_t kMaxYamlBytes = 64u << 20;

// The lines of a file, one at a time.
class TextLines {
 public:
  explicit TextLines(const std::string& path, std::size_t max_length = kMaxLineLength);

  // False when the file could not be opened (errno says why): callers word their own message.
  bool is_open() const { return in_.is_open(); }

  // The next line without its '\n' (nor a '\r' before it), without a UTF-8 byte-order mark on
  // the first line; false at the end of the file. Throws InputError at the line's number for a
  // line longer than the limit, having read at most one buffer of it (the limit, or 64 KiB);
  // after that, false.
  bool Next(std::string* line);
  // The same line as a view into the reader's buffer, valid until the next call (no copy).
  bool Next(std::string_view* line);

  int line_number() const { return line_number_; }

 private:
  // Moves the unread bytes to the buffer's start and reads after them.
  void Refill();

  std::string path_;
  std::size_t max_length_;
  std::ifstream in_;
  std::vector<char> buffer_;
  std::size_t begin_ = 0, end_ = 0;  // the bytes read and not yet returned
  bool end_of_file_ = false;         // nothing more to read after end_
  int line_number_ = 0;
  bool done_ = false;
};

// Removes a leading UTF-8 byte-order mark (EF BB BF) from `text`.
void StripByteOrderMark(std::string* text);

// A whole file of at most `max_bytes` (a YAML file), a leading byte-order mark removed. Throws
// InputError: a directory, a file that cannot be opened or read, or one over the limit (checked
// before reading: named with its size and the limit).
std::string ReadBoundedText(const std::string& path, std::size_t max_bytes = kMaxYamlBytes);

}  // namespace isolab
