// excitation (ground motion, applied forces) and analysis (step, duration, integrator options).
#include <fmt/format.h>

#include <cstdlib>
#include <string_view>

#include "isolab/core/errors.h"
#include "model_sections.h"

namespace isolab::model {
namespace {

// Runs an options struct's Validate() and reports a violation at the key it names.
template <typename Validate>
void ValidateAt(const YamlReader& reader, const YAML::Node& node, const std::string& path,
                Validate validate) {
  try {
    validate();
  } catch (const InvalidParameter& error) {
    const YAML::Node at = node[error.violation().key];
    throw InputError(reader.Locate(at.IsDefined() ? at : node),
                     fmt::format("{}.{}", path, error.violation().Describe()));
  }
}

// A quantity as the file gives it, for reports: its own text when it names a unit, else the
// number with the model's unit.
std::string AsGiven(const YAML::Node& node, Dimension dimension, const UnitSystem& units) {
  const std::string text = node.Scalar();
  char* end = nullptr;
  std::strtod(text.c_str(), &end);
  const bool bare =
      end != text.c_str() && std::string_view(end).find_first_not_of(" ") == std::string_view::npos;
  return bare ? fmt::format("{} {}", text, DescribeUnits(units, dimension)) : text;
}

// `scale: {pga: 0.4 g}` or `scale: {sa: 0.6 g, period: 2.5 s, damping: 0.05}`.
ScaleTarget ReadScaleTarget(const YamlReader& reader, const YAML::Node& node,
                            const std::string& path, const UnitSystem& units) {
  reader.CheckKeys(node, path, {"pga", "sa", "period", "damping"});
  ScaleTarget target;
  if (node["pga"] && node["sa"]) {
    reader.Fail(node, path, "give one target, pga or sa, not both");
  }
  if (node["pga"]) {
    for (const char* key : {"period", "damping"}) {
      if (node[key]) {
        reader.Fail(node[key], ChildPath(path, key),
                    "goes with a target sa (pseudo-spectral acceleration), not with pga");
      }
    }
    target.measure = ScaleTarget::Measure::kPga;
    target.value = ReadPositive(reader, node, path, "pga", dimension::kAcceleration, units);
    target.text = "PGA " + AsGiven(node["pga"], dimension::kAcceleration, units);
    return target;
  }
  if (!node["sa"]) {
    reader.Fail(node, path,
                "a map gives the target the record is scaled to: {pga: 0.4 g} or "
                "{sa: 0.6 g, period: 2.5 s, damping: 0.05}");
  }
  target.measure = ScaleTarget::Measure::kSa;
  target.value = ReadPositive(reader, node, path, "sa", dimension::kAcceleration, units);
  target.period = ReadPositive(reader, node, path, "period", dimension::kTime, units);
  if (node["damping"])
    target.damping = ReadRatio(reader, node["damping"], ChildPath(path, "damping"));
  target.text =
      fmt::format("Sa({}, {:g} %) {}", AsGiven(node["period"], dimension::kTime, units),
                  100.0 * target.damping, AsGiven(node["sa"], dimension::kAcceleration, units));
  return target;
}

}  // namespace

std::string RecordAngleProblem(double angle) {
  if (std::abs(angle) <= kMaxRecordAngle) return {};
  return fmt::format("{:g} degrees (must be in [-{:g}, {:g}])", angle, kMaxRecordAngle,
                     kMaxRecordAngle);
}

double ReadRecordAngle(const YamlReader& reader, const YAML::Node& node, const std::string& path) {
  const double angle = reader.ReadNumber(node, path);
  if (const std::string problem = RecordAngleProblem(angle); !problem.empty()) {
    reader.Fail(node, path, problem);
  }
  return angle;
}

GroundMotionSection ReadGroundMotion(const YamlReader& reader, const YAML::Node& motion,
                                     const std::string& motion_path, const UnitSystem& units) {
  reader.RequireMap(motion, motion_path);
  reader.CheckKeys(motion, motion_path, {"file", "units", "scale", "dt"});
  GroundMotionSection ground;
  ground.key = motion_path;
  ground.location = reader.Locate(motion);
  ground.file =
      reader.ReadString(reader.Require(motion, motion_path, "file"), motion_path + ".file");
  if (motion["units"]) {
    ground.units = reader.ReadString(motion["units"], motion_path + ".units");
    try {
      units.Convert(1.0, ground.units, dimension::kAcceleration);
    } catch (const std::invalid_argument& error) {
      reader.Fail(motion["units"], motion_path + ".units",
                  fmt::format("{} (g, m/s^2, cm/s^2, in/s^2, ...)", error.what()));
    }
  }
  if (motion["scale"] && motion["scale"].IsMap()) {
    ground.target = ReadScaleTarget(reader, motion["scale"], motion_path + ".scale", units);
  } else if (motion["scale"]) {
    // As a study's scales, --scale and Python's scale=: 0 runs no excitation at all.
    ground.scale = reader.ReadNumber(motion["scale"], motion_path + ".scale");
    if (!(ground.scale > 0.0)) {
      reader.Fail(motion["scale"], motion_path + ".scale",
                  fmt::format("{:g} (must be a finite number > 0)", ground.scale));
    }
  }
  if (motion["dt"]) {
    ground.dt = reader.ReadQuantity(motion["dt"], motion_path + ".dt", dimension::kTime, units);
    if (!(ground.dt > 0.0)) reader.Fail(motion["dt"], motion_path + ".dt", "must be > 0");
  }
  return ground;
}

ExcitationSection ReadExcitation(const YamlReader& reader, const YAML::Node& node,
                                 const UnitSystem& units) {
  const std::string path = "excitation";
  reader.RequireMap(node, path);
  reader.CheckKeys(node, path, {"ground_motion", "forces"});
  ExcitationSection section;
  if (node["ground_motion"]) {
    // One component {file, ...}, or H1 with an optional H2 {h1, h2, angle}.
    const std::string motion_path = "excitation.ground_motion";
    const YAML::Node motion = node["ground_motion"];
    reader.RequireMap(motion, motion_path);
    if (motion["h1"] || motion["h2"] || motion["v"] || motion["angle"]) {
      if (motion["file"]) {
        reader.Fail(motion, motion_path,
                    "give one record {file, units, scale, dt} or the components h1 and h2 "
                    "(each {file, units, scale, dt}) with the angle of h1 from x, not both");
      }
      reader.CheckKeys(motion, motion_path, {"h1", "h2", "v", "angle"});
      section.ground_motion.push_back(ReadGroundMotion(
          reader, reader.Require(motion, motion_path, "h1"), ChildPath(motion_path, "h1"), units));
      if (motion["h2"]) {
        section.ground_motion.push_back(
            ReadGroundMotion(reader, motion["h2"], ChildPath(motion_path, "h2"), units));
      }
      if (motion["v"]) {
        section.vertical =
            ReadGroundMotion(reader, motion["v"], ChildPath(motion_path, "v"), units);
      }
      // A target scales the whole record by one factor, computed from h1 (problem.h): the other
      // components take that factor, and a second target or factor would contradict it.
      for (const char* key : {"h2", "v"}) {
        const YAML::Node scale = motion[key] ? motion[key]["scale"] : YAML::Node();
        if (!scale) continue;
        const std::string scale_path = ChildPath(ChildPath(motion_path, key), "scale");
        if (scale.IsMap()) {
          reader.Fail(scale, scale_path,
                      fmt::format("a target scales the whole record by one factor, computed "
                                  "from h1: give it as {}.h1.scale",
                                  motion_path));
        }
        if (section.ground_motion[0].target) {
          reader.Fail(scale, scale_path,
                      fmt::format("{}.h1.scale is a target, whose factor scales every component: "
                                  "give no scale here",
                                  motion_path));
        }
      }
      if (motion["angle"]) {
        section.angle = ReadRecordAngle(reader, motion["angle"], ChildPath(motion_path, "angle"));
      }
    } else {
      section.ground_motion.push_back(ReadGroundMotion(reader, motion, motion_path, units));
    }
  }
  if (node["forces"]) {
    const YAML::Node list = node["forces"];
    reader.RequireSequence(list, "excitation.forces");
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string force_path = IndexPath("excitation.forces", i);
      reader.RequireMap(list[i], force_path);
      reader.CheckKeys(list[i], force_path, {"dof", "dt", "values"});
      ForceSection force;
      force.dof =
          reader.ReadInteger(reader.Require(list[i], force_path, "dof"), force_path + ".dof");
      const YAML::Node dt = reader.Require(list[i], force_path, "dt");
      force.dt = reader.ReadQuantity(dt, force_path + ".dt", dimension::kTime, units);
      if (!(force.dt > 0.0)) reader.Fail(dt, force_path + ".dt", "must be > 0");
      const YAML::Node values = reader.Require(list[i], force_path, "values");
      reader.RequireSequence(values, force_path + ".values");
      for (std::size_t k = 0; k < values.size(); ++k) {
        force.values.push_back(reader.ReadQuantity(values[k], IndexPath(force_path + ".values", k),
                                                   dimension::kForce, units));
      }
      section.forces.push_back(std::move(force));
    }
  }
  if (section.ground_motion.empty() && section.forces.empty()) {
    reader.Fail(node, path, "give a ground_motion, forces, or both");
  }
  return section;
}

FreeVibration ReadFreeVibration(const YamlReader& reader, const YAML::Node& node,
                                const std::string& path, const UnitSystem& units) {
  if (node.IsScalar() && node.Scalar() == "auto") return {};
  const double duration = reader.ReadQuantity(node, path, dimension::kTime, units);
  if (!(duration >= 0.0)) {
    reader.Fail(node, path,
                fmt::format("{:g} (must be auto, or a time >= 0; 0 for none)", duration));
  }
  return {false, duration};
}

AnalysisSection ReadAnalysis(const YamlReader& reader, const YAML::Node& node,
                             const UnitSystem& units) {
  const std::string path = "analysis";
  reader.RequireMap(node, path);
  reader.CheckKeys(node, path,
                   {"dt", "duration", "free_vibration", "integrator", "newmark", "ida"});
  AnalysisSection section;
  if (node["dt"]) {
    section.dt = reader.ReadQuantity(node["dt"], "analysis.dt", dimension::kTime, units);
    if (!(section.dt > 0.0))
      reader.Fail(node["dt"], "analysis.dt", fmt::format("{:g} (must be > 0)", section.dt));
  }
  if (node["duration"]) {
    section.duration =
        reader.ReadQuantity(node["duration"], "analysis.duration", dimension::kTime, units);
    if (!(section.duration > 0.0)) {
      reader.Fail(node["duration"], "analysis.duration",
                  fmt::format("{:g} (must be > 0)", section.duration));
    }
  }
  if (node["free_vibration"]) {
    const YAML::Node free = node["free_vibration"];
    if (node["duration"]) {
      reader.Fail(free, "analysis.free_vibration",
                  "give duration (the whole run) or free_vibration (after the excitation), not "
                  "both");
    }
    section.free_vibration = ReadFreeVibration(reader, free, "analysis.free_vibration", units);
  }
  if (node["integrator"]) {
    const std::string integrator = reader.ReadString(node["integrator"], "analysis.integrator");
    if (integrator == "ida") {
      section.integrator = AnalysisSection::Integrator::kIda;
    } else if (integrator != "newmark") {
      reader.Fail(node["integrator"], "analysis.integrator",
                  fmt::format("'{}' is not an integrator (expected newmark or ida)", integrator));
    }
  }
  if (node["newmark"]) {
    const YAML::Node newmark = node["newmark"];
    const std::string np = "analysis.newmark";
    reader.RequireMap(newmark, np);
    reader.CheckKeys(newmark, np,
                     {"method", "beta", "gamma", "newton", "force_tolerance",
                      "displacement_tolerance", "max_iterations", "max_step_cuts"});
    integrators::NewmarkOptions& o = section.newmark;
    if (newmark["method"]) {
      const std::string method = reader.ReadString(newmark["method"], np + ".method");
      if (method == "linear_acceleration") {
        o = integrators::NewmarkOptions::LinearAcceleration();
      } else if (method != "average_acceleration") {
        reader.Fail(
            newmark["method"], np + ".method",
            fmt::format("'{}' (expected average_acceleration or linear_acceleration)", method));
      }
    }
    if (newmark["beta"]) o.beta = reader.ReadNumber(newmark["beta"], np + ".beta");
    if (newmark["gamma"]) o.gamma = reader.ReadNumber(newmark["gamma"], np + ".gamma");
    if (newmark["newton"]) {
      const std::string newton = reader.ReadString(newmark["newton"], np + ".newton");
      using Newton = integrators::NewmarkOptions::Newton;
      if (newton == "full") {
        o.newton = Newton::kFull;
      } else if (newton == "modified_initial") {
        o.newton = Newton::kModifiedInitial;
      } else if (newton == "modified_step") {
        o.newton = Newton::kModifiedStep;
      } else {
        reader.Fail(newmark["newton"], np + ".newton",
                    fmt::format("'{}' (expected full, modified_initial or modified_step)", newton));
      }
    }
    if (newmark["force_tolerance"]) {
      o.force_tolerance = reader.ReadNumber(newmark["force_tolerance"], np + ".force_tolerance");
    }
    if (newmark["displacement_tolerance"]) {
      o.displacement_tolerance =
          reader.ReadNumber(newmark["displacement_tolerance"], np + ".displacement_tolerance");
    }
    if (newmark["max_iterations"]) {
      o.max_iterations = reader.ReadInteger(newmark["max_iterations"], np + ".max_iterations");
    }
    if (newmark["max_step_cuts"]) {
      o.max_step_cuts = reader.ReadInteger(newmark["max_step_cuts"], np + ".max_step_cuts");
    }
    ValidateAt(reader, newmark, np, [&] { o.Validate(); });
  }
  if (node["ida"]) {
    const YAML::Node ida = node["ida"];
    const std::string ip = "analysis.ida";
    reader.RequireMap(ida, ip);
    reader.CheckKeys(ida, ip, {"rtol", "atol", "max_step", "max_steps"});
    integrators::IdaOptions& o = section.ida;
    if (ida["rtol"]) o.relative_tolerance = reader.ReadNumber(ida["rtol"], ip + ".rtol");
    if (ida["atol"]) o.absolute_tolerance = reader.ReadNumber(ida["atol"], ip + ".atol");
    if (ida["max_step"]) {
      o.max_step = reader.ReadQuantity(ida["max_step"], ip + ".max_step", dimension::kTime, units);
    }
    if (ida["max_steps"]) o.max_steps = reader.ReadInteger(ida["max_steps"], ip + ".max_steps");
    ValidateAt(reader, ida, ip, [&] { o.Validate(); });
  }
  return section;
}

}  // namespace isolab::model
