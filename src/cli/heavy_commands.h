// The commands the front hands over to another executable (main.cpp), each named once: the
// executable that runs it, and the description both `isolab --help` and the command's own
// registration print.
#pragma once

#include <string_view>

namespace isolab::cli {

struct HeavyCommand {
  std::string_view name, executable, help;
};

inline constexpr HeavyCommand kFitCommand{
    "fit", "isolab-search",
    "Identify an isolator model's parameters from cyclic tests (CMA-ES), or a building's from "
    "shake-table motions (--building)"};
inline constexpr HeavyCommand kDiagnoseCommand{
    "diagnose", "isolab-search",
    "Fit a base isolator model to cyclic tests, name the effects it lacks, add them and refit"};
inline constexpr HeavyCommand kCompareCommand{
    "compare", "isolab-studies",
    "Isolator variants under a suite of records and scale factors: per-run HDF5 and a summary "
    "(worker processes, or MPI ranks under mpirun)"};
inline constexpr HeavyCommand kDesignCommand{
    "design", "isolab-studies",
    "Design an isolated building as ASCE 7-16 chapter 17 asks: bound models, the ELF "
    "procedure, a suite scaled to the target spectrum, runs with accidental eccentricity, "
    "design values and checks in a report"};
inline constexpr HeavyCommand kHeavyCommands[] = {kFitCommand, kDiagnoseCommand, kCompareCommand,
                                                  kDesignCommand};

}  // namespace isolab::cli
