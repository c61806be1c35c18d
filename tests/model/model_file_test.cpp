#include "isolab/model/model_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "isolab/core/errors.h"

namespace isolab::model {
namespace {

std::string DataFile(const std::string& name) {
  return std::string(ISOLAB_TEST_DATA_DIR) + "/io/data/" + name;
}

// The message of the InputError that loading `name` throws.
std::string ErrorOf(const std::string& name) {
  try {
    LoadModelFile(DataFile(name));
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << name << " loaded without error";
  return {};
}

void ExpectError(const std::string& name, const std::string& location, const std::string& text) {
  const std::string message = ErrorOf(name);
  EXPECT_EQ(message.rfind(DataFile(name) + location, 0), 0u) << message;
  EXPECT_NE(message.find(text), std::string::npos) << message;
}

TEST(ModelFile, BadParameterNamesFileLineKeyValueAndRule) {
  ExpectError("bad_thm1_k1_above_k0.yaml",
              ":7:11:", "isolation.components[0].k1 = 1.2 (must be < k0 = 1)");
  ExpectError("bad_mechanical_softening.yaml",
              ":5:54:", "isolation.components[1].kh2 = -1.5 (ke + kh2 must be > 0, is -0.5)");
}

TEST(ModelFile, MalformedStructureIsLocated) {
  ExpectError("bad_unknown_key.yaml",
              ":5:29:", "isolation.components[1].kO: unknown key (did you mean 'k0'?)");
  ExpectError("bad_missing_key.yaml", ":4:7:",
              "isolation.components[0]: missing key 'uy' (is required; thm1 in mathematical form "
              "takes k0, k1, k2, uy, uyh)");
  ExpectError("bad_syntax.yaml", ":5:1:", "YAML syntax error");
  ExpectError("bad_mixed_forms.yaml", ":4:7:", "mixes mathematical (k0) and mechanical (kh1)");
  ExpectError("bad_law_type.yaml", ":4:23:", "'thm3' is not an element law; did you mean 'thm1'?");
  ExpectError("bad_not_a_number.yaml",
              ":4:42:", "isolation.components[0].k0: 'stiff' is not a number");
  ExpectError("bad_components_not_a_list.yaml", ":3:15:", "isolation.components: expected a list");
  ExpectError("bad_missing_units.yaml", ":1:1:", "missing key 'units'");
  ExpectError("bad_unit.yaml", ":1:16:", "units.force: 'kilonewton' is not a force unit");
  ExpectError("bad_duplicate_name.yaml", ":5:7:", "name 'a' is already used by component 0");
  ExpectError("bad_cyclic_steps.yaml",
              ":5:42:", "cyclic.steps_per_cycle = 30 (must be a multiple of 4, at least 4)");
  ExpectError("bad_empty.yaml", ":1:1:", "the file is empty");
  ExpectError("bad_nan_value.yaml",
              ":4:69:", "isolation.components[0].uyh: '.nan' is not a finite number");
  // NaN and infinity spelled without YAML's dot are not numbers.
  ExpectError("bad_plain_nan_value.yaml",
              ":4:42:", "isolation.components[0].k1: 'nan' is not a finite number");
  ExpectError("bad_plain_inf_value.yaml",
              ":4:69:", "isolation.components[0].uyh: 'inf' is not a finite number");
  ExpectError("bad_non_scalar_key.yaml", ":4:52:", "a key must be a plain name");
}

TEST(ModelFile, DuplicateKeysAreRefusedWithBothLocations) {
  // yaml-cpp kept both and every lookup found the first: k0 = 3 and the second structure (a tenth
  // of the mass) were silently ignored.
  ExpectError("bad_duplicate_key.yaml", ":4:52:",
              "isolation.components[0].k0: key given twice, first at " +
                  DataFile("bad_duplicate_key.yaml") + ":4:38 (YAML keeps only one");
  ExpectError(
      "bad_duplicate_section.yaml", ":8:1:",
      "structure: key given twice, first at " + DataFile("bad_duplicate_section.yaml") + ":2:1 ");
}

TEST(ModelFile, BadOutputSelectionIsLocated) {
  ExpectError("bad_output_every.yaml",
              ":9:31:", "output.every: 0 (expected a whole number of steps >= 1)");
  ExpectError("bad_output_quantity.yaml", ":9:37:",
              "output.quantities[1]: unknown quantity 'velocty'; did you mean 'velocity'?");
  ExpectError("bad_output_level.yaml",
              ":9:28:", "output.levels[2]: 4 (the structure's levels are 0 to 3, or roof)");
  ExpectError("bad_output_level_name.yaml", ":9:19:",
              "output.levels[0]: expected a level: 0 for the base, k for floor k, or roof");
  ExpectError("bad_output_key.yaml", ":9:10:", "output.evry: unknown key (did you mean 'every'?)");
  ExpectError("bad_output_file_empty.yaml",
              ":10:16:", "output.file: an empty name (give one, or leave the key out)");
  ExpectError("bad_output_summary_only.yaml",
              ":9:24:", "output.summary_only: expected true or false");
}

TEST(ModelFile, ReadsTheOutputSelection) {
  const ModelFile model = LoadModelFile(DataFile("output_selection.yaml"));
  EXPECT_EQ(model.output_file, "out.h5");
  EXPECT_EQ(model.output.every, 20);
  EXPECT_EQ(model.output.quantities, (std::vector<std::string>{"isolator", "energy"}));
  EXPECT_EQ(model.output.levels, (std::vector<int>{0, 2, kRoofLevel}));
  EXPECT_FALSE(model.output.summary_only);
  EXPECT_TRUE(model.output.Records("energy"));
  EXPECT_FALSE(model.output.Records("velocity"));
}

TEST(ModelFile, MissingFileIsAnInputError) {
  EXPECT_NE(ErrorOf("no_such_file.yaml").find("cannot open"), std::string::npos);
}

TEST(ModelFile, ReadsMechanicalFormAndUnits) {
  const ModelFile model = LoadModelFile(DataFile("good_mechanical.yaml"));
  EXPECT_EQ(model.description, "mechanical form");
  EXPECT_EQ(model.units.force(), "kN");
  EXPECT_EQ(model.units.length(), "mm");
  ASSERT_EQ(model.isolation.size(), 2u);
  const auto math =
      model.isolation.components()[0].parameters.Values(hysteresis::ParameterForm::kMathematical);
  EXPECT_NEAR(math[1], 0.2, 1e-15);
  EXPECT_NEAR(math[2], 0.45, 1e-15);
  EXPECT_NEAR(math[4], 120.0, 1e-12);
  EXPECT_EQ(model.isolation.components()[1].name, "damper");
  EXPECT_FALSE(model.cyclic.has_value());
}

// R = g T^2 / (4 pi^2): 4 s with g = 9806.65 mm/s^2 is 3974.5 mm, a pendulum period the
// law's own post-slip stiffness W/R then gives back: 2 pi sqrt(m / (W/R)) with m = W/g.
TEST(ModelFile, FrictionPendulumTakesItsPeriodInsteadOfItsRadius) {
  const ModelFile model = LoadModelFile(DataFile("good_pendulum_period.yaml"));
  const auto values =
      model.isolation.components()[0].parameters.Values(hysteresis::ParameterForm::kMechanical);
  const double radius = values[1];
  EXPECT_NEAR(radius, 9806.65 * 16.0 / (4.0 * std::numbers::pi * std::numbers::pi), 1e-9);
  const double mass = 1471.0 / 9806.65, post_slip_stiffness = 1471.0 / radius;
  EXPECT_NEAR(2.0 * std::numbers::pi * std::sqrt(mass / post_slip_stiffness), 4.0, 1e-12);
  ExpectError("bad_pendulum_radius_and_period.yaml", ":5:70:",
              "isolation.components[0].period: give the radius r or the period, not both");
}

// Errors in the uniform shorthand `stories: {count: ...}` were located at 1:1 (the story was read
// from a copy of its node, which has no marks): they are located at the key.
TEST(ModelFile, ErrorsInUniformStoriesAreLocatedAtTheKey) {
  const auto error_of = [](const std::string& stories) -> std::string {
    try {
      LoadModelText(
          "units: {force: kN, length: mm, time: s}\n"
          "structure:\n"
          "  type: shear_building\n"
          "  stories: " +
              stories + "\n",
          "building.yaml");
    } catch (const InputError& error) {
      return error.what();
    }
    return "";
  };
  EXPECT_EQ(error_of("{count: 5, mass: 25 t,\n            stiffness: -76 kN/mm}"),
            "building.yaml:5:24: structure.stories.stiffness: -76 (must be > 0)");
  EXPECT_EQ(error_of("{count: 5, stiffness: 76 kN/mm}"),
            "building.yaml:4:12: structure.stories: missing key 'mass'");
  EXPECT_EQ(error_of("{count: 5, mass: 25 t, stiffness: 76 kN/mm, heigth: 3 m}")
                .rfind("building.yaml:4:56: structure.stories.heigth: unknown key", 0),
            0u);
}

// A lead core's heat capacity 10^6 times too small (kN/mm^2 read as MPa twice over) heated and
// cooled the core within a fraction of a time step: Newmark's force kept the cold strength while
// its heat account took almost none, an energy balance error of 68 % with exit 0. Material data
// outside what solids and metals have are refused at the key, with the range in SI and in the
// model's units.
TEST(ModelFile, LeadCoreMaterialDataOutsideWhatMetalsHaveAreRefused) {
  const auto model = [](const std::string& heating) {
    return "units: {force: kN, length: mm, time: s}\n"
           "isolation:\n"
           "  components:\n"
           "    - {name: lrb, type: lead_rubber, qd: 88.26, kd: 0.3391, ku: 3.391,\n"
           "       lead_diameter: 106, lead_height: 127, " +
           heating + "}\n";
  };
  const auto error_of = [&](const std::string& heating) -> std::string {
    try {
      LoadModelText(model(heating), "lrb.yaml");
    } catch (const InputError& error) {
      return error.what();
    }
    return "";
  };
  // Lead: rho c = 11200 kg/m^3 x 130 J/(kg degC) = 1.456e6 J/(m^3 degC) = 1.456e-3 kN/mm^2/degC.
  EXPECT_EQ(error_of("lead_heat_capacity: 1.456e-3"), "");
  EXPECT_EQ(error_of("lead_heat_capacity: 1.456 N/mm^2"), "");
  EXPECT_EQ(error_of("lead_heat_capacity: 1.456e-9"),
            "lrb.yaml:5:66: isolation.components[0].lead_heat_capacity = 1.456e-09 kN/mm^2 per "
            "degC = 1.456 J/(m^3 degC) (must be 500000 to 5e+06 J/(m^3 degC), 0.0005 to 0.005 "
            "kN/mm^2 per degC; lead 1.456e6): a unit slip?");
  // Steel conducts 50 W/(m degC) = 0.05 kN/(s degC); 50 in kN/s is a thousand times that.
  const std::string steel =
      "lead_heat_capacity: 1.456e-3, steel_diffusivity: 14.1, "
      "shim_thickness: 27, steel_conductivity: ";
  EXPECT_EQ(error_of(steel + "0.05"), "");
  EXPECT_NE(
      error_of(steel + "50")
          .find("lrb.yaml:5:141: isolation.components[0].steel_conductivity = 50 kN/s per degC "
                "= 50000 W/(m degC) (must be 1 to 500 W/(m degC)"),
      std::string::npos)
      << error_of(steel + "50");
}

// A model whose isolation `file` names itself, or A -> B -> A, would recurse until
// the stack overflowed. The file that closes the cycle is refused at its `file` key, naming the
// chain; the same file spelled another way ("./a.yaml") is still the same file.
// An angle of H1 beyond a turn either way is a typo (at 1e308 degrees its cosine is NaN).
TEST(ModelFile, ARecordAngleBeyondATurnIsRefusedAtItsKey) {
  ExpectError("bad_angle.yaml",
              ":5:57:", "excitation.ground_motion.angle: 400 degrees (must be in [-360, 360])");
}

// A file that is not there is refused at the key that names it: the model's line, not only the
// missing path.
TEST(ModelFile, AnIsolationFileThatIsNotThereIsRefusedAtItsKey) {
  ExpectError("bad_include_missing.yaml", ":3:19:",
              "isolation.file: '" + DataFile("no_such_isolation.yaml") +
                  "' is not a file (No such file or directory)");
}

TEST(ModelFile, IsolationFilesThatIncludeEachOtherAreRefused) {
  ExpectError("bad_include_self.yaml", ":3:19:", "isolation.file: the files include each other: ");
  const std::string message = ErrorOf("bad_include_cycle_a.yaml");
  EXPECT_EQ(message.rfind(DataFile("bad_include_cycle_b.yaml") + ":3:19:", 0), 0u) << message;
  EXPECT_NE(
      message.find("bad_include_cycle_a.yaml -> " + DataFile("bad_include_cycle_b.yaml") + " -> "),
      std::string::npos)
      << message;
}

TEST(ModelFile, ADirectoryIsAnInputErrorNotACrash) {
  // The fuzz target for study files found it: a directory opened as a stream and its first read
  // threw ios_base::failure, reported as "internal error" with exit code 1.
  ExpectError("bad_include_directory.yaml",
              ":3:9:", "isolation.file: '" + DataFile(".") + "' is not a file");
  EXPECT_THROW(LoadModelFile(std::string(ISOLAB_TEST_DATA_DIR) + "/io/data"), InputError);
}

}  // namespace
}  // namespace isolab::model
