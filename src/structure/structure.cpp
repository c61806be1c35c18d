#include "isolab/structure/structure.h"

#include <algorithm>
#include <stdexcept>

namespace isolab::structure {
namespace {

using hysteresis::LawState;
using hysteresis::Mat2;

}  // namespace

// The laws of an assembly whose every law is a spring of constant stiffness or a dashpot (so its
// tangent is constant: ConstantTangent holds it); nullopt for any other.
std::optional<std::vector<Structure::LinearLaw>> Structure::LinearLawsOf(
    const hysteresis::ParallelAssembly& assembly) {
  std::vector<LinearLaw> laws;
  for (const hysteresis::LawKernel& kernel : assembly.kernels()) {
    if (!hysteresis::HasConstantTangent(kernel)) return std::nullopt;
    if (const auto* spring = std::get_if<hysteresis::ElasticSpring>(&kernel)) {
      laws.emplace_back(*spring);
    } else if (const auto* damper = std::get_if<hysteresis::Dashpot>(&kernel)) {
      laws.emplace_back(*damper);
    } else {
      return std::nullopt;
    }
  }
  return laws;
}

int SlotOf(const SparseMatrix& matrix, int row, int col) {
  for (int k = matrix.outerIndexPtr()[col]; k < matrix.outerIndexPtr()[col + 1]; ++k) {
    if (matrix.innerIndexPtr()[k] == row) return k;
  }
  throw std::logic_error("sparse pattern lacks an entry it was built with");
}

bool Member::IsBetween(int* dof_i, int* dof_j) const {
  int plus = kGround, minus = kGround, count = 0;
  for (int a = 0; a < kMaxTerms; ++a) {
    if (dofs[a] == kGround) continue;
    ++count;
    if (coefficients[a] == 1.0 && plus == kGround) {
      plus = dofs[a];
    } else if (coefficients[a] == -1.0 && minus == kGround) {
      minus = dofs[a];
    } else {
      return false;
    }
  }
  if (plus == kGround || count != (minus == kGround ? 1 : 2)) return false;
  *dof_i = minus;
  *dof_j = plus;
  return true;
}

Member Member::Between(std::string name, int dof_i, int dof_j,
                       hysteresis::ParallelAssembly assembly) {
  Member member;
  member.name = std::move(name);
  member.assembly = std::move(assembly);
  member.dofs[0] = dof_j;
  member.coefficients[0] = 1.0;
  if (dof_i != kGround) {
    member.dofs[1] = dof_i;
    member.coefficients[1] = -1.0;
  }
  return member;
}

CoupledMember CoupledMember::UnderFloor(std::string name, int first_dof, Vec2 arm,
                                        hysteresis::PlanAssembly assembly) {
  CoupledMember member;
  member.name = std::move(name);
  member.assembly = std::move(assembly);
  const Vec2 columns[3] = {{1.0, 0.0}, {0.0, 1.0}, {-arm.y, arm.x}};
  for (int a = 0; a < 3; ++a) {
    member.dofs[a] = first_dof + a;
    member.columns[a] = columns[a];
  }
  return member;
}

void ConstantTerms::AppendEntries(int dofs, const SparseMatrix& damping,
                                  std::vector<Eigen::Triplet<double>>* entries) {
  for (int i = 0; i < dofs; ++i) entries->emplace_back(i, i, 0.0);
  for (int col = 0; col < damping.outerSize(); ++col) {
    for (SparseMatrix::InnerIterator it(damping, col); it; ++it) {
      entries->emplace_back(it.row(), it.col(), 0.0);
    }
  }
}

ConstantTerms::ConstantTerms(int dofs, const SparseMatrix& damping, const SparseMatrix& pattern) {
  for (int i = 0; i < dofs; ++i) mass_slots_.push_back(SlotOf(pattern, i, i));
  for (int col = 0; col < damping.outerSize(); ++col) {
    for (SparseMatrix::InnerIterator it(damping, col); it; ++it) {
      damping_slots_.push_back(SlotOf(pattern, static_cast<int>(it.row()), col));
    }
  }
}

void ConstantTerms::Fill(const Eigen::VectorXd& mass, const SparseMatrix& damping,
                         const TangentFactors& factors, SparseMatrix* tangent) const {
  double* values = tangent->valuePtr();
  std::fill(values, values + tangent->nonZeros(), 0.0);
  for (std::size_t i = 0; i < mass_slots_.size(); ++i) {
    values[mass_slots_[i]] += factors.mass * mass[i];
  }
  const double* c = damping.valuePtr();
  for (std::size_t k = 0; k < damping_slots_.size(); ++k) {
    values[damping_slots_[k]] += factors.damping * c[k];
  }
}

Structure::Structure(Eigen::VectorXd mass, std::vector<Member> members,
                     std::vector<CoupledMember> coupled_members, SparseMatrix viscous_damping)
    : mass_(std::move(mass)),
      members_(std::move(members)),
      coupled_(std::move(coupled_members)),
      member_count_(members_.size()),
      viscous_damping_(std::move(viscous_damping)) {
  const int n = dofs();
  for (int i = 0; i < n; ++i) {
    if (!(mass_[i] > 0.0)) {
      throw std::invalid_argument("the mass of dof " + std::to_string(i) + " must be > 0");
    }
  }
  viscous_damping_.makeCompressed();
  damping_product_ = DampingProduct(viscous_damping_);
  const auto check_dofs = [n](const std::string& name, const std::array<int, kMaxTerms>& dofs) {
    bool any = false;
    for (const int dof : dofs) {
      if (dof < kGround || dof >= n) {
        throw std::invalid_argument("member '" + name + "' acts on a dof that does not exist");
      }
      any = any || dof != kGround;
    }
    if (!any) throw std::invalid_argument("member '" + name + "' acts on no dof");
  };

  law_offsets_.push_back(0);
  for (const Member& member : members_) {
    check_dofs(member.name, member.dofs);
    // Component c's own state at offset + c, the further states of sliders in series after
    // all the components' own (parallel_assembly.h).
    std::size_t state = law_offsets_.back();
    for (const auto& kernel : member.assembly.kernels()) {
      if (std::holds_alternative<hysteresis::Dashpot>(kernel)) viscous_law_states_.push_back(state);
      ++state;
    }
    law_offsets_.push_back(law_offsets_.back() + member.assembly.state_size());
  }
  for (const CoupledMember& member : coupled_) {
    check_dofs(member.name, member.dofs);
    // A dashpot's x and y halves, listed once each so that the viscous energy is a sum.
    std::size_t state = law_offsets_.back();
    for (const auto& kernel : member.assembly.kernels()) {
      const auto* pair = std::get_if<hysteresis::UncoupledPair>(&kernel);
      const bool coupled = std::holds_alternative<hysteresis::PlanDashpot>(kernel);
      if (coupled || (pair && std::holds_alternative<hysteresis::Dashpot>(pair->x))) {
        viscous_law_states_.push_back(state);
      }
      if (coupled || (pair && std::holds_alternative<hysteresis::Dashpot>(pair->y))) {
        viscous_law_states_.push_back(state + 1);
      }
      state += 2;
    }
    // The further states of sliders in series, two LawStates each (plan_assembly.h).
    law_offsets_.push_back(law_offsets_.back() + 2 * member.assembly.state_size());
  }

  // The pattern: mass diagonal and viscous damping, every member's dofs pairwise; fixed for the
  // structure's life.
  std::vector<Eigen::Triplet<double>> entries;
  ConstantTerms::AppendEntries(n, viscous_damping_, &entries);
  const auto pairs = [&entries](const std::array<int, kMaxTerms>& dofs) {
    for (const int a : dofs) {
      for (const int b : dofs) {
        if (a != kGround && b != kGround) entries.emplace_back(a, b, 0.0);
      }
    }
  };
  for (const Member& member : members_) pairs(member.dofs);
  for (const CoupledMember& member : coupled_) pairs(member.dofs);
  pattern_.resize(n, n);
  pattern_.setFromTriplets(entries.begin(), entries.end());
  pattern_.makeCompressed();
  constant_terms_ = ConstantTerms(n, viscous_damping_, pattern_);

  for (std::size_t k = 0; k < members_.size(); ++k) {
    const Member& member = members_[k];
    Terms packed;
    for (int a = 0; a < kMaxTerms; ++a) {
      if (member.dofs[a] == kGround) continue;
      packed.dofs[packed.count] = member.dofs[a];
      packed.coefficients[packed.count++] = member.coefficients[a];
    }
    for (int a = 0; a < packed.count; ++a) {
      for (int b = 0; b < packed.count; ++b) {
        packed.slots[a * packed.count + b] = SlotOf(pattern_, packed.dofs[a], packed.dofs[b]);
      }
    }
    member_terms_.push_back(packed);
    member_constants_.push_back(member.assembly.ConstantTangent());
    Between spring;
    spring.member = k;
    if (member.IsBetween(&spring.dof_i, &spring.dof_j)) {
      spring.jj = SlotOf(pattern_, spring.dof_j, spring.dof_j);
      if (spring.dof_i != kGround) {
        spring.ii = SlotOf(pattern_, spring.dof_i, spring.dof_i);
        spring.ij = SlotOf(pattern_, spring.dof_i, spring.dof_j);
        spring.ji = SlotOf(pattern_, spring.dof_j, spring.dof_i);
      }
      if (const auto laws = LinearLawsOf(member.assembly)) {
        spring.linear.begin = static_cast<std::uint32_t>(linear_laws_.size());
        linear_laws_.insert(linear_laws_.end(), laws->begin(), laws->end());
        spring.linear.end = static_cast<std::uint32_t>(linear_laws_.size());
      }
      between_.push_back(spring);
    } else {
      general_.push_back(k);
    }
  }
  for (const CoupledMember& member : coupled_) {
    CoupledTerms packed;
    for (int a = 0; a < kMaxTerms; ++a) {
      if (member.dofs[a] == kGround) continue;
      packed.dofs[packed.count] = member.dofs[a];
      packed.columns[packed.count++] = member.columns[a];
    }
    for (int a = 0; a < packed.count; ++a) {
      for (int b = 0; b < packed.count; ++b) {
        packed.slots[a * packed.count + b] = SlotOf(pattern_, packed.dofs[a], packed.dofs[b]);
      }
    }
    packed.under_floor = packed.count == 3 && packed.dofs[1] == packed.dofs[0] + 1 &&
                         packed.dofs[2] == packed.dofs[0] + 2 &&
                         packed.columns[0] == Vec2{1.0, 0.0} && packed.columns[1] == Vec2{0.0, 1.0};
    packed.arm = {packed.columns[2].y, -packed.columns[2].x};
    coupled_terms_.push_back(packed);
    coupled_constants_.push_back(member.assembly.ConstantTangent());
  }
}

void Structure::AddMemberTangent(std::size_t member, double k_eff, double* values) const {
  const Terms& terms = member_terms_[member];
  for (int a = 0; a < terms.count; ++a) {
    const double row = terms.coefficients[a] * k_eff;
    for (int b = 0; b < terms.count; ++b) {
      values[terms.slots[a * terms.count + b]] += row * terms.coefficients[b];
    }
  }
}

void Structure::AddBetweenTangent(const Between& spring, double k_eff, double* values) const {
  values[spring.jj] += k_eff;
  if (spring.ii < 0) return;  // grounded
  values[spring.ii] += k_eff;
  values[spring.ij] -= k_eff;
  values[spring.ji] -= k_eff;
}

void Structure::AddCoupledTangent(std::size_t coupled, const Mat2& k_eff, double* values) const {
  const CoupledTerms& terms = coupled_terms_[coupled];
  if (terms.under_floor) {
    // T^T K T with T = [1 0 -a_y; 0 1 a_x], row-major over (u_x, u_y, theta).
    const double ax = terms.arm.x, ay = terms.arm.y;
    const double x_theta = -ay * k_eff.xx + ax * k_eff.xy, y_theta = -ay * k_eff.yx + ax * k_eff.yy;
    const double theta_x = -ay * k_eff.xx + ax * k_eff.yx, theta_y = -ay * k_eff.xy + ax * k_eff.yy;
    const int* slot = terms.slots.data();
    values[slot[0]] += k_eff.xx;
    values[slot[1]] += k_eff.xy;
    values[slot[2]] += x_theta;
    values[slot[3]] += k_eff.yx;
    values[slot[4]] += k_eff.yy;
    values[slot[5]] += y_theta;
    values[slot[6]] += theta_x;
    values[slot[7]] += theta_y;
    values[slot[8]] += -ay * theta_x + ax * theta_y;
    return;
  }
  for (int b = 0; b < terms.count; ++b) {
    const Vec2 k_column = k_eff * terms.columns[b];
    for (int a = 0; a < terms.count; ++a) {
      values[terms.slots[a * terms.count + b]] += Dot(terms.columns[a], k_column);
    }
  }
}

void Structure::ConstantTangent(const TangentFactors& factors, SparseMatrix* tangent) const {
  constant_terms_.Fill(mass_, viscous_damping_, factors, tangent);
  double* values = tangent->valuePtr();
  for (std::size_t k = 0; k < members_.size(); ++k) {
    if (const auto& constant = member_constants_[k]) {
      AddMemberTangent(k, constant->stiffness + factors.damping * constant->damping, values);
    }
  }
  for (std::size_t i = 0; i < coupled_.size(); ++i) {
    if (const auto& constant = coupled_constants_[i]) {
      AddCoupledTangent(i, constant->stiffness + factors.damping * constant->damping, values);
    }
  }
}

Vec2 Structure::CoupledDeformation(std::size_t coupled, std::span<const double> u) const {
  const CoupledTerms& terms = coupled_terms_[coupled];
  Vec2 d;
  for (int a = 0; a < terms.count; ++a) d = d + u[terms.dofs[a]] * terms.columns[a];
  return d;
}

Structure::Influence Structure::SlotInfluence(std::size_t slot) const {
  Influence influence;
  if (slot < member_count_) {
    const Terms& terms = member_terms_[slot];
    influence.count = terms.count;
    for (int a = 0; a < terms.count; ++a) {
      influence.dofs[a] = terms.dofs[a];
      influence.columns[a] = {terms.coefficients[a], 0.0};
    }
  } else {
    const CoupledTerms& terms = coupled_terms_[slot - member_count_];
    influence.count = terms.count;
    std::copy_n(terms.dofs.begin(), terms.count, influence.dofs.begin());
    std::copy_n(terms.columns.begin(), terms.count, influence.columns.begin());
  }
  return influence;
}

namespace {

// A slot's summed response and its laws' responses times s (a pendulum under its axial load).
void ScaleResponses(double s, hysteresis::AssemblyResponse* total,
                    std::span<hysteresis::LawResponse> responses) {
  total->force *= s;
  total->stiffness *= s;
  total->damping *= s;
  for (hysteresis::LawResponse& response : responses) {
    response.force *= s;
    response.stiffness *= s;
    response.damping *= s;
  }
}

}  // namespace

// Flattened: the laws' dispatch (std::visit) and their inline updates belong in this loop.
template <bool kScaled>
[[gnu::flatten]] void Structure::EvaluateMember(std::size_t k, std::span<const LawState> committed,
                                                const hysteresis::LawInput& in,
                                                std::span<LawState> trial,
                                                std::span<hysteresis::LawResponse> responses,
                                                std::span<double> member_forces,
                                                double damping_factor, double* values,
                                                const double* scales) const {
  const std::size_t offset = law_offsets_[k], count = members_[k].assembly.state_size();
  hysteresis::AssemblyResponse total =
      members_[k].assembly.Update(committed.subspan(offset, count), in,
                                  trial.subspan(offset, count), responses.subspan(offset, count));
  if constexpr (kScaled) {
    ScaleResponses(scales[k], &total, responses.subspan(offset, members_[k].assembly.size()));
  }
  member_forces[k] = total.force;
  if (values && !member_constants_[k]) {
    AddMemberTangent(k, total.stiffness + damping_factor * total.damping, values);
  }
}

// Flattened: the laws' dispatch (std::visit) and their inline updates belong in this loop.
template <bool kScaled>
[[gnu::flatten]] void Structure::EvaluateSprings(
    std::span<const LawState> committed, double t, const Eigen::VectorXd& u,
    const Eigen::VectorXd& v, std::span<LawState> trial,
    std::span<hysteresis::LawResponse> responses, Eigen::VectorXd* force,
    std::span<double> member_forces, double damping_factor, double* values, const double* scales,
    bool linear_force_only) const {
  for (const Between& spring : between_) {
    const std::size_t k = spring.member;
    const bool grounded = spring.dof_i == kGround;
    const hysteresis::LawInput in = BetweenInput(spring, t, u, v);
    if (linear_force_only && spring.linear.begin != spring.linear.end) {
      double f = 0.0;  // summed as ParallelAssembly::Update sums its laws' forces
      for (std::uint32_t l = spring.linear.begin; l < spring.linear.end; ++l) {
        f += std::visit([&in](const auto& law) { return law.Force(in); }, linear_laws_[l]);
      }
      member_forces[k] = f;
      (*force)[spring.dof_j] += f;
      if (!grounded) (*force)[spring.dof_i] -= f;
      continue;
    }
    const std::size_t offset = law_offsets_[k], count = members_[k].assembly.state_size();
    hysteresis::AssemblyResponse total =
        members_[k].assembly.Update(committed.subspan(offset, count), in,
                                    trial.subspan(offset, count), responses.subspan(offset, count));
    if constexpr (kScaled) {
      ScaleResponses(scales[k], &total, responses.subspan(offset, members_[k].assembly.size()));
    }
    member_forces[k] = total.force;
    (*force)[spring.dof_j] += total.force;
    if (!grounded) (*force)[spring.dof_i] -= total.force;
    if (values && !member_constants_[k]) {
      AddBetweenTangent(spring, total.stiffness + damping_factor * total.damping, values);
    }
  }
}

void Structure::UpdateCoupledComponent(std::size_t coupled, std::size_t component,
                                       std::span<const LawState> committed,
                                       const hysteresis::PlanLawInput& in,
                                       std::span<LawState> trial,
                                       hysteresis::PlanLawResponse* response) const {
  const hysteresis::PlanAssembly& assembly = coupled_[coupled].assembly;
  const hysteresis::PlanLawKernel& kernel = assembly.kernels()[component];
  const std::size_t first = slot_law_offset(coupled_slot(coupled)), offset = first + 2 * component;
  if (const auto* series = std::get_if<hysteresis::PlanSeriesArrangement>(&kernel)) {
    // Its elements' states, as LawState pairs after every component's own.
    const std::size_t at = first + 2 * assembly.ElementStatesOffset(component);
    const std::size_t count = 2 * static_cast<std::size_t>(series->state_slots() - 1);
    series->UpdateFlat({committed[offset], committed[offset + 1]}, committed.subspan(at, count), in,
                       {trial[offset], trial[offset + 1]}, trial.subspan(at, count), response);
    return;
  }
  hysteresis::UpdatePlanLaw(kernel, {committed[offset], committed[offset + 1]}, in,
                            {trial[offset], trial[offset + 1]}, response);
}

// Flattened: the laws' dispatch (std::visit) and their inline updates belong in this loop.
template <bool kScaled>
[[gnu::flatten]] void Structure::EvaluateCoupled(std::span<const LawState> committed, double t,
                                                 const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                                                 std::span<LawState> trial,
                                                 std::span<hysteresis::LawResponse> responses,
                                                 Eigen::VectorXd* force,
                                                 std::span<double> member_forces,
                                                 double damping_factor, double* values,
                                                 const double* scales) const {
  for (std::size_t i = 0; i < coupled_.size(); ++i) {
    const CoupledTerms& terms = coupled_terms_[i];
    hysteresis::PlanLawInput in{{}, {}, t};
    for (int a = 0; a < terms.count; ++a) {
      in.u = in.u + u[terms.dofs[a]] * terms.columns[a];
      in.v = in.v + v[terms.dofs[a]] * terms.columns[a];
    }
    const hysteresis::PlanAssembly& assembly = coupled_[i].assembly;
    std::size_t offset = slot_law_offset(coupled_slot(i));
    Vec2 f;
    Mat2 k_eff;
    const bool several = assembly.state_size() != assembly.size();
    for (std::size_t c = 0; c < assembly.size(); ++c) {
      hysteresis::PlanLawResponse response;
      if (several) {
        UpdateCoupledComponent(i, c, committed, in, trial, &response);
      } else {
        hysteresis::UpdatePlanLaw(assembly.kernels()[c], {committed[offset], committed[offset + 1]},
                                  in, {trial[offset], trial[offset + 1]}, &response);
      }
      responses[offset] = {response.force.x, response.stiffness.xx, response.damping.xx};
      responses[offset + 1] = {response.force.y, response.stiffness.yy, response.damping.yy};
      f = f + response.force;
      k_eff = k_eff + response.stiffness + damping_factor * response.damping;
      offset += 2;
    }
    if constexpr (kScaled) {
      const double s = scales[coupled_slot(i)];
      f = s * f;
      k_eff = s * k_eff;
      for (std::size_t l = slot_law_offset(coupled_slot(i)); l < offset; ++l) {
        responses[l].force *= s;
        responses[l].stiffness *= s;
        responses[l].damping *= s;
      }
    }
    const std::size_t column = slot_force_column(coupled_slot(i));
    member_forces[column] = f.x;
    member_forces[column + 1] = f.y;
    for (int a = 0; a < terms.count; ++a) (*force)[terms.dofs[a]] += Dot(terms.columns[a], f);
    if (values && !coupled_constants_[i]) AddCoupledTangent(i, k_eff, values);
  }
}

void Structure::Evaluate(std::span<const LawState> committed, double t, const Eigen::VectorXd& u,
                         const Eigen::VectorXd& v, std::span<LawState> trial,
                         std::span<hysteresis::LawResponse> responses, Eigen::VectorXd* force,
                         std::span<double> member_forces, const TangentFactors& factors,
                         SparseMatrix* tangent, std::span<const double> scales,
                         LinearLaws linear) const {
  double* values = tangent ? tangent->valuePtr() : nullptr;
  const bool linear_force_only = linear == LinearLaws::kForceOnly;
  if (scales.empty()) {
    EvaluateAll<false>(committed, t, u, v, trial, responses, force, member_forces, factors.damping,
                       values, nullptr, linear_force_only);
  } else {
    if (scales.size() != slots()) {
      throw std::invalid_argument("Structure::Evaluate: one scale per slot, or none");
    }
    if (linear_force_only) {
      throw std::invalid_argument("Structure::Evaluate: scales with the linear laws' force only");
    }
    EvaluateAll<true>(committed, t, u, v, trial, responses, force, member_forces, factors.damping,
                      values, scales.data(), false);
  }
}

void Structure::UpdateLinearLaws(std::span<const LawState> committed, double t,
                                 const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                                 std::span<LawState> trial,
                                 std::span<hysteresis::LawResponse> responses) const {
  if (linear_laws_.empty()) return;  // none (an SDOF on its isolator): nothing to walk
  for (const Between& spring : between_) {
    if (spring.linear.begin == spring.linear.end) continue;
    const hysteresis::LawInput in = BetweenInput(spring, t, u, v);
    std::size_t offset = law_offsets_[spring.member];
    for (std::uint32_t l = spring.linear.begin; l < spring.linear.end; ++l, ++offset) {
      std::visit(
          [&](const auto& law) {
            law.Update(committed[offset], in, &trial[offset], &responses[offset]);
          },
          linear_laws_[l]);
    }
  }
}

template <bool kScaled>
void Structure::EvaluateAll(std::span<const LawState> committed, double t, const Eigen::VectorXd& u,
                            const Eigen::VectorXd& v, std::span<LawState> trial,
                            std::span<hysteresis::LawResponse> responses, Eigen::VectorXd* force,
                            std::span<double> member_forces, double damping_factor, double* values,
                            const double* scales, bool linear_force_only) const {
  DampingForce(v, force);
  EvaluateSprings<kScaled>(committed, t, u, v, trial, responses, force, member_forces,
                           damping_factor, values, scales, linear_force_only);
  for (const std::size_t k : general_) {
    const Terms& terms = member_terms_[k];
    double d = 0.0, d_rate = 0.0;
    for (int a = 0; a < terms.count; ++a) {
      d += terms.coefficients[a] * u[terms.dofs[a]];
      d_rate += terms.coefficients[a] * v[terms.dofs[a]];
    }
    EvaluateMember<kScaled>(k, committed, {d, d_rate, t}, trial, responses, member_forces,
                            damping_factor, values, scales);
    for (int a = 0; a < terms.count; ++a) {
      (*force)[terms.dofs[a]] += terms.coefficients[a] * member_forces[k];
    }
  }
  if (!coupled_.empty()) {
    EvaluateCoupled<kScaled>(committed, t, u, v, trial, responses, force, member_forces,
                             damping_factor, values, scales);
  }
}

double Structure::SlotStoredEnergy(std::size_t slot, std::span<const LawState> states) const {
  if (slot < member_count_) {
    return members_[slot].assembly.StoredEnergy(
        states.subspan(law_offsets_[slot], members_[slot].assembly.state_size()));
  }
  const std::size_t i = slot - member_count_;
  const hysteresis::PlanAssembly& assembly = coupled_[i].assembly;
  const std::size_t first = slot_law_offset(coupled_slot(i));
  double energy = 0.0;
  for (std::size_t c = 0; c < assembly.size(); ++c) {
    const hysteresis::PlanLawKernel& kernel = assembly.kernels()[c];
    const std::size_t offset = first + 2 * c;
    if (const auto* series = std::get_if<hysteresis::PlanSeriesArrangement>(&kernel)) {
      const std::size_t at = first + 2 * assembly.ElementStatesOffset(c);
      energy += series->StoredEnergyFlat(
          {states[offset], states[offset + 1]},
          states.subspan(at, 2 * static_cast<std::size_t>(series->state_slots() - 1)));
    } else {
      energy += hysteresis::PlanStoredEnergy(kernel, {states[offset], states[offset + 1]});
    }
  }
  return energy;
}

double Structure::SlotDissipatedEnergy(std::size_t slot, std::span<const LawState> states) const {
  double energy = 0.0;
  for (std::size_t l = law_offsets_[slot]; l < law_offsets_[slot + 1]; ++l) {
    energy += states[l].dissipated;
  }
  return energy;
}

double Structure::StoredEnergy(std::span<const LawState> states) const {
  double energy = 0.0;
  for (std::size_t k = 0; k < members_.size(); ++k) {
    energy += members_[k].assembly.StoredEnergy(
        states.subspan(law_offsets_[k], members_[k].assembly.state_size()));
  }
  for (std::size_t i = 0; i < coupled_.size(); ++i) {
    const hysteresis::PlanAssembly& assembly = coupled_[i].assembly;
    const std::size_t first = slot_law_offset(coupled_slot(i));
    if (assembly.state_size() == assembly.size()) {  // one state a law
      std::size_t offset = first;
      for (const hysteresis::PlanLawKernel& kernel : assembly.kernels()) {
        energy += hysteresis::PlanStoredEnergy(kernel, {states[offset], states[offset + 1]});
        offset += 2;
      }
      continue;
    }
    for (std::size_t c = 0; c < assembly.size(); ++c) {
      const hysteresis::PlanLawKernel& kernel = assembly.kernels()[c];
      const std::size_t offset = first + 2 * c;
      if (const auto* series = std::get_if<hysteresis::PlanSeriesArrangement>(&kernel)) {
        const std::size_t at = first + 2 * assembly.ElementStatesOffset(c);
        energy += series->StoredEnergyFlat(
            {states[offset], states[offset + 1]},
            states.subspan(at, 2 * static_cast<std::size_t>(series->state_slots() - 1)));
      } else {
        energy += hysteresis::PlanStoredEnergy(kernel, {states[offset], states[offset + 1]});
      }
    }
  }
  return energy;
}

double Structure::DashpotEnergy(std::span<const LawState> states) const {
  double energy = 0.0;
  for (const std::size_t l : viscous_law_states_) energy += states[l].dissipated;
  return energy;
}

double Structure::DissipatedEnergy(std::span<const LawState> states) const {
  double dissipated = 0.0;
  for (const LawState& state : states) dissipated += state.dissipated;
  return dissipated;
}

}  // namespace isolab::structure
