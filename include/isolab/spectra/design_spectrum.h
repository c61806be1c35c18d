// Code design spectra, the targets ground motions are scaled to: the pseudo-acceleration Sa(T)
// in g of a 5 %-damped linear oscillator (Eurocode 8 at any damping ratio), as the codes give it.
//
// ASCE 7-16 Sec. 11.4.6 (Fig. 11.4-1), on the MCE_R parameters, as its chapter 17 uses it for
// isolated structures (S_MS, S_M1 where Sec. 11.4.6 has S_DS, S_D1):
//   T_0 = 0.2 S_M1 / S_MS,  T_s = S_M1 / S_MS,
//   Sa = S_MS (0.4 + 0.6 T / T_0)   for T < T_0 (Eq. 11.4-5)
//      = S_MS                       for T_0 <= T <= T_s
//      = S_M1 / T                   for T_s < T <= T_L (Eq. 11.4-6)
//      = S_M1 T_L / T^2             for T > T_L (Eq. 11.4-7)
// so Sa(0) = 0.4 S_MS.
//
// Eurocode 8 (EN 1998-1:2004) Sec. 3.2.2.2, the horizontal elastic response spectrum, with
// a_g = gamma_I a_gR (Sec. 3.2.1(3)), eta = sqrt(10 / (5 + xi)) >= 0.55 (Eq. 3.6, xi in %) and
// S, T_B, T_C, T_D of the ground type from Table 3.2 (type 1) or Table 3.3 (type 2):
//   Se = a_g S [1 + T / T_B (2.5 eta - 1)]   for 0 <= T <= T_B (Eq. 3.2)
//      = a_g S eta 2.5                       for T_B <= T <= T_C (Eq. 3.3)
//      = a_g S eta 2.5 T_C / T               for T_C <= T <= T_D (Eq. 3.4)
//      = a_g S eta 2.5 T_C T_D / T^2         for T_D <= T <= 4 s (Eq. 3.5)
// The code defines Se up to 4 s (its Annex A, informative, shapes longer periods differently
// for the displacement spectrum): a longer period is refused, not extrapolated.
//
// A tabulated spectrum (a site-specific one, io/target_spectrum_file.h reads it) is linear in T
// between its points and refused outside them.
#pragma once

#include <string>
#include <variant>
#include <vector>

namespace isolab::spectra {

// The ASCE 7-16 MCE_R spectrum (Sec. 11.4.6 shape on Sec. 11.4.4's parameters).
struct Asce7Spectrum {
  double sms = 0.0;          // S_MS, 5 %-damped MCE_R Sa at short periods (g), > 0
  double sm1 = 0.0;          // S_M1, 5 %-damped MCE_R Sa at 1 s (g), > 0
  double long_period = 8.0;  // T_L (s), the long-period transition (chapter 22 maps), >= T_s
};

// EN 1998-1 ground types (Table 3.1): A rock ... E a shallow alluvium layer on rock.
enum class GroundType { kA, kB, kC, kD, kE };

// The EN 1998-1 Sec. 3.2.2.2 horizontal elastic spectrum.
struct Eurocode8Spectrum {
  double agr = 0.0;                    // a_gR, reference peak ground acceleration on rock (g), > 0
  GroundType ground = GroundType::kB;  // ground type (Table 3.1)
  int type = 1;                        // spectrum type: 1 (Table 3.2, Ms > 5.5) or 2 (Table 3.3)
  double importance = 1.0;             // gamma_I, importance factor (Sec. 4.2.5), > 0
  double damping_ratio = 0.05;         // xi as a ratio (0.05 = 5 %), in [0, 1)
};

// A spectrum given point by point: Sa linear in T between the points.
struct TabulatedSpectrum {
  std::vector<double> periods;  // (s) >= 0, strictly increasing, at least 2
  std::vector<double> sa;       // (g) >= 0, one per period
  std::string source;           // where it came from (a file name), for Describe
};

using TargetSpectrum = std::variant<Asce7Spectrum, Eurocode8Spectrum, TabulatedSpectrum>;

// Throws InvalidParameter naming the field: "sms", "sm1", "long_period" (<= 0, not finite, or
// below T_s), "agr", "type" (not 1 or 2), "importance", "damping_ratio", "periods[k]" (< 0, not
// finite, or not above periods[k-1]), "sa[k]" (< 0, not finite), "periods" (fewer than 2), "sa"
// (a size other than the periods').
void Validate(const TargetSpectrum& spectrum);

// The last period (s) EN 1998-1 3.2.2.2 defines its elastic spectrum at (beyond: Annex A's
// displacement spectrum, not modelled here).
inline constexpr double kEurocode8LastPeriod = 4.0;

// Sa (g) at `period` (s). Throws InvalidParameter ("period") for a period that is negative or not
// finite, above 4 s for Eurocode 8, or outside a table's [first, last] period; and as Validate.
double SpectralAcceleration(const TargetSpectrum& spectrum, double period);

// Sa (g) at T (s) continued where the spectrum stops: past Eurocode 8's 4 s or a table's last
// period at constant spectral displacement (Sa(T_end) (T_end / T)^2), below a table's first period
// at its first value; elsewhere SpectralAcceleration. For what may look past a design's range (an
// equivalent linear search, a matching over a wider band), never for the range itself.
double ContinuedSpectralAcceleration(const TargetSpectrum& spectrum, double period);

// Eurocode 8's damping correction eta = sqrt(10 / (5 + xi)) >= 0.55, xi in % (EN 1998-1 Eq. 3.6):
// 1 at 5 %.
double DampingCorrection(double damping_ratio);

// One line for reports:
//   "ASCE 7-16 MCE_R: S_MS 1.5 g, S_M1 0.9 g, T_L 8 s"
//   "Eurocode 8 type 1, ground B: a_g 0.3 g (gamma_I 1 x a_gR 0.3 g), 5 % damping"
//   "table from site.csv, 0.01 to 10 s"
std::string Describe(const TargetSpectrum& spectrum);

// Where the shape changes, so that a period grid can include them (s), increasing: T_0, T_s, T_L
// (ASCE 7), T_B, T_C, T_D (Eurocode 8), every period of a table.
std::vector<double> CornerPeriods(const TargetSpectrum& spectrum);

}  // namespace isolab::spectra
