// FluidSolver: checkpoints. Everything that determines the future of the run is saved
// bit for bit (floats widen to double exactly and narrow back exactly), in the current
// (sorted) particle order, so that a restarted run repeats the uninterrupted one.

#include "common/hdf5_file.h"
#include "common/input_error.h"
#include "sph/fluid_solver_impl.h"

namespace chipflex::sph
{
namespace
{
template <typename T>
std::vector<double> widen(const std::vector<T>& a)
{
  return std::vector<double>(a.begin(), a.end());
}

template <typename T, std::size_t D>
std::vector<double> interleave(const std::array<std::vector<T>, D>& a, std::size_t n)
{
  std::vector<double> out(n * D);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t d = 0; d < D; ++d)
      out[i * D + d] = double(a[d][i]);
  return out;
}

template <typename T, std::size_t D>
void split(const std::vector<double>& in, std::array<std::vector<T>, D>& a, std::size_t n,
           const std::string& where)
{
  if (in.size() != n * D)
    throw InputError(where, "wrong size in checkpoint");
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t d = 0; d < D; ++d)
      a[d][i] = T(in[i * D + d]);
}
} // namespace

template <int dim>
void FluidSolver<dim>::save(Hdf5File& file, const std::string& group) const
{
  const_cast<FluidSolver*>(this)->finish_setup();
  const auto& p = particles_;
  const std::size_t n = p.size();
  file.ensure_group(group);
  file.write_attribute(group, "dim", std::int64_t(dim));
  file.write_attribute(group, "time", time_);
  file.write_attribute(group, "dt", dt_);
  file.write_attribute(group, "step", std::int64_t(step_));
  file.write_attribute(group, "verlet_counter", std::int64_t(verlet_counter_));
  file.write_attribute(group, "n_particles", std::int64_t(n));
  file.write_attribute(group, "n_boundary", std::int64_t(p.n_boundary));
  file.write(group + "/position", interleave(p.position, n), {n, std::size_t(dim)});
  file.write(group + "/velocity", interleave(p.velocity, n), {n, std::size_t(dim)});
  file.write(group + "/velocity_previous", interleave(p.velocity_previous, n),
             {n, std::size_t(dim)});
  if (!p.position_previous[0].empty())
    file.write(group + "/position_previous", interleave(p.position_previous, n),
               {n, std::size_t(dim)});
  file.write(group + "/density", widen(p.density), {n});
  file.write(group + "/density_previous", widen(p.density_previous), {n});
  file.write(group + "/id", std::vector<std::int64_t>(p.id.begin(), p.id.end()), {n});
  if (parameters_.scheme == TimeScheme::position_verlet && forces_current_)
  {
    // The next step's predictor and dt come from the last pass: a restart must not
    // recompute them (bitwise equal to the uninterrupted run).
    file.write(group + "/acceleration", interleave(p.acceleration, n), {n, std::size_t(dim)});
    file.write(group + "/density_rate", widen(p.density_rate), {n});
    file.write_attribute(group, "acceleration_max", acceleration_max_);
    file.write_attribute(group, "dot_rr2_max", double(dot_rr2_max_));
    file.write_attribute(group, "fastest_particle", std::int64_t(fastest_particle_));
  }
  for (std::size_t w = 0; w < walls_.size(); ++w)
  {
    const std::string g = group + "/walls/" + std::to_string(w);
    const std::size_t nv = walls_[w].vertices.size();
    std::vector<double> x(nv * dim), v(nv * dim);
    for (std::size_t k = 0; k < nv; ++k)
      for (int d = 0; d < dim; ++d)
      {
        x[k * dim + d] = walls_[w].vertices[k][d];
        v[k * dim + d] = walls_[w].velocities[k][d];
      }
    file.write(g + "/vertices", x, {nv, std::size_t(dim)});
    file.write(g + "/velocities", v, {nv, std::size_t(dim)});
  }
}

template <int dim>
void FluidSolver<dim>::load(const Hdf5File& file, const std::string& group)
{
  finish_setup();
  auto& p = particles_;
  const std::size_t n = p.size();
  const std::string where = file.path() + ":" + group;
  if (file.read_integer_attribute(group, "dim") != dim)
    throw InputError(where, "checkpoint of a different dimension");
  if (std::size_t(file.read_integer_attribute(group, "n_particles")) != n ||
      std::size_t(file.read_integer_attribute(group, "n_boundary")) != p.n_boundary)
    throw InputError(where, "checkpoint has a different particle count than the case (" +
                                std::to_string(n) + " particles, " + std::to_string(p.n_boundary) +
                                " boundary)");
  if (file.exists(group + "/position_previous") != !p.position_previous[0].empty())
    throw InputError(where, "checkpoint was written with another time scheme");
  time_ = file.read_double_attribute(group, "time");
  dt_ = file.read_double_attribute(group, "dt");
  step_ = file.read_integer_attribute(group, "step");
  verlet_counter_ = int(file.read_integer_attribute(group, "verlet_counter"));
  split(file.read_doubles(group + "/position"), p.position, n, where);
  split(file.read_doubles(group + "/velocity"), p.velocity, n, where);
  split(file.read_doubles(group + "/velocity_previous"), p.velocity_previous, n, where);
  if (!p.position_previous[0].empty())
    split(file.read_doubles(group + "/position_previous"), p.position_previous, n, where);
  const auto rho = file.read_doubles(group + "/density");
  const auto rho_prev = file.read_doubles(group + "/density_previous");
  const auto id = file.read_integers(group + "/id");
  if (rho.size() != n || rho_prev.size() != n || id.size() != n)
    throw InputError(where, "wrong array size in checkpoint");
  for (std::size_t i = 0; i < n; ++i)
  {
    p.density[i] = float(rho[i]);
    p.density_previous[i] = float(rho_prev[i]);
    p.id[i] = std::uint32_t(id[i]);
  }
  forces_current_ = false;
  if (parameters_.scheme == TimeScheme::position_verlet && file.exists(group + "/acceleration"))
  {
    split(file.read_doubles(group + "/acceleration"), p.acceleration, n, where);
    const auto rate = file.read_doubles(group + "/density_rate");
    if (rate.size() != n)
      throw InputError(where, "wrong array size in checkpoint");
    for (std::size_t i = 0; i < n; ++i)
      p.density_rate[i] = float(rate[i]);
    acceleration_max_ = file.read_double_attribute(group, "acceleration_max");
    dot_rr2_max_ = float(file.read_double_attribute(group, "dot_rr2_max"));
    fastest_particle_ = std::size_t(file.read_integer_attribute(group, "fastest_particle"));
    forces_current_ = true;
  }
  for (std::size_t w = 0; w < walls_.size(); ++w)
  {
    const std::string g = group + "/walls/" + std::to_string(w);
    const auto x = file.read_doubles(g + "/vertices");
    const auto v = file.read_doubles(g + "/velocities");
    const std::size_t nv = walls_[w].vertices.size();
    if (x.size() != nv * dim || v.size() != nv * dim)
      throw InputError(where, "wall " + std::to_string(w) + " has another vertex count");
    for (std::size_t k = 0; k < nv; ++k)
      for (int d = 0; d < dim; ++d)
      {
        walls_[w].vertices[k][d] = x[k * dim + d];
        walls_[w].velocities[k][d] = v[k * dim + d];
      }
  }
  boundary_moved_ = walls_moved_ = true;
}

template void FluidSolver<2>::save(Hdf5File&, const std::string&) const;
template void FluidSolver<3>::save(Hdf5File&, const std::string&) const;
template void FluidSolver<2>::load(const Hdf5File&, const std::string&);
template void FluidSolver<3>::load(const Hdf5File&, const std::string&);
} // namespace chipflex::sph
