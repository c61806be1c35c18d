// Reference data of Markou & Manolis (2016) for tests, typed in from the paper (Tables 9 and 10)
// and its closed forms (shared/design/models.md), independent of isolab's own code.
#pragma once

#include <cmath>

namespace isolab::testing {

// The ten shear-test amplitudes (mm) of the paper's HDRB identification.
inline constexpr double kTestAmplitudes[] = {5, 30, 50, 70, 100, 120, 140, 160, 180, 200};

// Table 9, nine THM1 components: k0, k1, k2 (kN/mm), uy, uyh (mm). k0 >> k1, k2 is written 1e6
// as in models/paper/table9_thm1_system.yaml; NaN marks the meaningless uyh of k1 = k2 = 0.
inline constexpr double kTable9[9][5] = {
    {1e6, 0.283532, 0.489882, 0, 64.809},
    {1e6, 0.000282, 0.905635, 0, 136.491},
    {1e6, 0.000246, 0.877611, 0, 108.657},
    {0.863754, 0.402485, -0.792654, 7.146, 125.542},
    {0.157047, 0.000238, -0.285050, 43.938, 151.692},
    {0.172839, 0.000547, -0.271989, 18.760, 80.117},
    {0.056183, 0.044945, -0.006864, 3.331, 21.299},
    {3.225241, 0, 0, 0.597, NAN},
    {67.445070, 0, 0, 0.041, NAN},
};

// Table 10, six THM2 components: k0, k1, uy (k2 and uyh do not change THM2's dissipation).
inline constexpr double kTable10[6][3] = {
    {3.316369, 0.097634, 0.604},   {67.826800, 0.034459, 0.041}, {0.583996, 0.082570, 7.945},
    {0.360200, 0.159367, 128.456}, {0.315248, 0.115504, 20.728}, {0.142166, 0.010595, 43.731},
};

// Steady-state energy per cycle of one THM1 at amplitude ua: W_d = 4 fs u_ha with
// u_ha = (ke ua - fs)/(ke + kh1) while u_ha <= uc, else (ke ua - fs + uc (kh2 - kh1))/(ke + kh2);
// zero when ua <= uy.
inline double Thm1CycleEnergy(const double (&p)[5], double ua) {
  const double k0 = p[0], k1 = p[1], k2 = p[2], uy = p[3], uyh = p[4];
  if (uy == 0.0 || ua <= uy) return 0.0;
  const double ke = k0, fs = k0 * uy;
  const double kh1 = k0 * k1 / (k0 - k1), kh2 = k0 * k2 / (k0 - k2);
  double u_ha = (ke * ua - fs) / (ke + kh1);
  if (k1 != k2) {
    const double uc = (uyh - uy) * (k0 - k1) / k0;
    if (u_ha > uc) u_ha = (ke * ua - fs + uc * (kh2 - kh1)) / (ke + kh2);
  }
  return 4.0 * fs * u_ha;
}

// Steady-state energy per cycle of one THM2: 4 fs (ua - uy) with fs = (k0 - k1) uy.
inline double Thm2CycleEnergy(const double (&p)[3], double ua) {
  const double k0 = p[0], k1 = p[1], uy = p[2];
  return ua > uy ? 4.0 * (k0 - k1) * uy * (ua - uy) : 0.0;
}

}  // namespace isolab::testing
