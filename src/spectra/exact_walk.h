// The exact recurrence of exact_linear_sdof.h walked over records, private to the spectra
// library: one record (a spectrum) or several of one step and length in lockstep (a pair's
// components, whose rotations are linear combinations of the two responses: rotd_spectrum.h).
#pragma once

#include <array>
#include <cstddef>
#include <numbers>

#include "isolab/integrators/excitation.h"
#include "isolab/spectra/exact_linear_sdof.h"

namespace isolab::spectra {

// Walks the recurrence under each of `grounds` from rest, calling visit(k, u) at every point k
// (time k h), u[n] the deformation under grounds[n]. The load at a sub-step is the record's
// linear interpolation, so the walk stays exact; each record's arithmetic is the same as when
// walked alone, so its deformations are too, to the bit. The records share grounds[0]'s step and
// length (checked by the callers).
template <std::size_t N, typename Visit>
void WalkExact(const std::array<const integrators::SampledHistory*, N>& grounds, double period,
               double zeta, int substeps, Visit&& visit) {
  const double omega = 2.0 * std::numbers::pi / period;
  const double h = grounds[0]->dt / substeps;
  const ExactStepCoefficients k = ExactStepCoefficients::For(omega, zeta, h);
  std::array<double, N> u{}, v{};
  visit(0L, u);
  const std::size_t samples = grounds[0]->values.size();
  long point = 0;
  for (std::size_t i = 0; i + 1 < samples; ++i) {
    std::array<double, N> p0, slope;
    for (std::size_t n = 0; n < N; ++n) {
      p0[n] = -grounds[n]->values[i];
      slope[n] = (-grounds[n]->values[i + 1] - p0[n]) / substeps;
    }
    for (int j = 0; j < substeps; ++j) {
      for (std::size_t n = 0; n < N; ++n) {
        const double pa = p0[n] + j * slope[n];
        const double pb =
            j + 1 == substeps ? -grounds[n]->values[i + 1] : p0[n] + (j + 1) * slope[n];
        const double u_next = k.a * u[n] + k.b * v[n] + k.c * pa + k.d * pb;
        v[n] = k.a_v * u[n] + k.b_v * v[n] + k.c_v * pa + k.d_v * pb;
        u[n] = u_next;
      }
      visit(++point, u);
    }
  }
}

}  // namespace isolab::spectra
