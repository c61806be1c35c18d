#include "isolab/structure/plan_structure.h"

#include <stdexcept>

namespace isolab::structure {
namespace {

using hysteresis::LawState;
using hysteresis::Mat2;
using hysteresis::PlanLawResponse;
using hysteresis::Vec2;

constexpr int kTerms = PlanMember::kMaxTerms;

// Columns of an isolator's kinematic map T = [1 0 -arm.y; 0 1 arm.x].
std::array<Vec2, 3> MapColumns(Vec2 arm) {
  return {Vec2{1.0, 0.0}, Vec2{0.0, 1.0}, Vec2{-arm.y, arm.x}};
}

}  // namespace

PlanStructure::PlanStructure(Eigen::VectorXd mass, std::vector<PlanMember> members,
                             std::vector<PlanIsolator> isolators, SparseMatrix viscous_damping)
    : mass_(std::move(mass)),
      members_(std::move(members)),
      isolators_(std::move(isolators)),
      viscous_damping_(std::move(viscous_damping)) {
  const int n = dofs();
  if (n == 0 || n % kPlanDofsPerFloor != 0) {
    throw std::invalid_argument("a plan structure has three dofs per floor");
  }
  for (int i = 0; i < n; ++i) {
    if (!(mass_[i] > 0.0)) {
      throw std::invalid_argument("the mass (or rotational inertia) of dof " + std::to_string(i) +
                                  " must be > 0");
    }
  }
  viscous_damping_.makeCompressed();
  law_offsets_.push_back(0);
  for (const PlanMember& member : members_) {
    for (const int dof : member.dofs) {
      if (dof < kGround || dof >= n) {
        throw std::invalid_argument("member '" + member.name +
                                    "' acts on a dof that does not exist");
      }
    }
    std::size_t state = law_offsets_.back();
    for (const auto& kernel : member.assembly.kernels()) {
      if (std::holds_alternative<hysteresis::Dashpot>(kernel)) viscous_law_states_.push_back(state);
      ++state;
    }
    law_offsets_.push_back(law_offsets_.back() + member.assembly.state_size());
  }
  for (const PlanIsolator& isolator : isolators_) {
    if (isolator.floor < 0 || isolator.floor >= floors()) {
      throw std::invalid_argument("isolator '" + isolator.name +
                                  "' is under a floor that does not exist");
    }
    // A dashpot's x and y halves (PlanViscousEnergy), listed once so the energy is a sum.
    std::size_t state = law_offsets_.back();
    for (const auto& kernel : isolator.assembly.kernels()) {
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
    state += 2 * (isolator.assembly.state_size() - isolator.assembly.size());
    law_offsets_.push_back(state);
  }

  // The pattern: mass diagonal and viscous damping, every member's terms pairwise, every
  // isolator's floor block; fixed for the structure's life.
  std::vector<Eigen::Triplet<double>> entries;
  ConstantTerms::AppendEntries(n, viscous_damping_, &entries);
  for (const PlanMember& member : members_) {
    for (const int a : member.dofs) {
      for (const int b : member.dofs) {
        if (a != kGround && b != kGround) entries.emplace_back(a, b, 0.0);
      }
    }
  }
  for (const PlanIsolator& isolator : isolators_) {
    const int first = kPlanDofsPerFloor * isolator.floor;
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) entries.emplace_back(first + a, first + b, 0.0);
    }
  }
  pattern_.resize(n, n);
  pattern_.setFromTriplets(entries.begin(), entries.end());
  pattern_.makeCompressed();

  constant_terms_ = ConstantTerms(n, viscous_damping_, pattern_);
  for (const PlanMember& member : members_) {
    MemberTerms packed;
    for (int a = 0; a < kTerms; ++a) {
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
  }
  for (const PlanIsolator& isolator : isolators_) {
    const int first = kPlanDofsPerFloor * isolator.floor;
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) isolator_slots_.push_back(SlotOf(pattern_, first + a, first + b));
    }
    isolator_constants_.push_back(isolator.assembly.ConstantTangent());
  }
}

void PlanStructure::AddMemberTangent(std::size_t member, double k_eff, double* values) const {
  const MemberTerms& terms = member_terms_[member];
  for (int a = 0; a < terms.count; ++a) {
    const double row = terms.coefficients[a] * k_eff;
    for (int b = 0; b < terms.count; ++b) {
      values[terms.slots[a * terms.count + b]] += row * terms.coefficients[b];
    }
  }
}

void PlanStructure::AddIsolatorTangent(std::size_t isolator, const Mat2& k_eff,
                                       double* values) const {
  const std::array<Vec2, 3> columns = MapColumns(isolators_[isolator].arm);
  const int* slots = &isolator_slots_[9 * isolator];
  for (int b = 0; b < 3; ++b) {
    const Vec2 k_column = k_eff * columns[b];
    for (int a = 0; a < 3; ++a) values[slots[3 * a + b]] += Dot(columns[a], k_column);
  }
}

void PlanStructure::ConstantTangent(const TangentFactors& factors, SparseMatrix* tangent) const {
  constant_terms_.Fill(mass_, viscous_damping_, factors, tangent);
  double* values = tangent->valuePtr();
  for (std::size_t k = 0; k < members_.size(); ++k) {
    if (const auto& constant = member_constants_[k]) {
      AddMemberTangent(k, constant->stiffness + factors.damping * constant->damping, values);
    }
  }
  for (std::size_t i = 0; i < isolators_.size(); ++i) {
    if (const auto& constant = isolator_constants_[i]) {
      AddIsolatorTangent(i, constant->stiffness + factors.damping * constant->damping, values);
    }
  }
}

Vec2 PlanStructure::IsolatorDeformation(std::size_t isolator, std::span<const double> u) const {
  const PlanIsolator& iso = isolators_[isolator];
  const int first = kPlanDofsPerFloor * iso.floor;
  const double theta = u[first + 2];
  return {u[first] - iso.arm.y * theta, u[first + 1] + iso.arm.x * theta};
}

void PlanStructure::Evaluate(std::span<const LawState> committed, double t,
                             const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                             std::span<LawState> trial,
                             std::span<hysteresis::LawResponse> responses, Eigen::VectorXd* force,
                             std::span<double> connection_forces, const TangentFactors& factors,
                             SparseMatrix* tangent) const {
  force->noalias() = viscous_damping_ * v;
  double* values = tangent ? tangent->valuePtr() : nullptr;

  for (std::size_t k = 0; k < members_.size(); ++k) {
    const MemberTerms& terms = member_terms_[k];
    double d = 0.0, d_rate = 0.0;
    for (int a = 0; a < terms.count; ++a) {
      d += terms.coefficients[a] * u[terms.dofs[a]];
      d_rate += terms.coefficients[a] * v[terms.dofs[a]];
    }
    const std::size_t offset = law_offsets_[k], count = members_[k].assembly.state_size();
    const hysteresis::AssemblyResponse total =
        members_[k].assembly.Update(committed.subspan(offset, count), {d, d_rate, t},
                                    trial.subspan(offset, count), responses.subspan(offset, count));
    connection_forces[k] = total.force;
    for (int a = 0; a < terms.count; ++a) {
      (*force)[terms.dofs[a]] += terms.coefficients[a] * total.force;
    }
    if (values && !member_constants_[k]) {
      AddMemberTangent(k, total.stiffness + factors.damping * total.damping, values);
    }
  }

  for (std::size_t i = 0; i < isolators_.size(); ++i) {
    const PlanIsolator& isolator = isolators_[i];
    const int first = kPlanDofsPerFloor * isolator.floor;
    const hysteresis::PlanLawInput in{
        {u[first] - isolator.arm.y * u[first + 2], u[first + 1] + isolator.arm.x * u[first + 2]},
        {v[first] - isolator.arm.y * v[first + 2], v[first + 1] + isolator.arm.x * v[first + 2]},
        t};
    std::size_t offset = isolator_law_offset(i);
    Vec2 f;
    Mat2 k_eff;
    for (const hysteresis::PlanLawKernel& kernel : isolator.assembly.kernels()) {
      PlanLawResponse response;
      hysteresis::UpdatePlanLaw(kernel, {committed[offset], committed[offset + 1]}, in,
                                {trial[offset], trial[offset + 1]}, &response);
      responses[offset] = {response.force.x, response.stiffness.xx, response.damping.xx};
      responses[offset + 1] = {response.force.y, response.stiffness.yy, response.damping.yy};
      f = f + response.force;
      k_eff = k_eff + response.stiffness + factors.damping * response.damping;
      offset += 2;
    }
    const std::size_t column = isolator_force_column(i);
    connection_forces[column] = f.x;
    connection_forces[column + 1] = f.y;
    // T^T f on the floor's dofs, T^T K_eff T into its 3x3 block.
    const std::array<Vec2, 3> columns = MapColumns(isolator.arm);
    for (int a = 0; a < 3; ++a) (*force)[first + a] += Dot(columns[a], f);
    if (values && !isolator_constants_[i]) AddIsolatorTangent(i, k_eff, values);
  }
}

double PlanStructure::StoredEnergy(std::span<const LawState> states) const {
  double energy = 0.0;
  for (std::size_t k = 0; k < members_.size(); ++k) {
    energy += members_[k].assembly.StoredEnergy(
        states.subspan(law_offsets_[k], members_[k].assembly.state_size()));
  }
  for (std::size_t i = 0; i < isolators_.size(); ++i) {
    std::size_t offset = isolator_law_offset(i);
    for (const hysteresis::PlanLawKernel& kernel : isolators_[i].assembly.kernels()) {
      energy += hysteresis::PlanStoredEnergy(kernel, {states[offset], states[offset + 1]});
      offset += 2;
    }
  }
  return energy;
}

double PlanStructure::DashpotEnergy(std::span<const LawState> states) const {
  double energy = 0.0;
  for (const std::size_t l : viscous_law_states_) energy += states[l].dissipated;
  return energy;
}

double PlanStructure::DissipatedEnergy(std::span<const LawState> states) const {
  double energy = 0.0;
  for (const LawState& state : states) energy += state.dissipated;
  return energy;
}

double PlanStructure::HystereticEnergy(std::span<const LawState> states) const {
  return DissipatedEnergy(states) - DashpotEnergy(states);
}

}  // namespace isolab::structure
