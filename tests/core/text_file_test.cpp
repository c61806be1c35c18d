// Bounded lines: a line up to the limit is read whole (with NUL bytes, CRLF endings and no final
// newline), also where the reader's blocks split it; one past it is refused at its line number,
// and nothing is read after it; a UTF-8 byte-order mark is dropped from the first line only; a
// whole file is refused over its limit before it is read.
#include "isolab/core/text_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "isolab/core/errors.h"
#include "own_test_file.h"

namespace isolab {
namespace {

std::string Write(const std::string& name, const std::string& bytes) {
  const auto path = testing::OwnTestFile(name);
  std::ofstream(path, std::ios::binary) << bytes;
  return path.string();
}

std::vector<std::string> AllLines(const std::string& path, std::size_t limit) {
  TextLines lines(path, limit);
  EXPECT_TRUE(lines.is_open());
  std::vector<std::string> out;
  for (std::string line; lines.Next(&line);) out.push_back(line);
  return out;
}

TEST(TextLines, ReadsLinesUpToTheLimitAsTheyAre) {
  const std::string nul("a\0b", 3);
  const std::string path = Write("lines.txt", "\xEF\xBB\xBF# first\r\n" + nul + "\n" +
                                                  std::string(10, 'x') + "\r\n\xEF\xBB\xBFlast");
  // The mark counts towards the first line's 10 characters: it is there until it is dropped.
  const std::vector<std::string> lines = AllLines(path, 10);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], "# first");  // the mark gone, and the '\r'
  EXPECT_EQ(lines[1], nul);
  EXPECT_EQ(lines[2], std::string(10, 'x'));  // exactly the limit, before a '\r'
  EXPECT_EQ(lines[3], "\xEF\xBB\xBFlast");    // a mark is only a mark at the start of the file
  EXPECT_TRUE(AllLines(Write("empty.txt", ""), 8).empty());
  EXPECT_EQ(AllLines(Write("newline.txt", "a\n"), 8), std::vector<std::string>{"a"});
}

TEST(TextLines, ALineOverTheLimitIsRefusedAtItsNumber) {
  for (const std::string& tail :
       {std::string(9, 'x'), std::string(9, 'x') + "\n", std::string(100000, '\0') + "\nnext\n"}) {
    const std::string path = Write("long.txt", "header\n" + tail);
    TextLines lines(path, 8);
    std::string line;
    ASSERT_TRUE(lines.Next(&line));
    try {
      lines.Next(&line);
      FAIL() << "a line of " << tail.size() << " characters was read";
    } catch (const InputError& error) {
      EXPECT_EQ(error.location().file, path);
      EXPECT_EQ(error.location().line, 2);
      EXPECT_NE(std::string(error.what()).find("a line of more than 8 characters"),
                std::string::npos)
          << error.what();
    }
    // "The rest is not read": not the line's remainder, nor the lines after it.
    EXPECT_FALSE(lines.Next(&line)) << "read after the refusal: " << line.substr(0, 20);
  }
}

// The reader finds lines a block at a time: lines across its blocks, and one of the default
// limit's length, come whole, as a plain split of the same bytes has them.
TEST(TextLines, LinesAcrossItsBlocksAreReadAsASplitOfTheBytes) {
  std::string bytes;
  unsigned seed = 12345;
  for (int line = 0; line < 400; ++line) {
    seed = seed * 1103515245u + 12345u;
    const std::size_t length = line == 150 ? kMaxLineLength : (seed >> 8) % 3000;
    for (std::size_t k = 0; k < length; ++k) bytes += static_cast<char>('a' + (k + line) % 26);
    bytes += line == 150 || (seed >> 4) % 3 == 0 ? "\r\n" : "\n";
  }
  std::vector<std::string> expected;
  for (std::size_t start = 0; start < bytes.size();) {
    const std::size_t end = bytes.find('\n', start);
    std::string line = bytes.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    expected.push_back(line);
    start = end + 1;
  }
  const std::string path = Write("blocks.txt", bytes);
  EXPECT_EQ(AllLines(path, kMaxLineLength), expected);
  TextLines views(path);
  std::size_t count = 0;
  for (std::string_view line; views.Next(&line); ++count) {
    ASSERT_LT(count, expected.size());
    EXPECT_EQ(line, expected[count]) << "line " << count + 1;
  }
  EXPECT_EQ(count, expected.size());
  EXPECT_EQ(views.line_number(), 400);
}

// A line of the limit's length whose '\r' is the last byte of the reader's first block and whose
// '\n' is the first of the next: it is read whole, not refused as one character too long.
TEST(TextLines, ALineAtTheLimitSplitBetweenBlocksBeforeItsNewlineIsRead) {
  constexpr std::size_t kFirstBlock = 64 * 1024;
  std::string bytes;
  while (bytes.size() + 4 <= kFirstBlock - 9) bytes += "abc\n";
  bytes += std::string(kFirstBlock - 9 - bytes.size() - 1, 'y') + "\n";
  bytes += std::string(8, 'x') + "\r";
  ASSERT_EQ(bytes.size(), kFirstBlock);
  bytes += "\nnext\n";
  const std::vector<std::string> lines = AllLines(Write("split.txt", bytes), 8);
  ASSERT_GE(lines.size(), 2u);
  EXPECT_EQ(lines[lines.size() - 2], std::string(8, 'x'));
  EXPECT_EQ(lines.back(), "next");
}

TEST(ReadBoundedText, RefusesAFileOverItsLimitBeforeReadingIt) {
  EXPECT_EQ(ReadBoundedText(Write("small.yaml", "\xEF\xBB\xBFunits: {}\n"), 64), "units: {}\n");
  const std::string path = Write("large.yaml", std::string(65, '#'));
  try {
    ReadBoundedText(path, 64);
    FAIL() << "65 bytes read under a 64-byte limit";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("65 bytes: more than the"), std::string::npos)
        << error.what();
  }
  EXPECT_THROW(ReadBoundedText(testing::OwnTestDirectory().string(), 64), InputError);
}

}  // namespace
}  // namespace isolab
