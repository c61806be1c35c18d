// The commands the front hands over to another executable (main.cpp), each named once: the
// executable that runs it, and the description both `isolab --help` and the command's own
// registration print. The front keeps `run`, `spectrum` and `bounds`, so that it builds from the
// solver's libraries alone: the others need the cyclic, building, design or study libraries.
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
inline constexpr HeavyCommand kCyclicCommand{
    "cyclic", "isolab-search",
    "Impose u(t) = u_a sin(2 pi t / T) on a model's isolation assembly and report energy per "
    "cycle, peak force and slider displacements; or drive a model's isolation, or a plan model's "
    "isolators, along a path (--path) or an orbit (--orbit)"};
inline constexpr HeavyCommand kShakeTableCommand{
    "shaketable", "isolab-search",
    "Shake-table measurements of an isolated building: the isolator's measured history, the "
    "table record, and the model's prediction against the measurements"};
inline constexpr HeavyCommand kSynthCommand{"synth", "isolab-studies",
                                            "Write a seeded synthetic ground motion (AT2)"};
// In `isolab --help`'s order.
inline constexpr HeavyCommand kHeavyCommands[] = {
    kCyclicCommand,  kFitCommand,    kDiagnoseCommand,  kSynthCommand,
    kCompareCommand, kDesignCommand, kShakeTableCommand};

}  // namespace isolab::cli
