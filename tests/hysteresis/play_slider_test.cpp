// The play sliders (play_slider.h) against their closed forms, on the sinusoidal protocol of
// cyclic_test.h:
//  * asymmetric_elastoplastic between -A and +A slips at +fs_pos and -fs_neg; each reversal
//    crosses fs_pos + fs_neg elastically over (fs_pos + fs_neg) / k, so the steady loop is a
//    parallelogram of area W = (fs_pos + fs_neg) (2 A - (fs_pos + fs_neg) / k), and its slip
//    branches are offset from zero by (fs_pos - fs_neg) / 2, the constant a symmetric law cannot
//    make;
//  * backlash_elastoplastic unloads over u_y, crosses the clearance g at zero force, reloads
//    over u_y and slips: W = 4 fs (A - u_y - g / 2), and the force is zero exactly along a
//    stretch of width g after every reversal.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "isolab/core/errors.h"
#include "isolab/hysteresis/cyclic_test.h"
#include "isolab/hysteresis/parallel_assembly.h"

namespace isolab::hysteresis {
namespace {

CyclicResult Loop(LawType type, std::vector<double> mathematical, double amplitude) {
  return RunCyclicTest(SingleLaw(type, std::move(mathematical)),
                       CyclicProtocol{amplitude, 2.0, 3, 4000});
}

TEST(PlaySlider, AsymmetricLoopAreaAndOffsetAreTheClosedForms) {
  const double k = 2.0, uy_pos = 3.0, uy_neg = 7.0, amplitude = 40.0;
  const double fs_pos = k * uy_pos, fs_neg = k * uy_neg;
  const CyclicResult result =
      Loop(LawType::kAsymmetricElastoplastic, {k, uy_pos, uy_neg}, amplitude);
  const double area = (fs_pos + fs_neg) * (2 * amplitude - (fs_pos + fs_neg) / k);
  // The dissipation is bookkept from the slider's travel, exact for any increment.
  EXPECT_NEAR(result.cycles[1].dissipated, area, 1e-9 * area);
  EXPECT_NEAR(result.cycles[2].dissipated, area, 1e-9 * area);
  // Slipping at the peaks: +fs_pos at +A, -fs_neg at -A.
  const auto& loop = result.loop;
  const std::size_t quarter = 1000, three_quarters = 3000;
  EXPECT_NEAR(loop.force[4000 + quarter], fs_pos, 1e-12 * fs_pos);
  EXPECT_NEAR(loop.force[4000 + three_quarters], -fs_neg, 1e-12 * fs_neg);
  // The mean force over the steady cycles is the offset (fs_pos - fs_neg) / 2 weighted by the
  // slip branches' share of the cycle; its sign is the weaker direction's, here negative.
  double mean = 0.0;
  for (std::size_t k_sample = 4000; k_sample < 8000; ++k_sample) mean += loop.force[k_sample];
  EXPECT_LT(mean / 4000, 0.0);
}

TEST(PlaySlider, BacklashLoopAreaAndZeroForcePlateauAreTheClosedForms) {
  const double k = 2.0, uy = 3.0, gap = 10.0, amplitude = 40.0;
  const double fs = k * uy;
  const CyclicResult result = Loop(LawType::kBacklashElastoplastic, {k, uy, gap}, amplitude);
  const double area = 4 * fs * (amplitude - uy - gap / 2);
  EXPECT_NEAR(result.cycles[1].dissipated, area, 1e-9 * area);
  EXPECT_NEAR(result.cycles[2].dissipated, area, 1e-9 * area);
  // After the reversal at +A (sample 1000 of the second cycle) the force falls over u_y, then is
  // exactly zero while the displacement crosses the clearance, from A - u_y to A - u_y - g.
  const auto& loop = result.loop;
  double plateau_high = -INFINITY, plateau_low = INFINITY;
  for (std::size_t s = 5000; s <= 7000; ++s) {
    if (loop.force[s] == 0.0) {
      plateau_high = std::max(plateau_high, loop.displacement[s]);
      plateau_low = std::min(plateau_low, loop.displacement[s]);
    }
  }
  // Sampled: the zero stretch's ends lie within one step (2 pi A / 4000) of the exact ones.
  const double step = 2 * M_PI * amplitude / 4000;
  EXPECT_NEAR(plateau_high, amplitude - uy, step);
  EXPECT_NEAR(plateau_low, amplitude - uy - gap, step);
  // Without clearance it is the elastoplastic element exactly.
  const CyclicResult plain = Loop(LawType::kBacklashElastoplastic, {k, uy, 0.0}, amplitude);
  const CyclicResult elastoplastic = Loop(LawType::kElastoplastic, {k, uy}, amplitude);
  for (std::size_t s = 0; s < plain.loop.force.size(); s += 97) {
    EXPECT_NEAR(plain.loop.force[s], elastoplastic.loop.force[s], 1e-12 * fs) << s;
  }
}

TEST(PlaySlider, MechanicalAndMathematicalFormsAgreeAndRulesNameTheKey) {
  const auto math = LawParameters::Make(LawType::kBacklashElastoplastic,
                                        ParameterForm::kMathematical, std::vector{2.0, 3.0, 10.0});
  EXPECT_EQ(math.Values(ParameterForm::kMechanical), (std::vector{2.0, 6.0, 10.0}));
  const auto mech = LawParameters::Make(LawType::kAsymmetricElastoplastic,
                                        ParameterForm::kMechanical, std::vector{2.0, 6.0, 14.0});
  EXPECT_EQ(mech.Values(ParameterForm::kMathematical), (std::vector{2.0, 3.0, 7.0}));
  try {
    LawParameters::Make(LawType::kBacklashElastoplastic, ParameterForm::kMathematical,
                        std::vector{2.0, 3.0, -1.0});
    ADD_FAILURE() << "a negative gap was accepted";
  } catch (const InvalidParameter& error) {
    EXPECT_EQ(error.violation().key, "gap");
  }
  EXPECT_EQ(LawTypeFromName("asymmetric_elastoplastic"), LawType::kAsymmetricElastoplastic);
  EXPECT_EQ(LawTypeFromName("backlash_elastoplastic"), LawType::kBacklashElastoplastic);
}

}  // namespace
}  // namespace isolab::hysteresis
