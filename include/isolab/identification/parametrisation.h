// The model to identify, written as a separable least-squares problem. Every law's force is a
// sum of amplitude x basis force, where the amplitudes are stiffnesses that enter linearly and
// the basis forces depend only on shape coordinates (displacements and stiffness ratios):
//   thm1, bhm1:         k0 x [THM1 with k0 = 1]          shape: k1_ratio, k2_ratio, uy, uyh_gap
//                       (bhm1: k1_ratio, uy)             (k1 = k0 k1_ratio, k2 = k0 k2_ratio,
//                                                         uyh = uy + uyh_gap)
//   thm2:               (k0 - k1) x [elastoplastic, yield uy] + k1 x clamp(u, +-uyh)
//                       + k2 x (u - clamp(u, +-uyh))     shape: uy, uyh
//   bhm2:               (k0 - k1) x [elastoplastic, uy] + k1 x u          shape: uy
//   elastoplastic:      k0 x [elastoplastic, uy]          shape: uy
//   asymmetric_elastoplastic:  k0 x [its law, k0 = 1]     shape: uy_pos, uy_neg
//   backlash_elastoplastic:    k0 x [its law, k0 = 1]     shape: uy, gap
//   degrading_bhm2:     (k0 - k1) x phi [elastoplastic, uy] + k1 x phi u
//                                                         shape: uy, loss, slip_scale
//   trilinear_elastic:  k1 x clamp(u, +-uyh) + k2 x (u - clamp(u, +-uyh))  shape: uyh
//   linear_spring:      k x u;   dashpot: c x v           (no shape)
// So the search (CMA-ES) runs over the shape coordinates only, each mapped from [0, 1] to a range
// (log-scaled), and for each shape the amplitudes follow exactly from a linear least-squares
// solve with their signs constrained (fit.h): variable projection (Golub & Pereyra 1973). The
// laws' rules hold by construction: k1 < k0 through 0 < k1_ratio < 1 and k0 - k1 >= 0, k2 < k0
// through k2_ratio < 1, uyh > uy through uyh_gap > 0.
#pragma once

#include <Eigen/Core>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "isolab/hysteresis/law_parameters.h"
#include "isolab/hysteresis/parallel_assembly.h"
#include "isolab/identification/cyclic_data.h"

namespace isolab::identification {

struct CoordinateRange {
  double low = 0.0, high = 1.0;
  bool log = false;  // log-uniform between low and high (both > 0)
  double At(double x) const;
  double Inverse(double value) const;  // clamped to [0, 1]
};

struct ComponentSpec {
  std::string name;
  hysteresis::LawType type = hysteresis::LawType::kThm1;
  std::map<std::string, CoordinateRange> ranges;  // overrides, by shape coordinate name
  std::map<std::string, double> fixed;            // shape coordinates held at a value
  std::map<std::string, double> start;            // shape coordinates' starting values
};

// Scales of the measured data that set the default ranges.
struct DataScales {
  double displacement = 1.0;  // peak |u| (length)
  double force = 1.0;         // peak |F| (force)
  double velocity = 1.0;      // peak |v| (length/time)
};

// Shape coordinate names of a law type, in order. Throws std::invalid_argument for a law that
// cannot be identified (Bouc-Wen).
std::vector<std::string> CoordinateNames(hysteresis::LawType type);

// Fitted components as laws isolab reads. A part the fit gave no stiffness leaves a law whose
// rule fails (a BHM2 whose slider got k0 - k1 = 0 has k1 = k0); such a component is written as
// the law that remains (a BHM2 or degrading BHM2 without its slider is the linear spring k1, a
// THM2 without it the trilinear elastic spring k1, k2, uyh). Changes `types` and `mathematical`
// in place and returns one note per change.
std::vector<std::string> SimplifyComponents(const std::vector<std::string>& names,
                                            std::vector<hysteresis::LawType>* types,
                                            std::vector<std::vector<double>>* mathematical);

class ModelParametrisation {
 public:
  // Throws std::invalid_argument for an unknown coordinate name or an empty range.
  ModelParametrisation(std::vector<ComponentSpec> components, const DataScales& scales);

  // Free shape coordinates, over all components, and their "c1.uy"-style names.
  int dimension() const { return static_cast<int>(free_.size()); }
  std::vector<std::string> FreeNames() const;
  // Linear amplitudes, over all components, and which of them must be >= 0.
  int amplitude_count() const { return static_cast<int>(nonnegative_.size()); }
  const std::vector<bool>& nonnegative() const { return nonnegative_; }

  // Basis forces of every amplitude at shape point x (in [0, 1]^dimension()), one matrix per
  // test with one column per amplitude and one row per sample: the laws driven through the tests,
  // each from rest, or, for one specimen, in order with their state carried from test to test.
  // `threads` (>= 1) share the laws' runs, each into its own column: the result is the same for
  // any count. Every element is written: `bases` may hold an earlier call's matrices (a fit keeps
  // them from evaluation to evaluation), and no value of theirs may survive.
  void Basis(std::span<const double> x, std::span<const CyclicTestData> tests, bool one_specimen,
             std::vector<Eigen::MatrixXd>* bases, int threads = 1) const;

  // The component each free coordinate belongs to, and the first amplitude of component c
  // (first_amplitude(size) is amplitude_count()).
  int free_component(int k) const { return free_[k].component; }
  int first_amplitude(std::size_t c) const { return first_amplitude_[c]; }
  // "base.k0-k1"-style names of the amplitudes, in order.
  std::vector<std::string> AmplitudeNames() const;
  // Each free coordinate's range.
  const CoordinateRange& free_range(int k) const { return free_[k].range; }

  // Mathematical parameters (ParameterKeys order) of every component at x with `amplitudes`.
  std::vector<std::vector<double>> Mathematical(std::span<const double> x,
                                                const Eigen::VectorXd& amplitudes) const;
  hysteresis::ParallelAssembly Assembly(std::span<const double> x,
                                        const Eigen::VectorXd& amplitudes) const;
  // The point holding every component's starting values (the range's middle where none).
  std::vector<double> StartPoint() const;
  // Every component's shape coordinates at x, in CoordinateNames order (fixed ones included).
  std::vector<std::vector<double>> ShapeValues(std::span<const double> x) const;

  const std::vector<ComponentSpec>& components() const { return components_; }

 private:
  struct Slot {
    int component = 0;
    int coordinate = 0;  // index into CoordinateNames(type)
    CoordinateRange range;
  };
  std::vector<ComponentSpec> components_;
  std::vector<std::vector<double>> fixed_values_;  // per component, NaN where free
  std::vector<Slot> free_;
  std::vector<int> first_amplitude_;  // per component, and one past the last
  std::vector<bool> nonnegative_;
};

}  // namespace isolab::identification
