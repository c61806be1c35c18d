#include "isolab/model/opensees_export.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <set>
#include <sstream>
#include <string_view>
#include <vector>

#include "isolab/hysteresis/hdr_bearing.h"
#include "isolab/hysteresis/law_parameters.h"

namespace isolab::model {
namespace {

using hysteresis::LawParameters;
using hysteresis::LawType;
using hysteresis::ParameterForm;

// A law's value by key in the form whose keys the bearing presets share.
double Value(const LawParameters& law, std::string_view key, ParameterForm form) {
  const auto keys = hysteresis::ParameterKeys(law.type(), form);
  const auto at = std::find(keys.begin(), keys.end(), key);
  if (at == keys.end()) {
    throw std::logic_error(fmt::format("{} has no key {}", hysteresis::LawName(law.type()), key));
  }
  return law.Values(form)[static_cast<std::size_t>(at - keys.begin())];
}

double Mechanical(const LawParameters& law, std::string_view key) {
  return Value(law, key, ParameterForm::kMechanical);
}

bool Given(const LawParameters& law, std::string_view key) {
  return !std::isnan(Mechanical(law, key));
}

// The shortest text that reads back as the same double.
std::string Number(double value) { return fmt::format("{}", value); }

// One component's element(s) between $iNode and $jNode, as lines of the type's procedure, and
// its initial horizontal stiffness (for the stiff axial material's default).
struct ComponentTcl {
  std::string lines;
  double initial_stiffness = 0.0;
};

constexpr std::string_view kShearInPlan = "-orient 0 0 1 1 0 0";  // local x up, y along global x

ComponentTcl Elastomeric(double ke, double kh, double fs, const std::string& what) {
  return {fmt::format("  # {}: the bilinear loop, yielding at fs = {}\n"
                      "  set e [isolab_tag]; lappend elements $e\n"
                      "  element elastomericBearingPlasticity $e $iNode $jNode {} {} {} 0 2 "
                      "-P $p -T $r -My $r -Mz $r {}\n",
                      what, Number(fs), Number(ke), Number(fs), Number(kh / ke), kShearInPlan),
          ke};
}

ComponentTcl FrictionPendulum(const LawParameters& law, const std::string& what) {
  const double w = Mechanical(law, "w"), r = Mechanical(law, "r"), uy = Mechanical(law, "uy");
  const bool constant = Given(law, "mu");
  const double mu = constant ? Mechanical(law, "mu") : Mechanical(law, "mu_slow");
  const std::string friction =
      constant ? fmt::format("frictionModel Coulomb $f {}", Number(mu))
               : fmt::format("frictionModel VelDependent $f {} {} {}", Number(mu),
                             Number(Mechanical(law, "mu_fast")), Number(Mechanical(law, "a")));
  return {fmt::format("  # {}: W = {} (friction acts on the element's axial load; apply it)\n"
                      "  set f [isolab_tag]; {}\n"
                      "  set e [isolab_tag]; lappend elements $e\n"
                      "  element singleFPBearing $e $iNode $jNode $f {} {} "
                      "-P $p -T $r -My $r -Mz $r {}\n",
                      what, Number(w), friction, Number(r), Number(mu * w / uy), kShearInPlan),
          w / r + mu * w / uy};
}

// OpenSees' element takes one inner surface for both: isolab's bearing must have them alike.
ComponentTcl TriplePendulum(const LawParameters& law, const std::string& what,
                            const std::string& where) {
  const auto v = [&](std::string_view key) { return Mechanical(law, key); };
  for (const auto& [a, b] : {std::pair{"r2", "r3"}, {"mu2", "mu3"}, {"d2", "d3"}}) {
    if (v(a) != v(b)) {
      throw std::invalid_argument(fmt::format(
          "{}: triple_friction_pendulum with {} = {} and {} = {}: OpenSees' "
          "TripleFrictionPendulum takes one inner surface for both (give them alike to export)",
          where, a, v(a), b, v(b)));
    }
  }
  const double w = v("w");
  return {
      fmt::format("  # {}: W = {} (apply it as the element's axial load)\n"
                  "  set f1 [isolab_tag]; frictionModel Coulomb $f1 {}\n"
                  "  set f2 [isolab_tag]; frictionModel Coulomb $f2 {}\n"
                  "  set f3 [isolab_tag]; frictionModel Coulomb $f3 {}\n"
                  "  set e [isolab_tag]; lappend elements $e\n"
                  "  element TripleFrictionPendulum $e $iNode $jNode $f1 $f2 $f3 $p $r $r $r "
                  "{} {} {} {} {} {} {} {} [expr {{$isolab_axial_stiffness / 1000.0}}] {} "
                  "1e-10\n",
                  what, Number(w), Number(v("mu2")), Number(v("mu1")), Number(v("mu4")),
                  Number(v("r2")), Number(v("r1")), Number(v("r4")), Number(v("d2")),
                  Number(v("d1")), Number(v("d4")), Number(w), Number(v("uy")), Number(1e-3 * w)),
      std::min({v("mu1"), v("mu2"), v("mu4")}) * w / v("uy")};
}

ComponentTcl LinearSpring(double k, const std::string& what) {
  return {fmt::format("  # {}\n"
                      "  set k [isolab_tag]; uniaxialMaterial Elastic $k {}\n"
                      "  set e [isolab_tag]; lappend elements $e\n"
                      "  element zeroLength $e $iNode $jNode -mat $k $k $p $r $r $r "
                      "-dir 1 2 3 4 5 6\n",
                      what, Number(k)),
          k};
}

constexpr std::string_view kExported =
    "exported: bhm2, elastoplastic, lead_rubber without heating, hdr_bearing, "
    "friction_pendulum, triple_friction_pendulum, linear_spring";

ComponentTcl OfLaw(const LawParameters& law, const std::string& what, const std::string& where) {
  const auto refuse = [&](const std::string& why) -> ComponentTcl {
    throw std::invalid_argument(
        fmt::format("{}: {} {} ({})", where, hysteresis::LawName(law.type()), why, kExported));
  };
  switch (law.type()) {
    case LawType::kBhm2:
      return Elastomeric(Mechanical(law, "ke"), Mechanical(law, "kh"), Mechanical(law, "fs"), what);
    case LawType::kElastoplastic:
      return Elastomeric(Mechanical(law, "ke"), 0.0, Mechanical(law, "fs"), what);
    case LawType::kLeadRubber:
      if (Given(law, "lead_diameter")) {
        return refuse(
            "with the lead core's heating has no OpenSees element that reproduces it "
            "(LeadRubberX's loop is smooth): export the bearing without the heating keys");
      }
      return Elastomeric(Mechanical(law, "ku"), Mechanical(law, "kd"), Mechanical(law, "qd"), what);
    case LawType::kHdrBearing: {
      hysteresis::HdrDesign design;
      design.shear_modulus = Mechanical(law, "g");
      design.bonded_area = Mechanical(law, "area");
      design.rubber_thickness = Mechanical(law, "tr");
      design.damping = Mechanical(law, "damping");
      design.strain = Mechanical(law, "strain");
      if (Given(law, "yield_strain")) design.yield_strain = Mechanical(law, "yield_strain");
      const hysteresis::Bhm2Mechanical bhm2 = hysteresis::EquivalentBhm2(design);
      return Elastomeric(bhm2.ke, bhm2.kh, bhm2.fs, what);
    }
    case LawType::kFrictionPendulum:
      return FrictionPendulum(law, what);
    case LawType::kTripleFrictionPendulum:
      return TriplePendulum(law, what, where);
    case LawType::kLinearSpring:
      return LinearSpring(Mechanical(law, "k"), what);
    default:
      return refuse("has no OpenSees element that reproduces it");
  }
}

// What a component's law is, in its own keys, for the comment above its element.
std::string Described(const std::string& name, const LawParameters& law) {
  const auto keys = hysteresis::ParameterKeys(law.type(), ParameterForm::kMechanical);
  const std::vector<double> values = law.Values(ParameterForm::kMechanical);
  std::vector<std::string> given;
  for (std::size_t k = 0; k < keys.size(); ++k) {
    if (!std::isnan(values[k])) given.push_back(fmt::format("{} {}", keys[k], Number(values[k])));
  }
  return fmt::format("{}: {} {}", name, hysteresis::LawName(law.type()), fmt::join(given, ", "));
}

struct Site {
  std::string name;
  hysteresis::Vec2 position;
  std::vector<std::pair<std::string, LawParameters>> components;  // (name, law)
  std::string where;                                              // key path, for messages
};

// Names become Tcl words and procedure names: letters, digits and _ . - only.
void RequireTclWord(const std::string& name, const std::string& where) {
  const bool word = !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '-';
  });
  if (!word) {
    throw std::invalid_argument(fmt::format(
        "{}: the name '{}' is not a Tcl word (give names of letters, digits, _ . - only)", where,
        name));
  }
}

std::vector<Site> Sites(const ModelFile& model) {
  std::vector<Site> sites;
  if (model.structure && model.structure->kind == StructureSection::Kind::kPlanBuilding) {
    for (const structure::PlanIsolatorSite& s : model.structure->plan.isolators) {
      Site site{s.name, s.position, {}, fmt::format("plan.isolators: isolator '{}'", s.name)};
      RequireTclWord(s.name, site.where);
      for (const hysteresis::PlanComponent& c : s.assembly.components()) {
        RequireTclWord(c.name, site.where);
        if (c.law_y) {
          throw std::invalid_argument(fmt::format(
              "{}, component '{}': an uncoupled pair (a law along x and another along y) has no "
              "OpenSees element that reproduces it",
              site.where, c.name));
        }
        site.components.emplace_back(c.name, c.law);
      }
      sites.push_back(std::move(site));
    }
    return sites;
  }
  std::vector<std::pair<std::string, LawParameters>> laws;
  for (const hysteresis::Component& c : model.isolation.components()) {
    RequireTclWord(c.name, "isolation");
    laws.emplace_back(c.name, c.parameters);
  }
  std::vector<std::string> names = IsolationBearings(model);
  if (names.empty() && !laws.empty()) names.push_back("isolation");
  for (const std::string& name : names) {
    RequireTclWord(name, "isolation");
    sites.push_back({name, {0.0, 0.0}, laws, fmt::format("isolation: bearing '{}'", name)});
  }
  return sites;
}

double SiteWeight(const Site& site) {
  double w = 0.0;
  for (const auto& [name, law] : site.components) w += hysteresis::PendulumWeight(law).value_or(0);
  return w;
}

// Bearing types: sites whose elements are the same share one procedure, named for its components
// ("isolab_type_lrb"), with a number where two types' components share names.
struct BearingType {
  std::string procedure;
  std::string body;
  double initial_stiffness = 0.0;
};

std::string Header(const ModelFile& model, const std::string& title) {
  const UnitSystem& u = model.units;
  return fmt::format(
      "# {}\n"
      "# The bearings as OpenSees elements (OpenSees 3.8, Tcl), written by isolab: units {}, {}, "
      "{}.\n"
      "# Source this file in a three-dimensional model (model BasicBuilder -ndm 3 -ndf 6) with z "
      "up,\n"
      "# then `isolab_bearing NAME iNode jNode` places bearing NAME between a ground node and the "
      "base\n"
      "# node above it and returns its element tags. isolab_sites lists each bearing: name, x, y, "
      "the\n"
      "# weight W its pendulums carry (apply it: their friction acts on the element's axial "
      "load),\n"
      "# and its procedure. isolab models no vertical, torsional or rocking deformation of a "
      "bearing:\n"
      "# they are stiff Elastic materials here; set isolab_axial_stiffness and\n"
      "# isolab_rotational_stiffness before sourcing to use your bearing's. Tags are drawn from\n"
      "# isolab_next_tag (set it before sourcing to keep clear of your model's).\n\n",
      title, u.force(), u.length(), u.time());
}

// The model's bearing types and each site's; throws std::invalid_argument naming what cannot be
// exported.
struct Bearings {
  std::vector<Site> sites;
  std::vector<BearingType> types;
  std::vector<std::size_t> type_of;  // per site
  double stiffest = 0.0;             // the largest initial horizontal stiffness of a bearing
};

Bearings Collect(const ModelFile& model) {
  Bearings b;
  b.sites = Sites(model);
  if (b.sites.empty()) throw std::invalid_argument("the model has no bearings");
  std::set<std::string> procedures;
  for (const Site& site : b.sites) {
    std::string body;
    double stiffness = 0.0;
    std::vector<std::string> names;
    for (const auto& [name, law] : site.components) {
      const ComponentTcl c =
          OfLaw(law, Described(name, law), fmt::format("{}, component '{}'", site.where, name));
      body += c.lines;
      stiffness += c.initial_stiffness;
      names.push_back(name);
    }
    // OpenSees' pendulums take their friction from their own axial force, which every element
    // between the same nodes would share: a pendulum is exported only as a bearing of its own.
    if (site.components.size() > 1) {
      for (const auto& [name, law] : site.components) {
        if (!hysteresis::PendulumWeight(law)) continue;
        throw std::invalid_argument(fmt::format(
            "{}, component '{}': a {} with other components in parallel (OpenSees' pendulum "
            "elements take their friction from their own axial force, which the others would "
            "share: give the pendulum an isolator of its own)",
            site.where, name, hysteresis::LawName(law.type())));
      }
    }
    b.stiffest = std::max(b.stiffest, stiffness);
    auto same = std::find_if(b.types.begin(), b.types.end(),
                             [&](const BearingType& t) { return t.body == body; });
    if (same == b.types.end()) {
      // In a namespace of their own (isolab_type_...), apart from the file's own procedures.
      const std::string stem = fmt::format("isolab_type_{}", fmt::join(names, "_"));
      std::string procedure = stem;
      for (int k = 2; procedures.contains(procedure); ++k)
        procedure = fmt::format("{}_{}", stem, k);
      procedures.insert(procedure);
      b.types.push_back({procedure, body, stiffness});
      same = b.types.end() - 1;
    }
    b.type_of.push_back(static_cast<std::size_t>(same - b.types.begin()));
  }
  return b;
}

}  // namespace

OpenSeesExport ExportToOpenSees(const ModelFile& model, const std::string& title) {
  Bearings bearings;
  try {
    bearings = Collect(model);
  } catch (const std::invalid_argument& e) {
    return {"", e.what()};
  }
  const auto& [sites, types, type_of, stiffest] = bearings;
  const double metre = 1.0 / model.units.SiFactor(dimension::kLength);
  std::ostringstream tcl;
  tcl << Header(model, title);
  fmt::print(tcl,
             "if {{![info exists isolab_next_tag]}} {{ set isolab_next_tag 900001 }}\n"
             "if {{![info exists isolab_axial_stiffness]}} {{ set isolab_axial_stiffness {} }}\n"
             "if {{![info exists isolab_rotational_stiffness]}} "
             "{{ set isolab_rotational_stiffness {} }}\n"
             "proc isolab_tag {{}} {{\n  global isolab_next_tag\n  set tag $isolab_next_tag\n"
             "  incr isolab_next_tag\n  return $tag\n}}\n\n",
             Number(1000.0 * stiffest), Number(1000.0 * stiffest * metre * metre));
  for (const BearingType& t : types) {
    fmt::print(tcl,
               "proc {} {{iNode jNode}} {{\n"
               "  global isolab_axial_stiffness isolab_rotational_stiffness\n"
               "  set elements {{}}\n"
               "  set p [isolab_tag]; uniaxialMaterial Elastic $p $isolab_axial_stiffness\n"
               "  set r [isolab_tag]; uniaxialMaterial Elastic $r $isolab_rotational_stiffness\n"
               "{}  return $elements\n}}\n\n",
               t.procedure, t.body);
  }
  fmt::print(tcl, "# name, x, y ({}), W ({}), procedure\nset isolab_sites {{\n",
             model.units.length(), model.units.force());
  for (std::size_t i = 0; i < sites.size(); ++i) {
    fmt::print(tcl, "  {{{} {} {} {} {}}}\n", sites[i].name, Number(sites[i].position.x),
               Number(sites[i].position.y), Number(SiteWeight(sites[i])),
               types[type_of[i]].procedure);
  }
  tcl << "}\n\n"
         "proc isolab_bearing {name iNode jNode} {\n"
         "  global isolab_sites\n"
         "  foreach site $isolab_sites {\n"
         "    if {[lindex $site 0] eq $name} { return [[lindex $site 4] $iNode $jNode] }\n"
         "  }\n"
         "  error \"isolab_bearing: no bearing '$name' in this file\"\n"
         "}\n";
  return {tcl.str(), ""};
}

}  // namespace isolab::model
