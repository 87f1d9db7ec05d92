#pragma once
// An elastic solid made of SPH particles, in one of two formulations (SolidFormulation):
// total Lagrangian St Venant-Kirchhoff (the default, below), or Gray, Monaghan & Swift
// 2001, "SPH elastic dynamics", Comput. Methods Appl. Mech. Engrg. 190, 6641-6662 — the
// seed paper's first gate model (Table 1 in docs/elastic_gate.md). That one is updated
// Lagrangian: density by continuity,
// pressure from the bulk modulus, deviatoric stress by the Jaumann rate of Hooke's law,
// momentum with Monaghan's artificial viscosity and the artificial stress that removes
// the tensile instability (their eq. 27-30: R = -eps sigma'/rho^2 on positive principal
// stresses, weighted by f^n = (W(r)/W(dp))^n, n = 4). 2D is plane strain.
//
// Optionally (on by default) every kernel gradient carries the correction of Bonet & Lok
// 1999, "Variational and momentum preservation aspects of SPH formulations", Comput.
// Methods Appl. Mech. Engrg. 180, 97-115, recomputed every step in the current
// configuration: without it kernels cut off at the strip's two free surfaces
// under-estimate the bending strain rate, and the six-layer gate is 16-21 % softer than
// its material (tests/coupling/test_sph_solid_validation.cc).
//
// The solid is its own particle set: the fluid never sees its particles but a skin
// (coupling/sph_solid_skin_body.h) that moves with them, so it is loaded through the
// same surface-node path as every other body kind.

#include <Eigen/Dense>
#include <limits>
#include <vector>

namespace chipflex::sph
{
/// How the solid computes its stress.
enum class SolidFormulation
{
  /// Gray, Monaghan & Swift 2001 (the seed's model): updated Lagrangian, density by
  /// continuity, Jaumann rate of Hooke's law, artificial stress against the tensile
  /// instability, neighbours in the current configuration.
  updated_lagrangian,
  /// Total Lagrangian (Bonet & Lok 1999; the form SPHinXsys uses for its solids):
  /// neighbours and kernel gradients of the reference configuration, the deformation
  /// gradient F_i = I + sum_j V_j (u_j - u_i) (C_i grad_0 W_ij)^T, St Venant-Kirchhoff
  /// stress S = lambda tr(E) I + 2 mu E, E = (F^T F - I) / 2, and the forces that are the
  /// exact derivative of the discrete strain energy sum_i V_i psi(F_i). Fixed neighbours
  /// have no tensile instability, so no artificial stress.
  total_lagrangian
};

/// Density, E and nu have no defaults (NaN: not given): a default would silently give
/// every solid that forgot one the elastic gate's rubber. The numerical parameters below
/// keep theirs. check() names what is missing.
struct SolidMaterial
{
  double density = std::numeric_limits<double>::quiet_NaN();        ///< kg/m^3
  double youngs_modulus = std::numeric_limits<double>::quiet_NaN(); ///< Pa
  double poisson_ratio = std::numeric_limits<double>::quiet_NaN();  ///< -
  double artificial_stress = 0.2; ///< eps of Gray et al. (Table 1)
  double viscosity_alpha = 1.0;   ///< Monaghan artificial viscosity (Gray et al. use 1)
  double viscosity_beta = 0.0;    ///< quadratic term (velocities here are far below c)
  double cfl = 0.3;               ///< dt = cfl h / (c + |v|max)
  SolidFormulation formulation = SolidFormulation::total_lagrangian;
  /// Total Lagrangian: Ganzenmueller's (2015) hourglass control, the coefficient alpha of
  /// a pair spring on the mismatch between the separation F_i (X_j - X_i) the particle's
  /// deformation gradient predicts and the actual x_j - x_i; 0: off. At the gate's six
  /// layers it also carries bending stiffness: 0 leaves the strip 27 % too soft, 10 puts
  /// it within 3.3 % of beam theory, 50 makes it 70 % too stiff (docs/sph.md).
  double hourglass_control = 10;
  /// Bonet & Lok (1999) kernel-gradient correction: every kernel gradient of particle i
  /// is multiplied by C_i = (sum_j V_j grad_i W_ij (x_j - x_i)^T)^-1, which makes the SPH
  /// gradient of any linear field exact, at free surfaces too (docs/sph.md, "SPH solid").
  /// Total Lagrangian: once, in the reference configuration; updated Lagrangian: every
  /// step, in the current one.
  bool kernel_gradient_correction = true;
  /// Where det(sum_j V_j grad_i W_ij (x_j - x_i)^T) falls below this (a full kernel
  /// gives 1), particle i keeps the uncorrected gradient: the matrix is ill-conditioned
  /// for particles with few neighbours (a corner, a particle thrown off the surface).
  double correction_min_determinant = 0.05;

  /// Throws std::invalid_argument naming a value not given or out of range.
  void check() const;

  double bulk_modulus() const { return youngs_modulus / (3 * (1 - 2 * poisson_ratio)); }
  double shear_modulus() const { return youngs_modulus / (2 * (1 + poisson_ratio)); }
  /// Speed of the longitudinal (fastest) wave: sqrt((K + 4G/3) / rho).
  double wave_speed() const;
};

template <int dim>
class SolidBody
{
public:
  using Vector = Eigen::Matrix<double, dim, 1>;
  using Tensor = Eigen::Matrix<double, dim, dim>;

  /// @param spacing the particle spacing dp (W(dp) normalises the artificial stress)
  /// @param smoothing_length h of the Wendland C2 kernel (support 2h)
  SolidBody(const SolidMaterial& material, double spacing, double smoothing_length);

  /// A particle at rest and stress free; `fixed` particles never move (a clamp) but
  /// carry stress so that the clamp is elastic continuum for their neighbours.
  int add_particle(const Vector& position, double volume, bool fixed);

  void set_gravity(const Vector& g) { gravity_ = g; }
  /// External forces per particle (N; 2D: N per metre), held until replaced.
  void set_external_forces(const std::vector<Vector>& forces);

  /// The largest stable step in the current state.
  double stable_time_step() const;
  /// Advances by `dt` with as many equal sub-steps as stability asks for; returns
  /// the number of sub-steps taken.
  int advance(double dt);
  /// One symplectic-Euler step (velocity, then position with the new velocity).
  void step(double dt);

  std::size_t n_particles() const { return x_.size(); }
  const std::vector<Vector>& positions() const { return x_; }
  const std::vector<Vector>& velocities() const { return v_; }
  const std::vector<double>& densities() const { return rho_; }
  const std::vector<double>& masses() const { return mass_; }
  const std::vector<Tensor>& deviatoric_stresses() const { return s_; }
  bool is_fixed(int i) const { return fixed_[i]; }
  double pressure(int i) const;
  /// The kernel-gradient correction C_i of the last step (identity where it is off or
  /// fell back); and how many particles fell back to the uncorrected gradient.
  const std::vector<Tensor>& corrections() const { return correction_; }
  std::size_t n_uncorrected() const { return n_uncorrected_; }
  const SolidMaterial& material() const { return material_; }
  double spacing() const { return spacing_; }
  double smoothing_length() const { return h_; }

  /// Momentum of the moving particles plus the impulse that the fixed ones took up
  /// (their reaction): conserved by the pairwise forces, changed only by external
  /// forces and gravity. Used by tests.
  Vector linear_momentum() const;

  /// The state as one flat array (positions, velocities, densities, stresses, and the
  /// fixed particles' reaction impulse) for checkpoints; restore() takes it back.
  std::vector<double> state() const;
  void restore(const std::vector<double>& state);

private:
  void build_neighbour_list();
  void update_neighbours();
  void compute_corrections(); // C_i from the current positions
  void setup_reference();     // total Lagrangian: neighbours, C_i, grad_0 W_ij
  void step_total_lagrangian(double dt);
  void compute_accelerations(); // from the current stress and positions
  void compute_stress_rates();  // from the current velocities
  double kernel(double r) const;
  double kernel_derivative(double r) const; // dW/dr

  SolidMaterial material_;
  double spacing_, h_, w_dp_;
  Vector gravity_ = Vector::Zero();

  std::vector<Vector> x_, v_, f_ext_, x_at_build_;
  std::vector<double> rho_, mass_;
  std::vector<Tensor> s_;
  std::vector<char> fixed_;
  Vector clamp_impulse_ = Vector::Zero();

  // Neighbour list (CSR), built with a margin and rebuilt when a particle has moved
  // more than half of it: a solid's neighbourhoods hardly change.
  std::vector<int> neighbour_start_, neighbours_;
  double margin_;
  std::size_t n_uncorrected_ = 0;

  // Rates of the current step.
  std::vector<Vector> acceleration_;
  std::vector<double> density_rate_;
  std::vector<Tensor> stress_rate_, sigma_, artificial_;
  std::vector<Tensor> correction_; // C_i (identity without the correction)

  // Total Lagrangian: reference positions and volumes, the reference kernel gradient
  // grad_0 W_ij per neighbour pair (CSR as neighbours_), first Piola-Kirchhoff stress.
  std::vector<Vector> x_ref_, reference_gradient_;
  std::vector<double> volume_ref_;
  std::vector<Tensor> piola_, deformation_;
  bool reference_ready_ = false;
};
} // namespace chipflex::sph
