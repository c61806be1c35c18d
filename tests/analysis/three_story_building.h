// A three-story shear building on an isolation layer given as YAML, in kN, mm, s: the model of
// the analysis tests of fitted models (parameter draws) and of the building tests' synthetic
// measurements (building/synthetic_building.h).
#pragma once

#include <string>

#include "isolab/model/model_file.h"

namespace isolab::testing {

inline std::string BuildingText(const std::string& isolation, double story_stiffness = 60.0,
                                double damping = 0.04) {
  return "units: {force: kN, length: mm, time: s}\n"
         "isolation: {components: [" +
         isolation +
         "]}\n"
         "structure:\n"
         "  type: shear_building\n"
         "  base_mass: 60 t\n"
         "  stories: {count: 3, mass: 50 t, stiffness: " +
         std::to_string(story_stiffness) +
         "}\n"
         "  damping: {type: modal, ratios: [" +
         std::to_string(damping) + "]}\n";
}

inline constexpr const char* kBilinear = "{name: iso, type: bhm2, k0: 12.0, k1: 1.5, uy: 6.0}";

inline model::ModelFile Model(const std::string& text) {
  return model::LoadModelText(text, "building.yaml");
}

}  // namespace isolab::testing
