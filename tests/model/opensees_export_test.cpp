// The OpenSees export (model/opensees_export.h): each law's element takes the numbers that make
// its loop the law's, checked through the element's own definition (OpenSees' manual) against
// closed forms written here: the bilinear's yield and secant, an HDR bearing's effective stiffness
// and damping at its design strain, the pendulums' radii, friction and weight, and the bound
// models' factors combined as ASCE 7-16 17.2.8.4 combines them. Against OpenSees itself the
// export runs in scripts/opensees_export_check.py (OpenSees is not a test dependency).
#include "isolab/model/opensees_export.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numbers>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli/run_isolab.h"
#include "isolab/core/errors.h"
#include "isolab/model/bounds.h"
#include "isolab/model/model_file.h"
#include "own_test_file.h"

namespace isolab::model {
namespace {

std::string OneDirection(const std::string& components, const std::string& extra = "") {
  return "units: {force: kN, length: mm, time: s}\nisolation:\n" + extra + "  components: [" +
         components + "]\n";
}

std::string Export(const std::string& text) {
  const OpenSeesExport exported = ExportToOpenSees(LoadModelText(text, "m.yaml"), "test");
  EXPECT_EQ(exported.refused, "");
  return exported.tcl;
}

std::string Refusal(const std::string& text) {
  const OpenSeesExport exported = ExportToOpenSees(LoadModelText(text, "m.yaml"), "test");
  EXPECT_EQ(exported.tcl, "");
  return exported.refused;
}

// The words of the first line that starts with `start` (after indentation).
std::vector<std::string> Words(const std::string& tcl, const std::string& start) {
  std::istringstream lines(tcl);
  for (std::string line; std::getline(lines, line);) {
    const std::size_t first = line.find_first_not_of(' ');
    if (first == std::string::npos || line.compare(first, start.size(), start) != 0) continue;
    std::istringstream in(line.substr(first));
    std::vector<std::string> words;
    for (std::string w; in >> w;) words.push_back(w);
    return words;
  }
  ADD_FAILURE() << "no line starting '" << start << "' in\n" << tcl;
  return std::vector<std::string>(32, "nan");
}

double At(const std::vector<std::string>& words, std::size_t i) { return std::stod(words.at(i)); }

// elastomericBearingPlasticity $e $iNode $jNode kInit qd alpha1 alpha2 mu: a spring alpha1 kInit
// in parallel with an elastic-perfectly-plastic one of stiffness (1 - alpha1) kInit and strength
// qd, the manual's bilinear.
struct Bilinear {
  double k_init, qd, alpha1;
  double Yield() const { return qd / ((1 - alpha1) * k_init); }
  double Force(double d) const { return alpha1 * k_init * d + qd; }  // on the backbone, d >= Yield
};

Bilinear ElastomericOf(const std::string& tcl) {
  const std::vector<std::string> w = Words(tcl, "element elastomericBearingPlasticity");
  EXPECT_EQ(w.at(8), "0");  // alpha2: no nonlinear hardening
  return {At(w, 5), At(w, 6), At(w, 7)};
}

TEST(OpenSeesExport, ALeadRubberBearingIsItsBilinearLoop) {
  const Bilinear b =
      ElastomericOf(Export(OneDirection("{name: lrb, type: lead_rubber, qd: 95, kd: 0.6, ku: 6}")));
  EXPECT_DOUBLE_EQ(b.k_init, 6.0);
  EXPECT_DOUBLE_EQ(b.qd, 95.0);
  EXPECT_NEAR(b.Force(300.0), 0.6 * 300 + 95, 1e-12);  // Kd D + Qd
  EXPECT_NEAR(b.Yield(), 95 / (6 - 0.6), 1e-12);       // Dy = Qd / (Ku - Kd)
}

TEST(OpenSeesExport, AnHdrBearingHasItsDesignStiffnessAndDampingAtItsDesignStrain) {
  // G 0.4 MPa, A 231875 mm^2, T_r 100 mm, 8.9 % at 150 % strain, yielding at 10 % (the default).
  const Bilinear b = ElastomericOf(Export(OneDirection(
      "{name: hdr, type: hdr_bearing, g: 4.0e-4, area: 231875, tr: 100, damping: 0.089, "
      "strain: 1.5}")));
  const double k_eff = 4.0e-4 * 231875 / 100, d = 150.0;
  EXPECT_NEAR(b.Force(d) / d, k_eff, 1e-12 * k_eff);
  EXPECT_NEAR(b.Yield(), 10.0, 1e-9);
  const double loop = 4 * b.qd * (d - b.Yield());  // the bilinear loop's area
  EXPECT_NEAR(loop / (2 * std::numbers::pi * k_eff * d * d), 0.089, 1e-12);
}

TEST(OpenSeesExport, BilinearLawsAndSpringsInParallelAreOneBearing) {
  const std::string tcl = Export(OneDirection(
      "{name: k, type: linear_spring, k: 0.5}, {name: s, type: bhm2, ke: 4.0, kh: 0.2, fs: 60}, "
      "{name: e, type: elastoplastic, k0: 2, uy: 10}",
      "  count: 4\n  name: b\n"));
  const std::vector<std::string> spring = Words(tcl, "set k [isolab_tag]; uniaxialMaterial");
  EXPECT_EQ(spring.back(), "0.5");
  const Bilinear bhm2 = ElastomericOf(tcl);
  EXPECT_DOUBLE_EQ(bhm2.k_init, 4.0);
  EXPECT_DOUBLE_EQ(bhm2.qd, 60.0);
  EXPECT_NEAR(bhm2.Force(100) - bhm2.Force(50), 0.2 * 50, 1e-12);  // kh after yield
  // The elastoplastic law: no hardening, strength k0 uy.
  const std::string after = tcl.substr(tcl.find("# e: elastoplastic"));
  const Bilinear plastic = ElastomericOf(after);
  EXPECT_DOUBLE_EQ(plastic.qd, 20.0);
  EXPECT_DOUBLE_EQ(plastic.alpha1, 0.0);
  // One procedure, four bearings of a one-direction layer, at the origin, carrying no weight.
  for (const char* site : {"{b_1 0 0 0 isolab_type_k_s_e}", "{b_4 0 0 0 isolab_type_k_s_e}"}) {
    EXPECT_NE(tcl.find(site), std::string::npos) << tcl;
  }
  EXPECT_EQ(tcl.find("{b_5 "), std::string::npos);
}

TEST(OpenSeesExport, FrictionPendulumsTakeTheirRadiusFrictionAndWeight) {
  const std::string plan =
      "units: {force: kN, length: mm, time: s}\n"
      "plan:\n  footprint: [[0, 0], [20000, 20000]]\n  base: {mass: 300 t}\n  isolators:\n"
      "    - {name: fp, positions: [[0, 20000]], components: [{name: fp, type: "
      "friction_pendulum, w: 1471, period: 4 s, uy: 0.5, mu: 0.05}]}\n"
      "    - {name: fpv, positions: [[20000, 0], [5000, 7000]], components: [{name: fpv, type: "
      "friction_pendulum, w: 1000, r: 2235, uy: 0.5, mu_slow: 0.03, mu_fast: 0.06, a: 0.02}]}\n";
  const std::string tcl = Export(plan);
  // R = g T^2 / (4 pi^2) with g = 9806.65 mm/s^2; the pre-slide stiffness kInit = mu W / uy.
  const double r = 9806.65 * 16 / (4 * std::numbers::pi * std::numbers::pi);
  const std::vector<std::string> fp = Words(tcl, "element singleFPBearing");
  EXPECT_NEAR(At(fp, 6), r, 1e-12 * r);
  EXPECT_NEAR(At(fp, 7), 0.05 * 1471 / 0.5, 1e-12);
  EXPECT_EQ(Words(tcl, "set f [isolab_tag]; frictionModel Coulomb").back(), "0.05");
  const std::vector<std::string> velocity =
      Words(tcl, "set f [isolab_tag]; frictionModel VelDependent");
  EXPECT_EQ(std::vector<std::string>(velocity.end() - 3, velocity.end()),
            (std::vector<std::string>{"0.03", "0.06", "0.02"}));
  const std::vector<std::string> fpv =
      Words(tcl.substr(tcl.find("proc isolab_type_fpv")), "element singleFPBearing");
  EXPECT_NEAR(At(fpv, 7), 0.03 * 1000 / 0.5, 1e-12);  // at mu_slow
  for (const char* site :
       {"{fp_1 0 20000 1471 isolab_type_fp}", "{fpv_1 20000 0 1000 isolab_type_fpv}",
        "{fpv_2 5000 7000 1000 isolab_type_fpv}"}) {
    EXPECT_NE(tcl.find(site), std::string::npos) << tcl;
  }
}

TEST(OpenSeesExport, ATriplePendulumMapsAsDocsBearingsTabulates) {
  const std::string tfp =
      "{name: tfp, type: triple_friction_pendulum, w: 2092, uy: 0.5, r1: 2235, r2: 305, r3: 305, "
      "r4: 2000, mu1: 0.05, mu2: 0.02, mu3: 0.02, mu4: 0.09, d1: 380, d2: 60, d3: 60, d4: 340}";
  const std::string tcl = Export(OneDirection(tfp));
  // ... $f1 $f2 $f3 $p $r $r $r L1 L2 L3 d1 d2 d3 W uy kvt minFv tol
  const std::vector<std::string> w = Words(tcl, "element TripleFrictionPendulum");
  const std::vector<double> expected = {305, 2235, 2000, 60, 380, 340, 2092, 0.5};
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_DOUBLE_EQ(At(w, 12 + i), expected[i]);
  EXPECT_EQ(Words(tcl, "set f1 [isolab_tag]").back(), "0.02");  // inner
  EXPECT_EQ(Words(tcl, "set f2 [isolab_tag]").back(), "0.05");  // the outer that slides first
  EXPECT_EQ(Words(tcl, "set f3 [isolab_tag]").back(), "0.09");

  std::string unlike = tfp;
  unlike.replace(unlike.find("r3: 305"), 7, "r3: 300");
  const std::string refused = Refusal(OneDirection(unlike));
  EXPECT_NE(refused.find("component 'tfp': triple_friction_pendulum with r2 = 305 and r3 = 300"),
            std::string::npos)
      << refused;
}

TEST(OpenSeesExport, ALawWithoutAnOpenSeesElementIsRefusedByName) {
  const std::vector<std::pair<std::string, std::string>> refused = {
      {"{name: c, type: thm1, k0: 3.4, k1: 0.34, k2: 1.0, uy: 28.9, uyh: 250}",
       "component 'c': thm1 has no OpenSees element"},
      {"{name: c, type: dashpot, c: 2}", "component 'c': dashpot has no OpenSees element"},
      {"{name: lrb, type: lead_rubber, qd: 88.26, kd: 0.3391, ku: 3.391, lead_diameter: 106, "
       "lead_height: 127, lead_heat_capacity: 1.456e-3}",
       "component 'lrb': lead_rubber with the lead core's heating"},
      {"{name: d, type: double_friction_pendulum, w: 1250, r1: 1500, r2: 1500, mu1: 0.04, "
       "mu2: 0.07, d1: 300, d2: 300, uy: 0.5}",
       "component 'd': double_friction_pendulum has no OpenSees element"},
  };
  for (const auto& [component, message] : refused) {
    const std::string why =
        Refusal(OneDirection("{name: k, type: linear_spring, k: 1}, " + component));
    EXPECT_NE(why.find("isolation: bearing 'isolation', " + message), std::string::npos) << why;
  }
  // A pendulum shares its axial force with nothing in OpenSees: alone in its isolator or refused.
  const std::string shared = Refusal(OneDirection(
      "{name: k, type: linear_spring, k: 1}, {name: fp, type: friction_pendulum, w: 1471, r: "
      "4338, uy: 0.5, mu: 0.05}"));
  EXPECT_NE(shared.find("component 'fp': a friction_pendulum with other components in parallel"),
            std::string::npos)
      << shared;
}

TEST(OpenSeesExport, TheBoundsCarryTheirFactorsCombinedAsAsce7Does) {
  const ModelFile model = LoadModelText(
      OneDirection("{name: lrb, type: lead_rubber, qd: 95, kd: 0.6, ku: 6}",
                   "  modification:\n    lrb:\n"
                   "      qd: {testing: [0.9, 1.2], ageing: [1.0, 1.1], specification: [0.85, "
                   "1.15]}\n"
                   "      kd: {testing: [0.95, 1.1], ageing: [1.0, 1.1], specification: [0.9, "
                   "1.1]}\n"),
      "m.yaml");
  const BoundModels bounds = MakeBoundModels(model);
  ASSERT_EQ(bounds.models.size(), 3u);
  // lambda_max = (1 + 0.75 (ageing - 1)) testing specification; lambda_min likewise below 1.
  const double qd_max = (1 + 0.75 * 0.1) * 1.2 * 1.15, kd_max = (1 + 0.75 * 0.1) * 1.1 * 1.1;
  const double qd_min = 0.9 * 0.85, kd_min = 0.95 * 0.9;
  const double expected[3][2] = {
      {95, 0.6}, {95 * qd_max, 0.6 * kd_max}, {95 * qd_min, 0.6 * kd_min}};
  for (std::size_t i = 0; i < 3; ++i) {
    const Bilinear b = ElastomericOf(Export(bounds.models[i].text));
    EXPECT_NEAR(b.qd, expected[i][0], 1e-12 * expected[i][0]) << bounds.models[i].bound;
    EXPECT_NEAR(b.alpha1 * b.k_init, expected[i][1], 1e-12) << bounds.models[i].bound;
    EXPECT_DOUBLE_EQ(b.k_init, 6.0);
  }
}

TEST(OpenSeesExport, TypesWithTheSameNamesButOtherValuesGetTheirOwnProcedure) {
  // Components b_2, then b twice with other values: three procedures, none taken twice.
  const std::string tcl = Export(
      "units: {force: kN, length: mm, time: s}\n"
      "plan:\n  footprint: [[0, 0], [20000, 20000]]\n  base: {mass: 300 t}\n  isolators:\n"
      "    - {name: d, position: [9, 0], components: [{name: b_2, type: bhm2, k0: 5, k1: 0.3, "
      "uy: 20}]}\n"
      "    - {name: a, positions: [[0, 0], [1, 0]], components: [{name: b, type: bhm2, k0: 3, "
      "k1: 0.3, uy: 20}]}\n"
      "    - {name: c, position: [5, 0], components: [{name: b, type: bhm2, k0: 4, k1: 0.3, "
      "uy: 20}]}\n");
  for (const char* site :
       {"{d 9 0 0 isolab_type_b_2}", "{a_2 1 0 0 isolab_type_b}", "{c 5 0 0 isolab_type_b_3}"}) {
    EXPECT_NE(tcl.find(site), std::string::npos) << tcl;
  }
  const auto k_init = [&](const std::string& procedure) {
    return At(Words(tcl.substr(tcl.find("proc " + procedure + " ")),
                    "element elastomericBearingPlasticity"),
              5);
  };
  EXPECT_EQ(k_init("isolab_type_b_2"), 5.0);
  EXPECT_EQ(k_init("isolab_type_b"), 3.0);
  EXPECT_EQ(k_init("isolab_type_b_3"), 4.0);
}

// The file as Tcl runs it (/usr/bin/tclsh, OpenSees' own interpreter language), with OpenSees'
// commands stubbed to print what they are given: every site's procedure runs, each element gets
// a tag of its own, and the materials and friction models it names exist. Components named as
// the file's own procedures (bearing, tag) do not clash with them.
TEST(OpenSeesExport, TheFileRunsAsTclAndPlacesEverySite) {
  const std::string tcl = Export(
      "units: {force: kN, length: mm, time: s}\n"
      "plan:\n  footprint: [[0, 0], [20000, 20000]]\n  base: {mass: 300 t}\n  isolators:\n"
      "    - {name: a, positions: [[0, 0], [1, 0]], components: [{name: bearing, type: bhm2, "
      "k0: 3, k1: 0.3, uy: 20}, {name: tag, type: linear_spring, k: 0.5}]}\n"
      "    - {name: fp, position: [5, 0], components: [{name: fp, type: friction_pendulum, w: "
      "1000, r: 2235, uy: 0.5, mu_slow: 0.03, mu_fast: 0.06, a: 0.02}]}\n"
      "    - {name: tfp, position: [7, 0], components: [{name: tfp, type: "
      "triple_friction_pendulum, w: 2092, uy: 0.5, r1: 2235, r2: 305, r3: 305, r4: 2235, mu1: "
      "0.05, mu2: 0.02, mu3: 0.02, mu4: 0.09, d1: 380, d2: 60, d3: 60, d4: 380}]}\n");
  const std::filesystem::path folder = testing::FreshTestDirectory();
  std::ofstream(folder / "bearings.tcl") << tcl;
  std::ofstream(folder / "driver.tcl")
      << "set defined {}\n"
         "proc uniaxialMaterial {type tag args} { global defined; lappend defined $tag }\n"
         "proc frictionModel {type tag args} { global defined; lappend defined $tag }\n"
         "proc element {type tag i j args} {\n"
         "  global defined\n"
         "  foreach word $args { if {[string is integer -strict $word] && $word >= 900001 &&\n"
         "    [lsearch $defined $word] < 0} { error \"element $tag names $word, not defined\" } }\n"
         "  puts \"element $type $tag $i $j\"\n"
         "}\n"
         "source bearings.tcl\n"
         "set node 0\n"
         "foreach site $isolab_sites {\n"
         "  puts \"site [lindex $site 0] -> [isolab_bearing [lindex $site 0] [incr node] [incr "
         "node]]\"\n"
         "}\n";
  const testing::Outcome run =
      testing::RunShell("cd " + folder.string() + " && /usr/bin/tclsh driver.tcl", true);
  ASSERT_EQ(run.exit_code, 0) << run.output << "\n(Debian package tcl)";
  // a_1, a_2: two elements each; fp, tfp: one; every tag used once.
  std::set<std::string> tags;
  std::istringstream lines(run.output);
  int elements = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("element ", 0) != 0) continue;
    ++elements;
    std::istringstream words(line);
    std::string word, type, tag;
    words >> word >> type >> tag;
    EXPECT_TRUE(tags.insert(tag).second) << "tag " << tag << " twice\n" << run.output;
  }
  EXPECT_EQ(elements, 6) << run.output;
  for (const char* placed :
       {"element elastomericBearingPlasticity 900003 1 2", "element zeroLength 900005 1 2",
        "element elastomericBearingPlasticity 900008 3 4", "element singleFPBearing",
        "element TripleFrictionPendulum", "site tfp -> "}) {
    EXPECT_NE(run.output.find(placed), std::string::npos) << placed << "\n" << run.output;
  }
}

}  // namespace
}  // namespace isolab::model
