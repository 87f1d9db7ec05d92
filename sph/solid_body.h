#pragma once
// An elastic solid made of SPH particles: Gray, Monaghan & Swift 2001, "SPH elastic
// dynamics", Comput. Methods Appl. Mech. Engrg. 190, 6641-6662 — the seed paper's
// first gate model (Table 1 in docs/elastic_gate.md). Updated Lagrangian: density by continuity,
// pressure from the bulk modulus, deviatoric stress by the Jaumann rate of Hooke's law,
// momentum with Monaghan's artificial viscosity and the artificial stress that removes
// the tensile instability (their eq. 27-30: R = -eps sigma'/rho^2 on positive principal
// stresses, weighted by f^n = (W(r)/W(dp))^n, n = 4). 2D is plane strain.
//
// The solid is its own particle set: the fluid never sees its particles but a skin
// (coupling/sph_solid_skin_body.h) that moves with them, so it is loaded through the
// same surface-node path as every other body kind.

#include <Eigen/Dense>
#include <vector>

namespace chipflex::sph
{
struct SolidMaterial
{
  double density = 1100;          ///< kg/m^3 (Table 1)
  double youngs_modulus = 1.2e7;  ///< Pa (Table 1)
  double poisson_ratio = 0.4;     ///< - (Table 1)
  double artificial_stress = 0.2; ///< eps of Gray et al. (Table 1)
  double viscosity_alpha = 1.0;   ///< Monaghan artificial viscosity (Gray et al. use 1)
  double viscosity_beta = 0.0;    ///< quadratic term (velocities here are far below c)
  double cfl = 0.3;               ///< dt = cfl h / (c + |v|max)

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
  void compute_accelerations(); // from the current stress and positions
  void compute_stress_rates();  // from the current velocities
  double kernel(double r) const;
  double kernel_derivative(double r) const; // dW/dr

  SolidMaterial material_;
  double spacing_, h_, kernel_factor_, w_dp_;
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

  // Rates of the current step.
  std::vector<Vector> acceleration_;
  std::vector<double> density_rate_;
  std::vector<Tensor> stress_rate_, sigma_, artificial_;
};
} // namespace chipflex::sph
