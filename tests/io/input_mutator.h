// Seeded mutations of a text input, for fuzzing isolab's readers without a fuzzing compiler: the
// edits careless users and broken tools make (a flipped byte, a cut-off file, a line pasted twice
// or lost, a 20 kB line, a number too big for its type), one to four at a time. The same seed
// gives the same mutants on every platform (std::mt19937_64's sequence is fixed by the standard,
// and only its raw output is used).
#pragma once

#include <array>
#include <cstdint>
#include <random>
#include <string>
#include <string_view>
#include <vector>

namespace isolab::testing {

class InputMutator {
 public:
  explicit InputMutator(std::uint64_t seed) : engine_(seed) {}

  // A mutant of `input`; `*edits` says what was done ("flip@12 truncate@40"), to reproduce it.
  std::string Mutate(std::string input, std::string* edits) {
    edits->clear();
    const std::size_t count = 1 + Below(4);
    for (std::size_t k = 0; k < count; ++k) {
      if (!edits->empty()) *edits += ' ';
      *edits += Edit(&input);
    }
    return input;
  }

 private:
  // Characters with a meaning in YAML, CSV, AT2 headers or numbers.
  // (An array, not a string_view: it holds a NUL.)
  static constexpr char kSpecial[] = ":-{}[],\n \t#\"'&*!|>%@`.eE+0123456789\0\r=()/^";
  // Numbers at and past the edges of what readers hold.
  static constexpr std::array<std::string_view, 16> kNumbers = {
      "1e308", "1e309",  "-1e308",     "99999999999999999999", "0",  "-0",  "nan",  ".nan",
      "inf",   "1e-320", "2147483648", "4294967296",           "-1", "1e9", "0x10", "1,5"};

  std::size_t Below(std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(engine_() % n); }
  char Special() { return kSpecial[Below(sizeof(kSpecial) - 1)]; }

  // Starts of the text's lines (0 first; a trailing newline starts no line).
  static std::vector<std::size_t> LineStarts(const std::string& text) {
    std::vector<std::size_t> starts{0};
    for (std::size_t i = 0; i + 1 < text.size(); ++i) {
      if (text[i] == '\n') starts.push_back(i + 1);
    }
    return starts;
  }
  static std::size_t LineEnd(const std::string& text, std::size_t start) {
    const std::size_t end = text.find('\n', start);
    return end == std::string::npos ? text.size() : end + 1;
  }

  std::string Edit(std::string* text) {
    std::string& s = *text;
    const std::size_t at = Below(s.size() + 1);
    switch (Below(10)) {
      case 0:
        if (s.empty()) return "none";
        s[at % s.size()] = static_cast<char>(s[at % s.size()] ^ (1 << Below(8)));
        return "flip@" + std::to_string(at % s.size());
      case 1:
        if (s.empty()) return "none";
        s[at % s.size()] = Special();
        return "set@" + std::to_string(at % s.size());
      case 2:
        s.resize(at);
        return "truncate@" + std::to_string(at);
      case 3: {  // a line pasted again elsewhere
        const std::vector<std::size_t> starts = LineStarts(s);
        const std::size_t from = starts[Below(starts.size())];
        std::string line = s.substr(from, LineEnd(s, from) - from);
        if (line.empty() || line.back() != '\n') line += '\n';
        const std::size_t to = starts[Below(starts.size())];
        s.insert(to, line);
        return "duplicate@" + std::to_string(from) + "->" + std::to_string(to);
      }
      case 4: {  // a line lost
        const std::vector<std::size_t> starts = LineStarts(s);
        const std::size_t from = starts[Below(starts.size())];
        s.erase(from, LineEnd(s, from) - from);
        return "delete@" + std::to_string(from);
      }
      case 5: {  // a long line: inserted mid-line, or a whole line of its own
        const std::size_t length = Below(2) == 0 ? 5000 : 20000;
        const char fill = "9 a.-e,x"[Below(8)];
        s.insert(at, std::string(length, fill));
        return "long@" + std::to_string(at) + "x" + std::to_string(length);
      }
      case 6: {  // a number replaced by one at or past a limit
        std::size_t start = s.find_first_of("0123456789", at);
        if (start == std::string::npos) start = s.find_first_of("0123456789");
        if (start == std::string::npos) return "none";
        std::size_t end = start;
        while (end < s.size() &&
               std::string_view("0123456789.eE+-").find(s[end]) != std::string_view::npos) {
          ++end;
        }
        while (start > 0 &&
               std::string_view("0123456789.-+").find(s[start - 1]) != std::string_view::npos) {
          --start;
        }
        const std::string_view number = kNumbers[Below(kNumbers.size())];
        s.replace(start, end - start, number);
        return "number@" + std::to_string(start) + "=" + std::string(number);
      }
      case 7: {  // two lines swapped
        const std::vector<std::size_t> starts = LineStarts(s);
        std::size_t a = starts[Below(starts.size())], b = starts[Below(starts.size())];
        if (a == b) return "none";
        if (a > b) std::swap(a, b);
        const std::string first = s.substr(a, LineEnd(s, a) - a);
        std::string second = s.substr(b, LineEnd(s, b) - b);
        if (second.empty() || second.back() != '\n') second += '\n';
        s.replace(b, LineEnd(s, b) - b, first);
        s.replace(a, first.size(), second);
        return "swap@" + std::to_string(a) + "," + std::to_string(b);
      }
      case 8: {  // a few special bytes inserted
        std::string bytes;
        for (std::size_t k = 1 + Below(8); k > 0; --k) bytes += Special();
        s.insert(at, bytes);
        return "insert@" + std::to_string(at);
      }
      default: {  // a stretch of the text repeated in place
        const std::size_t length = Below(std::min<std::size_t>(s.size() - at, 200) + 1);
        s.insert(at, s.substr(at, length));
        return "repeat@" + std::to_string(at) + "+" + std::to_string(length);
      }
    }
  }

  std::mt19937_64 engine_;
};

}  // namespace isolab::testing
