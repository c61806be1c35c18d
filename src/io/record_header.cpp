#include "record_header.h"

#include <cctype>

namespace isolab::io {
namespace {

// ASCII case folding: the words sought are ASCII, and std::tolower (a call per character,
// locale-dependent) was most of the time spent looking for "end data" on every data line.
char AsciiLower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }
bool SameLetter(char a, char b) { return AsciiLower(a) == AsciiLower(b); }

bool IsSpace(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }
bool IsDigit(char c) { return c >= '0' && c <= '9'; }
bool IsNumberChar(char c) {
  return IsDigit(c) || c == '.' || c == 'e' || c == 'E' || c == 'd' || c == 'D' || c == '+' ||
         c == '-';
}
bool IsUnitChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '/' || c == '^' || c == '*' ||
         c == '.';
}

// Where `word` starts in `text` at or after `from` (letters in any case), or npos. The words
// sought are a few letters long, so this is linear in the text.
std::size_t FindIgnoringCase(std::string_view text, std::string_view word, std::size_t from = 0) {
  if (word.size() > text.size()) return std::string_view::npos;
  for (std::size_t i = from; i + word.size() <= text.size(); ++i) {
    std::size_t k = 0;
    while (k < word.size() && SameLetter(text[i + k], word[k])) ++k;
    if (k == word.size()) return i;
  }
  return std::string_view::npos;
}

// A position in a line that only moves forwards; each Take* consumes what it matched.
class Cursor {
 public:
  Cursor(std::string_view text, std::size_t at) : text_(text), at_(at) {}

  std::size_t at() const { return at_; }

  bool TakeWord(std::string_view word) {
    if (text_.size() - at_ < word.size()) return false;
    for (std::size_t k = 0; k < word.size(); ++k) {
      if (!SameLetter(text_[at_ + k], word[k])) return false;
    }
    at_ += word.size();
    return true;
  }
  bool TakeChar(char c) {
    if (at_ >= text_.size() || text_[at_] != c) return false;
    ++at_;
    return true;
  }
  // The run of characters `accept` takes from here (possibly empty).
  template <typename Predicate>
  std::string_view TakeRun(Predicate accept) {
    const std::size_t start = at_;
    while (at_ < text_.size() && accept(text_[at_])) ++at_;
    return text_.substr(start, at_ - start);
  }
  std::size_t TakeSpaces() { return TakeRun(IsSpace).size(); }

 private:
  std::string_view text_;
  std::size_t at_;
};

// NPTS\s*=\s*(\d+)\s*,?\s*DT\s*=\s*([number]+), tried where an NPTS starts.
std::optional<HeaderSampling> NptsDtAt(std::string_view line, std::size_t at) {
  Cursor cursor(line, at);
  HeaderSampling found;
  cursor.TakeWord("npts");
  cursor.TakeSpaces();
  if (!cursor.TakeChar('=')) return std::nullopt;
  cursor.TakeSpaces();
  found.points = cursor.TakeRun(IsDigit);
  if (found.points.empty()) return std::nullopt;
  cursor.TakeSpaces();
  cursor.TakeChar(',');
  cursor.TakeSpaces();
  if (!cursor.TakeWord("dt")) return std::nullopt;
  cursor.TakeSpaces();
  if (!cursor.TakeChar('=')) return std::nullopt;
  cursor.TakeSpaces();
  found.step = cursor.TakeRun(IsNumberChar);
  if (found.step.empty()) return std::nullopt;
  return found;
}

}  // namespace

bool ContainsIgnoringCase(std::string_view text, std::string_view word) {
  return FindIgnoringCase(text, word) != std::string_view::npos;
}

std::optional<HeaderSampling> FindNptsDt(std::string_view line) {
  // An attempt reads only spaces, digits, '=', ',', "DT" and a number after its NPTS, none of
  // which starts another NPTS: the attempts read disjoint stretches of the line.
  for (std::size_t at = FindIgnoringCase(line, "npts"); at != std::string_view::npos;
       at = FindIgnoringCase(line, "npts", at + 1)) {
    if (auto found = NptsDtAt(line, at)) return found;
  }
  return std::nullopt;
}

std::optional<HeaderSampling> FindOldestSampling(std::string_view line) {
  Cursor cursor(line, 0);
  HeaderSampling found;
  cursor.TakeSpaces();
  found.points = cursor.TakeRun(IsDigit);
  if (found.points.empty() || cursor.TakeSpaces() == 0) return std::nullopt;
  found.step = cursor.TakeRun(IsNumberChar);
  if (found.step.empty() || cursor.TakeSpaces() == 0) return std::nullopt;
  if (!cursor.TakeWord("npts")) return std::nullopt;
  cursor.TakeSpaces();
  if (!cursor.TakeChar(',')) return std::nullopt;
  cursor.TakeSpaces();
  if (!cursor.TakeWord("dt")) return std::nullopt;
  return found;
}

std::optional<HeaderSampling> FindPeknoldSampling(std::string_view line) {
  constexpr std::string_view kPhrase = "points at equal spacing of";
  for (std::size_t at = FindIgnoringCase(line, kPhrase); at != std::string_view::npos;
       at = FindIgnoringCase(line, kPhrase, at + 1)) {
    // Back over the spaces and the count before the phrase.
    std::size_t start = at;
    while (start > 0 && IsSpace(line[start - 1])) --start;
    if (start == at) continue;
    const std::size_t count_end = start;
    while (start > 0 && IsDigit(line[start - 1])) --start;
    if (start == count_end) continue;
    Cursor cursor(line, at + kPhrase.size());
    if (cursor.TakeSpaces() == 0) continue;
    HeaderSampling found;
    found.points = line.substr(start, count_end - start);
    found.step = cursor.TakeRun(IsNumberChar);
    cursor.TakeSpaces();
    if (found.step.empty() || !cursor.TakeWord("sec")) continue;
    return found;
  }
  return std::nullopt;
}

std::optional<UnitsStatement> FindUnitsStatement(std::string_view line) {
  const auto statement = [&](std::size_t at, const Cursor& cursor, std::string_view unit) {
    while (!unit.empty() && unit.back() == '.') unit.remove_suffix(1);
    return UnitsStatement{line.substr(at, cursor.at() - at), unit};
  };
  // PEER: "... IN UNITS OF G", anywhere.
  if (const std::size_t at = FindIgnoringCase(line, "units of"); at != std::string_view::npos) {
    Cursor cursor(line, at + 8);
    cursor.TakeSpaces();
    const std::string_view unit = cursor.TakeRun(IsUnitChar);
    return statement(at, cursor, unit);
  }
  // Peknold: "The units are (g)", with its parentheses (else it is prose).
  for (std::size_t at = FindIgnoringCase(line, "units are"); at != std::string_view::npos;
       at = FindIgnoringCase(line, "units are", at + 1)) {
    Cursor cursor(line, at + 9);
    cursor.TakeSpaces();
    if (!cursor.TakeChar('(')) continue;
    const std::string_view unit = cursor.TakeRun(IsUnitChar);
    if (!cursor.TakeChar(')')) continue;
    return statement(at, cursor, unit);
  }
  // The oldest PEER files: a line "ACCELERATION IN G" and nothing more (a description's
  // "acceleration in the north" is prose).
  Cursor cursor(line, 0);
  cursor.TakeSpaces();
  const std::size_t at = cursor.at();
  if (cursor.TakeWord("acceleration in") && cursor.TakeSpaces() > 0) {
    const std::string_view unit = cursor.TakeRun(IsUnitChar);
    Cursor rest = cursor;
    rest.TakeSpaces();
    if (!unit.empty() && rest.at() == line.size()) return statement(at, cursor, unit);
  }
  return std::nullopt;
}

std::optional<UnitsStatement> FindCsvUnits(std::string_view header) {
  const std::size_t comma = header.rfind(',');
  const std::string_view column =
      comma == std::string_view::npos ? header : header.substr(comma + 1);
  const std::size_t open = column.find('(');
  if (open == std::string_view::npos) return std::nullopt;
  const std::size_t close = column.find(')', open);
  const std::size_t end = close == std::string_view::npos ? column.size() : close + 1;
  std::string_view unit = column.substr(open + 1, end - open - 1);
  if (close != std::string_view::npos) unit.remove_suffix(1);
  while (!unit.empty() && IsSpace(unit.front())) unit.remove_prefix(1);
  while (!unit.empty() && IsSpace(unit.back())) unit.remove_suffix(1);
  return UnitsStatement{column.substr(open, end - open), unit};
}

}  // namespace isolab::io
