// A verdict on what a fitted model leaves: noise, or structure the model lacks. Read after the
// diagnosis's last step, so the report can say in its first lines whether anything is left
// unexplained, and where.
//
//  * Size: e^2 against the noise floor (discrepancy.h: a floor read where the signal has no
//    content, so it does not change with the sampling rate). Within noise_margin of it, the
//    residual is noise.
//  * Whiteness: the residual's correlation time (CorrelationTimes), in seconds and as the share
//    of samples that count as independent, n_eff / n: 1 for white noise.
//  * Dependence on the state of motion: the residual, in units of each test's noise, averaged
//    over cells of the state, test by test: direction of motion (v > 0, v < 0) x |u| / u_a
//    (four bands) x time since the last reversal (0-10, 10-25, 25-50, 50-100 % of the
//    half-cycle, and the stretches outside half-cycles). The share of the residual those cell means
//    explain, R^2, cross-validated between alternate cycles (the product of the two sets' cell
//    means), so that chance patterns of a correlated residual count for nothing. A residual that
//    follows the state is structure a model of the device could carry; one that does not is a
//    disturbance the motion does not drive, or noise in the device's own band that no floor
//    estimate can separate.
#pragma once

#include <string>
#include <vector>

#include "isolab/diagnosis/discrepancy.h"

namespace isolab::diagnosis {

// One table of the residual by cells: rows x columns of RMS and mean residual, in units of each
// test's noise (1 RMS: the model misses by no more than noise there), and the samples in each.
struct ResidualTable {
  std::string title;
  std::vector<std::string> rows, columns;
  std::vector<std::vector<double>> rms, mean;
  std::vector<std::vector<long>> samples;
};

struct ResidualVerdict {
  enum class Kind {
    kNoise,        // within noise_margin of the floor
    kStructured,   // above it, and it follows the state of motion
    kUnexplained,  // above it, and the state of motion does not explain it
  };
  Kind kind = Kind::kNoise;
  double e2 = 0.0, floor = 0.0, ratio = 0.0;  // ratio = e2 / floor
  double correlation_time = 0.0;              // seconds, over tests weighted by samples
  double whiteness = 1.0;                     // n_eff / n
  double state_share = 0.0;                   // R^2 of the state cells, cross-validated
  double state_share_noise = 0.0;     // cells / n_eff: what the plain, not cross-validated, R^2
                                      // of a state-free residual would be
  std::vector<ResidualTable> tables;  // direction x |u|; direction x time since reversal;
                                      // loading / unloading x |u|
  std::string headline;               // one sentence with the numbers
  std::vector<std::string> where;     // the cells that stand out, strongest first

  bool Structured() const { return kind != Kind::kNoise; }
};

struct VerdictOptions {
  double noise_margin = 1.2;  // e^2 within this factor of the floor is noise; >= 1
  // The state explains the residual when its cross-validated R^2 reaches this share; (0, 1).
  double state_share = 0.1;

  // Throws InvalidParameter naming the first field out of range.
  void Validate() const;
};

ResidualVerdict JudgeResidual(const Discrepancy& discrepancy, double e2, double noise_floor,
                              const VerdictOptions& options = {});

// "noise", "structured", "unexplained", as reports write them.
std::string_view VerdictName(ResidualVerdict::Kind kind);

}  // namespace isolab::diagnosis
