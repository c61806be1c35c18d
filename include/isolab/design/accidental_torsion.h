// Accidental torsion as the codes ask it of a response-history analysis of a building in plan
// (ASCE 7-16 sections 12.8.4.2 and 17.6.2.2; Eurocode 8 part 1 section 4.3.2): every floor's centre
// of mass moved from its nominal place by an accidental eccentricity of `ratio` (5 %) of the
// footprint's extent perpendicular to the motion, each way. A pair of records drives both
// directions at once, so the shift has an x part (for the motion along y) and a y part (for the
// motion along x), and the four combinations of their signs are the cases a design runs; the
// worst bearing of the worst case gives the total displacement D_TM. The floors' rotational
// inertia about their own centre of mass is kept (the mass moves, it is not redistributed).
#pragma once

#include <string>
#include <vector>

#include "isolab/hysteresis/plan_vector.h"
#include "isolab/model/model_file.h"

namespace isolab::design {

struct EccentricityCase {
  std::string name;        // "ex+ey+", "ex+ey-", "ex-ey+", "ex-ey-"
  hysteresis::Vec2 shift;  // of every centre of mass (length)
};

// The four cases (+-ratio L_x, +-ratio L_y) of a plan model's footprint L_x x L_y. Throws
// InputError naming `key` for a model not in plan (one direction has no plan to shift in) and for
// a ratio outside (0, 0.5).
std::vector<EccentricityCase> AccidentalEccentricities(const model::ModelFile& model, double ratio,
                                                       const std::string& key);

// The model with the base's and every story's floor centre of mass moved by `shift`.
model::ModelFile WithCentresOfMassShifted(model::ModelFile model, hysteresis::Vec2 shift);

}  // namespace isolab::design
