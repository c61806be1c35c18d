#include "isolab/structure/plan_building.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "isolab/structure/shear_building.h"

namespace isolab::structure {
namespace {

using hysteresis::Vec2;

// A story's resistance along `direction` (unit x or y) at plan point p, or in torsion (direction
// zero), between the floor whose dofs start at `below` (kGround: a fixed base) and the one whose
// dofs start at `above`.
Member StoryMember(std::string name, int below, const PlanFloor& floor_below, int above,
                   const PlanFloor& floor_above, Vec2 p, Vec2 direction,
                   hysteresis::ParallelAssembly assembly) {
  Member member;
  member.name = std::move(name);
  member.assembly = std::move(assembly);
  // Displacement along `direction` of the floor point p: direction . (u + theta k x (p - c)),
  // or the floor's rotation for torsion.
  const auto terms = [&](int first_dof, const PlanFloor& f, double sign, int first_term) {
    if (first_dof == kGround) return;
    const Vec2 arm = p - f.centre_of_mass;
    const bool torsion = direction == Vec2{};
    const double rotation = torsion ? 1.0 : Dot(direction, Perpendicular(arm));
    const double coefficients[3] = {direction.x, direction.y, rotation};
    for (int a = 0; a < 3; ++a) {
      member.dofs[first_term + a] = first_dof + a;
      member.coefficients[first_term + a] = sign * coefficients[a];
    }
  };
  terms(below, floor_below, -1.0, 0);
  terms(above, floor_above, 1.0, 3);
  // Drop the terms that are zero, so the tangent pattern holds only real couplings.
  for (int a = 0; a < kMaxTerms; ++a) {
    if (member.coefficients[a] == 0.0) member.dofs[a] = kGround;
  }
  return member;
}

const PlanFloor& FloorOf(const PlanBuilding& building, int floor) {
  return floor == 0 ? building.base : building.stories[floor - 1].floor;
}

SparseMatrix RayleighDamping(const PlanBuilding& building, const std::vector<Member>& members,
                             const Eigen::VectorXd& mass, bool fixed_base) {
  const int n = static_cast<int>(mass.size());
  if (!building.damping.rayleigh) return SparseMatrix(n, n);
  const PlanDamping& d = building.damping;
  if (!(d.periods[0] > 0.0 && d.periods[1] > 0.0) || d.periods[0] == d.periods[1]) {
    throw std::invalid_argument("damping.periods: two different periods > 0");
  }
  const double w1 = 2.0 * std::numbers::pi / d.periods[0];
  const double w2 = 2.0 * std::numbers::pi / d.periods[1];
  const double z1 = d.ratios[0], z2 = d.ratios[1];
  // zeta(w) = a0 / (2 w) + a1 w / 2 through both points.
  const double a1 = 2.0 * (z2 * w2 - z1 * w1) / (w2 * w2 - w1 * w1);
  const double a0 = 2.0 * z1 * w1 - a1 * w1 * w1;
  if (a0 < 0.0 || a1 < 0.0) {
    throw std::invalid_argument(
        "damping.ratios: these ratios give a negative Rayleigh coefficient (a0 = " +
        std::to_string(a0) + ", a1 = " + std::to_string(a1) + ")");
  }
  // a1 K: the stories' initial stiffness. It does not resist the building's rigid-body motion,
  // so it equals its fixed-base form on motion relative to the base.
  std::vector<Eigen::Triplet<double>> entries;
  for (const Member& member : members) {
    const double k = a1 * InitialStiffness(member.assembly);
    for (int a = 0; a < kMaxTerms; ++a) {
      for (int b = 0; b < kMaxTerms; ++b) {
        if (member.dofs[a] == kGround || member.dofs[b] == kGround) continue;
        entries.emplace_back(member.dofs[a], member.dofs[b],
                             member.coefficients[a] * k * member.coefficients[b]);
      }
    }
  }
  // a0 T^T M_s T with T q = q_s - R_s q_base, R_s carrying the base's rigid-body motion to floor
  // s's centre of mass: the mass term damps no rigid-body motion on the isolators either. On a
  // fixed base, T is the identity: a0 M.
  const PlanFloor& base = building.base;
  if (fixed_base) {
    for (int i = 0; i < n; ++i) entries.emplace_back(i, i, a0 * mass[i]);
  }
  for (int f = 1; !fixed_base && f < n / kPlanDofsPerFloor; ++f) {
    const Vec2 r = FloorOf(building, f).centre_of_mass - base.centre_of_mass;
    // Rows of T for floor f: dof (3f + a) minus R[a][*] on the base's dofs.
    const double rigid[3][3] = {{1.0, 0.0, -r.y}, {0.0, 1.0, r.x}, {0.0, 0.0, 1.0}};
    for (int a = 0; a < 3; ++a) {
      const double m = a0 * mass[kPlanDofsPerFloor * f + a];
      // T row: e_(3f+a) - sum_b rigid[a][b] e_b; add m * row^T row.
      std::array<std::pair<int, double>, 4> row{{{kPlanDofsPerFloor * f + a, 1.0}}};
      int size = 1;
      for (int b = 0; b < 3; ++b) {
        if (rigid[a][b] != 0.0) row[size++] = {b, -rigid[a][b]};
      }
      for (int i = 0; i < size; ++i) {
        for (int j = 0; j < size; ++j) {
          entries.emplace_back(row[i].first, row[j].first, m * row[i].second * row[j].second);
        }
      }
    }
  }
  SparseMatrix c(n, n);
  c.setFromTriplets(entries.begin(), entries.end());
  c.prune(0.0);
  return c;
}

}  // namespace

LaidOutStructure BuildPlanBuilding(const PlanBuilding& building, bool fixed_base) {
  if (!fixed_base && building.isolators.empty()) {
    throw std::invalid_argument("isolators: at least one isolator");
  }
  if (fixed_base && building.stories.empty()) {
    throw std::invalid_argument("stories: a building on a fixed base needs a story");
  }
  const int floors = static_cast<int>(building.stories.size()) + 1;
  const int first = fixed_base ? 1 : 0;  // the lowest floor with dofs
  // The first dof of floor f (the base is floor 0), or kGround for a fixed base.
  const auto dof = [first](int f) { return f < first ? kGround : kPlanDofsPerFloor * (f - first); };
  Layout layout;
  layout.directions = 2;
  layout.rotations = true;
  Eigen::VectorXd mass(kPlanDofsPerFloor * (floors - first));
  for (int f = first; f < floors; ++f) {
    const PlanFloor& floor = FloorOf(building, f);
    const std::string what = f == 0 ? "base" : "story " + building.stories[f - 1].name;
    if (!(floor.mass > 0.0)) throw std::invalid_argument(what + ": mass must be > 0");
    if (!(floor.rotational_inertia > 0.0)) {
      throw std::invalid_argument(what + ": rotational inertia must be > 0");
    }
    mass.segment(dof(f), kPlanDofsPerFloor) << floor.mass, floor.mass, floor.rotational_inertia;
    layout.levels.push_back({f == 0 ? "base" : "floor " + std::to_string(f),
                             {dof(f), dof(f) + 1, dof(f) + 2},
                             floor.centre_of_mass});
  }
  std::vector<Member> members;
  for (int s = 0; s + 1 < floors; ++s) {
    const PlanStory& story = building.stories[s];
    const PlanFloor& below = FloorOf(building, s);
    const Vec2 p = story.centre_of_stiffness;
    const int x = static_cast<int>(members.size());
    layout.stories.push_back({story.name, s + 1 - first, story.height, {x, x + 1, x + 2}});
    members.push_back(StoryMember(story.name + ".x", dof(s), below, dof(s + 1), story.floor, p,
                                  {1.0, 0.0}, story.x));
    members.push_back(StoryMember(story.name + ".y", dof(s), below, dof(s + 1), story.floor, p,
                                  {0.0, 1.0}, story.y));
    members.push_back(StoryMember(story.name + ".torsion", dof(s), below, dof(s + 1), story.floor,
                                  p, {}, story.torsion));
  }
  std::vector<CoupledMember> isolators;
  if (fixed_base) {
    layout.base_shear = {{0, kX}, {1, kY}};
  } else {
    for (const PlanIsolatorSite& site : building.isolators) {
      // Coupled members' slots follow the members'.
      const int slot = static_cast<int>(members.size() + isolators.size());
      layout.isolators.push_back({site.name, slot, 0, site.position});
      layout.base_shear.push_back({slot, kX});
      isolators.push_back(CoupledMember::UnderFloor(
          site.name, 0, site.position - building.base.centre_of_mass, site.assembly));
    }
  }
  for (const Direction direction : {kX, kY}) {
    Eigen::VectorXd& r = layout.ground_influence[direction];
    r.setZero(mass.size());
    for (Eigen::Index i = direction; i < r.size(); i += kPlanDofsPerFloor) r[i] = 1.0;
  }
  SparseMatrix c = RayleighDamping(building, members, mass, fixed_base);
  return {Structure(std::move(mass), std::move(members), std::move(isolators), std::move(c)),
          std::move(layout)};
}

}  // namespace isolab::structure
