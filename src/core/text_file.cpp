#include "isolab/core/text_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iterator>
#include <string_view>

#include "isolab/core/errors.h"

namespace isolab {

namespace {

// A directory opens as a stream on Linux and throws from its first read; opening a pipe waits for
// a writer, and a device may never end: every reader takes regular files only (errors.md).
void RequireRegularFile(const std::string& path) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (status.type() == std::filesystem::file_type::directory) {
    throw InputError({path}, "is a directory, not a file");
  }
  if (!error && status.type() != std::filesystem::file_type::regular) {
    throw InputError({path},
                     "is not a regular file (a device or a pipe): isolab reads its "
                     "inputs only from files");
  }
}

// Lines are found in blocks this large (or the limit, if larger): a read per block, not per line.
constexpr std::size_t kBlockBytes = 64 * 1024;

// The UTF-8 byte-order mark (EF BB BF) that editors on Windows put before a file's first line.
constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";

}  // namespace

TextLines::TextLines(const std::string& path, std::size_t max_length)
    : path_((RequireRegularFile(path), path)),
      max_length_(max_length),
      in_(path, std::ios::binary),
      // A '\r' after the limit's characters, and one more to tell an overlong line from one that
      // fills the limit exactly.
      buffer_(std::max(max_length + 2, kBlockBytes)) {}

void TextLines::Refill() {
  std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
  end_ -= begin_;
  begin_ = 0;
  in_.read(buffer_.data() + end_, static_cast<std::streamsize>(buffer_.size() - end_));
  const auto read = static_cast<std::size_t>(in_.gcount());
  end_ += read;
  // A short read is the end (or a read error, which ends the file the same way).
  if (!in_ || read == 0) end_of_file_ = true;
}

bool TextLines::Next(std::string_view* line) {
  if (done_) return false;
  const char* newline = nullptr;
  // Until a '\n', the end, or more unread bytes than a line may have (with its '\r').
  while (true) {
    newline = static_cast<const char*>(std::memchr(buffer_.data() + begin_, '\n', end_ - begin_));
    if (newline != nullptr || end_of_file_ || end_ - begin_ > max_length_ + 1) break;
    Refill();
  }
  const char* start = buffer_.data() + begin_;
  std::size_t length =
      newline != nullptr ? static_cast<std::size_t>(newline - start) : end_ - begin_;
  if (newline == nullptr && end_of_file_) {
    done_ = true;
    if (length == 0) return false;  // the end, after a final '\n' or in an empty file
  }
  ++line_number_;
  begin_ += length + (newline != nullptr ? 1 : 0);
  if (length > 0 && start[length - 1] == '\r') --length;
  if (length > max_length_) {
    done_ = true;  // as the message says: a caller that goes on reads no part of this line
    throw InputError({path_, line_number_},
                     fmt::format("a line of more than {} characters: is this a text file of the "
                                 "expected kind? (the rest is not read)",
                                 max_length_));
  }
  *line = std::string_view(start, length);
  if (line_number_ == 1 && line->starts_with(kByteOrderMark)) {
    line->remove_prefix(kByteOrderMark.size());
  }
  return true;
}

bool TextLines::Next(std::string* line) {
  std::string_view view;
  if (!Next(&view)) return false;
  line->assign(view);
  return true;
}

void StripByteOrderMark(std::string* text) {
  if (text->starts_with(kByteOrderMark)) text->erase(0, kByteOrderMark.size());
}

std::string ReadBoundedText(const std::string& path, std::size_t max_bytes) {
  RequireRegularFile(path);
  std::ifstream stream(path, std::ios::binary);
  if (!stream) throw InputError({path}, fmt::format("cannot open ({})", std::strerror(errno)));
  std::error_code error;
  const auto size = std::filesystem::file_size(path, error);
  if (!error && size > max_bytes) {
    throw InputError({path}, fmt::format("{} bytes: more than the {} MiB a model, study or "
                                         "specification file may have (is this one?)",
                                         size, max_bytes >> 20));
  }
  std::string text;
  try {
    // At most one byte past the limit, whatever the file system said the size was.
    std::istreambuf_iterator<char> in(stream), end;
    while (in != end && text.size() <= max_bytes) text.push_back(*in++);
  } catch (const std::ios_base::failure& failure) {
    throw InputError({path}, fmt::format("cannot read ({})", failure.what()));
  }
  if (text.size() > max_bytes) {
    throw InputError({path}, fmt::format("more than the {} MiB a model, study or specification "
                                         "file may have (is this one?)",
                                         max_bytes >> 20));
  }
  StripByteOrderMark(&text);
  return text;
}

}  // namespace isolab
