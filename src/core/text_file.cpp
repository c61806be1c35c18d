#include "isolab/core/text_file.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iterator>

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

}  // namespace

TextLines::TextLines(const std::string& path, std::size_t max_length)
    : path_((RequireRegularFile(path), path)),
      in_(path, std::ios::binary),
      buffer_(max_length + 2) {}

bool TextLines::Next(std::string* line) {
  if (done_) return false;
  // getline stores at most size - 1 characters: the limit, a '\r' before the '\n', and one more
  // to tell an overlong line from one that fills the limit exactly.
  in_.getline(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  const std::streamsize read = in_.gcount();
  if (in_.eof()) {
    done_ = true;
    if (read == 0) return false;  // the end, after a final '\n' or in an empty file
  } else if (in_.fail()) {
    // size - 1 characters and no '\n' yet.
    throw InputError({path_, line_number_ + 1},
                     fmt::format("a line of more than {} characters: is this a text file of the "
                                 "expected kind? (the rest is not read)",
                                 buffer_.size() - 2));
  }
  ++line_number_;
  // gcount counts the '\n' extracted, which is not stored.
  std::size_t length = static_cast<std::size_t>(read) - (done_ ? 0 : 1);
  if (length > 0 && buffer_[length - 1] == '\r') --length;
  if (length > buffer_.size() - 2) {
    throw InputError({path_, line_number_},
                     fmt::format("a line of more than {} characters: is this a text file of the "
                                 "expected kind? (the rest is not read)",
                                 buffer_.size() - 2));
  }
  line->assign(buffer_.data(), length);
  if (line_number_ == 1) StripByteOrderMark(line);
  return true;
}

void StripByteOrderMark(std::string* text) {
  if (text->starts_with("\xEF\xBB\xBF")) text->erase(0, 3);
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
