// The equivalent lateral force (ELF) procedure of ASCE 7-16 section 17.5: the isolation system as
// one linear spring of its effective stiffness and damping at the displacement it reaches, so the
// design displacement is a fixed point
//
//   D_M = g S_M1 T_M / (4 pi^2 B_M)                                     (ASCE 7-16 Eq. 17.5-1)
//   T_M = 2 pi sqrt(W / (k_M g))                                        (Eq. 17.5-2)
//   k_M = sum (|F+| + |F-|) / (2 D_M),  beta_M = sum E_M / (2 pi k_M D_M^2)   (Eqs. 17.8-3, -4)
//
// with B_M from beta_M by ASCE 7-16 Table 17.5-1 (DampingCoefficient). The effective properties
// are the bearings' own laws' (IsolationSystem::At): every isolator driven together along x through
// three cycles u = D sin(2 pi t / T) at the current T_M (only rate-dependent laws see T), read on
// the third cycle, where a bilinear loop is steady. Friction pendulums carry the weight the runs
// give them: their laws' `w`, or under a model's axial_load (docs/axial_load.md) their static
// share of the building's weight (the runs' N at rest), so that the ELF step and the runs agree.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "isolab/hysteresis/plan_vector.h"
#include "isolab/model/model_file.h"
#include "isolab/spectra/design_spectrum.h"

namespace isolab::design {

// ASCE 7-16 Table 17.5-1: B_M against the effective damping ratio beta (a fraction), linear
// between the table's points (2 %: 0.8, 5 %: 1.0, 10 %: 1.2, 20 %: 1.5, 30 %: 1.7, 40 %: 1.9,
// 50 %: 2.0) and constant beyond its ends.
double DampingCoefficient(double beta);

// The isolation system's effective properties at one displacement (model units).
struct EffectiveProperties {
  double displacement = 0.0;  // D (length)
  double stiffness = 0.0;     // k_eff = sum (|F+| + |F-|) / (2 D) (force/length)
  double dissipated = 0.0;    // sum E: energy per cycle (force*length)
  double damping = 0.0;       // beta_eff = E / (2 pi k_eff D^2)
};

// The sum over a model's isolators (an SDOF's spring, a layer's `count` bearings, a plan model's
// isolators), at displacement D and cycle period T (model units). Throws InputError for a model
// without isolation.
class IsolationSystem {
 public:
  explicit IsolationSystem(const model::ModelFile& model);
  EffectiveProperties At(double displacement, double period) const;
  // Each isolator's effective properties at D (in layout order: bearing_weights() names them),
  // and where it stands (zero in one direction).
  std::vector<EffectiveProperties> BearingProperties(double displacement, double period) const;
  const std::vector<hysteresis::Vec2>& positions() const { return positions_; }
  // Per isolator (layout order): its name, the weight its pendulum laws take (`w`, their sum) and
  // the weight it carries here and in the runs (its static share under axial_load, else `w`);
  // NaN for an isolator that is not a pendulum bearing.
  struct BearingWeight {
    std::string name;
    double law = 0.0, carried = 0.0;
  };
  const std::vector<BearingWeight>& bearing_weights() const { return bearing_weights_; }
  double weight() const { return weight_; }    // W: every level's mass x g (force)
  double gravity() const { return gravity_; }  // 1 g (length/time^2)

 private:
  // The distinct laws (one per bearing type), and each bearing as its law times its scale.
  std::vector<std::function<EffectiveProperties(double, double)>> laws_;
  struct Bearing {
    std::size_t law = 0;
    double scale = 1.0;
  };
  std::vector<Bearing> bearings_;
  std::vector<hysteresis::Vec2> positions_;
  std::vector<BearingWeight> bearing_weights_;
  double weight_ = 0.0, gravity_ = 0.0;
};

// D = demand(T, beta): the code's displacement for an effective period T and damping ratio beta
// (model units), e.g. Eq. 17.5-1's g S_M1 T / (4 pi^2 B_M(beta)).
using DisplacementDemand = std::function<double(double period, double damping)>;

// The code's demand on a target spectrum (model units): ASCE 7-16 Eq. 17.5-1, g S_M1 T / (4 pi^2
// B), on an ASCE 7 target; the spectral displacement Sa(T) g T^2 / (4 pi^2 B) on another, with Sa
// continued past the spectrum's end (spectra::ContinuedSpectralAcceleration). B is
// CodeDampingCoefficient's.
DisplacementDemand CodeDemand(const spectra::TargetSpectrum& target, const UnitSystem& units);

// B for an effective damping ratio beta: Eurocode 8's 1 / eta, eta = sqrt(10 / (5 + 100 beta)) >=
// 0.55 (EN 1998-1 3.2.2.2), on a Eurocode 8 target; ASCE 7-16 Table 17.5-1 on another.
double CodeDampingCoefficient(const spectra::TargetSpectrum& target, double beta);

struct ElfResult {
  EffectiveProperties at_design;  // k_M, beta_M at D_M
  double displacement = 0.0;      // D_M (length)
  double period = 0.0;            // T_M (time)
  double base_shear = 0.0;        // V_b = k_M D_M (Eq. 17.5-7) (force)
  int iterations = 0;
};

// The fixed point D = demand(T(D), beta(D)), by bisection on a sign change of demand - D found
// scanning down from 50 m to 10 um (`metre`: 1 m in the model's length unit), so the largest
// root, the conservative one; then the cycles' period is set to the T_M found and the search
// repeated until T_M settles to 1e-9 (once more for rate-independent laws). Throws
// std::runtime_error when no displacement in that range balances the demand.
ElfResult SolveElf(const IsolationSystem& system, const DisplacementDemand& demand, double metre);

// D_TM of ASCE 7-16 Eq. 17.5-3 for a building in plan, D_M [1 + (y / P_T^2) 12 e / (b^2 + d^2)],
// the larger of the two directions and not below 1.15 D_M (17.5.3.3): b x d the footprint, y the
// farthest bearing from the isolation's centre of rigidity (its bearings' k_eff at D_M) across the
// motion, e the structure's centre of mass from that centre plus the code's 5 % of the plan across
// the motion (whatever eccentricity a design's runs take), P_T by Eq. 17.5-4 (the bearings' radius
// of gyration about the centre of mass over the plan's, sqrt((b^2 + d^2) / 12)), taken as it comes
// (below 1, a torsionally flexible layout, it raises D_TM). In one direction, where the model has
// no plan, the code's floor 1.15 D_M.
double TotalDisplacement(const model::ModelFile& model, const IsolationSystem& system,
                         const ElfResult& elf);

}  // namespace isolab::design
