// The statements of a record's header that isolab reads, found by hand-written scanners: each
// walks the line once forwards (a bounded look back at most), never backtracks, and so takes time
// linear in the line's length (std::regex took 93 s on a 20 kB line and overflowed the stack on
// 10 kB). Letters match in any case; "spaces" are any white space.
#pragma once

#include <optional>
#include <string_view>

namespace isolab::io {

// The texts of a declared sample count and step, as written (the caller parses and locates them).
struct HeaderSampling {
  std::string_view points;  // digits
  std::string_view step;    // digits, '.', e/E/d/D, '+', '-'
};

// "NPTS= 3000, DT= .02000 SEC" anywhere in the line (PEER; the comma is optional).
std::optional<HeaderSampling> FindNptsDt(std::string_view line);
// "  3000 0.02 NPTS, DT" opening the line (the oldest PEER files).
std::optional<HeaderSampling> FindOldestSampling(std::string_view line);
// "1559 points at equal spacing of 0.02 sec" anywhere in the line (Peknold files).
std::optional<HeaderSampling> FindPeknoldSampling(std::string_view line);

// A units statement and the unit it names, as written.
struct UnitsStatement {
  std::string_view statement;  // "UNITS OF CM/S/S"
  std::string_view unit;       // "CM/S/S"; empty when the statement names none
};

// The units statement of a header line: PEER's "UNITS OF G" (anywhere), Peknold's "The units
// are (g)" (with its parentheses) or the oldest PEER files' line "ACCELERATION IN G" (alone on
// its line). A unit is a run of letters, digits and / ^ * . (a sentence's closing '.' dropped).
std::optional<UnitsStatement> FindUnitsStatement(std::string_view line);
// A CSV header's units: the parentheses of its last column, "acc (m/s^2)" (the values' column).
std::optional<UnitsStatement> FindCsvUnits(std::string_view header);

// True when `text` contains `word`, letters in any case.
bool ContainsIgnoringCase(std::string_view text, std::string_view word);

}  // namespace isolab::io
