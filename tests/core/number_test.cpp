// The one number reader: finite decimal numbers are read exactly as written,
// every spelling of NaN and infinity that from_chars, strtod or YAML would accept is refused.
#include "isolab/core/number.h"

#include <gtest/gtest.h>

#include <string>

namespace isolab {
namespace {

TEST(ParseFiniteNumber, ReadsFiniteDecimalNumbersExactly) {
  EXPECT_EQ(ParseFiniteNumber("2"), 2.0);
  EXPECT_EQ(ParseFiniteNumber("-1.5e-3"), -1.5e-3);
  EXPECT_EQ(ParseFiniteNumber("+4"), 4.0);
  EXPECT_EQ(ParseFiniteNumber("0.1"), 0.1);  // the double nearest 0.1, as the compiler reads it
  EXPECT_EQ(ParseFiniteNumber("1.7976931348623157e308"), 1.7976931348623157e308);
}

TEST(ParseFiniteNumber, RefusesNonFiniteSpellingsSayingWhy) {
  for (const char* text : {"nan", "NaN", "-nan", "+nan", "nan(0x1)", "inf", "-inf", "+INF",
                           "infinity", "-Infinity", ".nan", ".NaN", ".inf", "-.inf", "+.Inf"}) {
    std::string problem;
    EXPECT_FALSE(ParseFiniteNumber(text, &problem)) << text;
    EXPECT_EQ(problem, std::string("'") + text + "' is not a finite number") << text;
  }
}

TEST(ParseFiniteNumber, RefusesOverflowAndNonNumbers) {
  std::string problem;
  EXPECT_FALSE(ParseFiniteNumber("1e999", &problem));
  EXPECT_EQ(problem, "'1e999' is out of range");
  for (const char* text : {"", " 1", "1 ", "1,5", "0x10", "+-1", "++1", "1e", "stiff", "nanny"}) {
    EXPECT_FALSE(ParseFiniteNumber(text, &problem)) << text;
    EXPECT_EQ(problem, std::string("'") + text + "' is not a number") << text;
  }
}

// The plain prefix reader takes what ParseFiniteNumber takes, without a '+', and says how much.
TEST(ReadPlainFiniteNumber, ReadsWhatParseFiniteNumberReadsAndSaysWhereItStopped) {
  for (const char* text : {"2", "-1.5e-3", "0.1", "1.7976931348623157e308", "-0", ".5", "1."}) {
    std::size_t length = 0;
    EXPECT_EQ(ReadPlainFiniteNumber(text, &length), ParseFiniteNumber(text)) << text;
    EXPECT_EQ(length, std::string(text).size()) << text;
  }
  std::size_t length = 0;
  EXPECT_EQ(ReadPlainFiniteNumber("1.5,2", &length), 1.5);
  EXPECT_EQ(length, 3u);
  EXPECT_EQ(ReadPlainFiniteNumber("1e", &length), 1.0);  // the caller sees the 'e' left over
  EXPECT_EQ(length, 1u);
  for (const char* text : {"+4", "nan", "-inf", "infinity", ".nan", "1e999", "", " 1", "x"}) {
    EXPECT_FALSE(ReadPlainFiniteNumber(text, &length)) << text;
  }
}

}  // namespace
}  // namespace isolab
