// Detectors: each reads the discrepancy between a fitted model and the measurements (never a
// truth) and returns the statistic that shows its effect, with the threshold that statistic must
// reach before isolab will name the effect. Thresholds sit well above what a model that lacks
// nothing leaves under measurement noise (the null case of tests/diagnosis measures how far).
//
//   rate_dependence:     partial R^2 of a global viscous term c v in the residual, after each
//                        test's own hysteretic-shaped terms (a sign(v) and a u column) are
//                        taken out, so a loop that is merely too thin or too soft does not count;
//                        c must come out positive. Supporting: the change of loop energy with
//                        test frequency at equal amplitude, measured against modelled.
// The loop statistics read half-cycles between reversals (discrepancy.h), grouped by test and
// amplitude (across the tests of one specimen tested in order):
//   amplitude_dependent_dissipation:
//                        the largest rise, from a smaller to a larger amplitude group, of the
//                        mean ln(measured / modelled energy per half-cycle), less twice its
//                        standard error.
//   large_amplitude_hardening:
//                        the same for the secant stiffness between reversals. Supporting: how
//                        much more of the residual lies at |u| > 0.7 u_a on loading branches of
//                        the larger half-cycles than the share of samples there.
//   cyclic_degradation:  how much more the measured energy falls from the first to the last
//                        half-cycle of an amplitude group than the modelled one, averaged over
//                        groups. Supporting: the same for the secant stiffness, and the change
//                        of the residual between those half-cycles relative to noise.
//   asymmetric_strength: the share of the residual a constant force per test explains (partial
//                        R^2). Every odd-symmetric law leaves a residual of mean near zero over
//                        whole cycles; a device stronger one way leaves its offset. Supporting:
//                        the mean offset and its sign across tests, and the midpoint of the
//                        forces at the top and bottom reversals, measured against modelled.
//   backlash:            the tangent stiffness after a reversal, read per half-cycle over bins
//                        of distance from the reversal (1 % of the largest range each) in the
//                        first half of the half-cycle and averaged: the largest rise from a
//                        nearer bin to a farther one, less twice its standard error, measured
//                        less modelled, over the model's stiffness right after the reversal. A
//                        clearance makes the stiffness drop and rise again at a distance from the
//                        reversal that does not grow with the amplitude; every other catalogue
//                        law stiffens monotonically less there (a hardening spring stiffens
//                        again only past the loop's centre, where |u| passes its breakpoint).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "isolab/diagnosis/discrepancy.h"
#include "isolab/diagnosis/effects.h"

namespace isolab::diagnosis {

struct Statistic {
  std::string name;
  double value = 0.0;
};

struct Evidence {
  Effect effect = Effect::kRateDependence;
  std::string statistic;   // what `value` measures
  double value = 0.0;      // the deciding statistic
  double threshold = 0.0;  // the value it must reach to support the effect
  std::string finding;     // one sentence with the numbers, for the report
  std::vector<Statistic> supporting;
  // Where the data place the effect's component, as starting values of its shape coordinates
  // (the refit's first island starts there): backlash reads the clearance off the distance at
  // which the stiffness rises again, so the search does not begin in the basin of a clearance a
  // third as wide.
  std::map<std::string, double> start{};

  bool Supported() const { return value >= threshold; }
  double Strength() const { return value / threshold; }  // ranks candidates
};

Evidence Detect(Effect effect, const Discrepancy& discrepancy);

}  // namespace isolab::diagnosis
