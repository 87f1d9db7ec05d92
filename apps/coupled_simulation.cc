#include "apps/coupled_simulation.h"

#include "common/hdf5_file.h"
#include "common/input_error.h"
#include "coupling/body_factory.h"

#include <iomanip>
#include <sstream>

namespace chipflex::apps
{
namespace
{
/// Probe samples closer than this are not stored (the CSV stays ~4000 rows for a
/// 0.4 s run whatever the particle spacing).
constexpr double sample_interval = 1e-4; // s
} // namespace

CoupledSimulation::CoupledSimulation(const sph::CaseDescription<2>& fluid_case,
                                     const BodyCase& bodies, const std::string& output_directory,
                                     const ContactCase& contact)
    : fluid_(fluid_case, output_directory), case_(bodies), skins_(output_directory, "skins"),
      started_(std::chrono::steady_clock::now())
{
  // Coupled momentum exchange is exact only with the symplectic fluid schemes (the
  // Verlet step's velocity update spans two steps): refuse the other rather than
  // silently losing momentum.
  if (!sph::is_symplectic(fluid_.description().fluid.scheme))
    throw InputError("time, scheme",
                     "a case with bodies needs the symplectic or position verlet scheme");
  cosim_ = std::make_unique<coupling::CoSimulation<2>>(fluid_.fluid());
  for (const auto& d : case_.bodies)
  {
    bodies_.push_back(coupling::make_coupled_body(d, fluid_.description().fluid.gravity));
    cosim_->add_body(*bodies_.back(), d.name, d.wall_model, d.lennard_jones, d.expected_pressure);
    fluid_.exclude_from_wall_output(cosim_->fluid_wall_id(cosim_->n_bodies() - 1));
    probe_start_.push_back(bodies_.back()->probe_position());
    reference_skins_.emplace_back();
    bodies_.back()->skin().skin_positions(reference_skins_.back());
    histories_.emplace_back();
  }
  if (contact.enabled)
    cosim_->enable_contact(contact.parameters);
  record();
}

void CoupledSimulation::record()
{
  const double t = time();
  for (std::size_t b = 0; b < bodies_.size(); ++b)
  {
    auto& h = histories_[b];
    if (!h.empty() && t - h.time().back() < sample_interval * (1 - 1e-9))
      continue;
    const Eigen::Vector2d u = bodies_[b]->probe_position() - probe_start_[b];
    h.append(t, u.x(), u.y());
  }
}

void CoupledSimulation::advance()
{
  cosim_->step();
  record();
}

ParticleFrame CoupledSimulation::frame() const
{
  std::vector<SurfaceOutput<2>::Surface> skins;
  for (int b = 0; b < cosim_->n_bodies(); ++b)
  {
    const auto& wall = cosim_->skin_wall(b);
    const auto& skin = cosim_->body(b).skin();
    std::vector<Eigen::Vector2d> x, v;
    skin.skin_positions(x);
    skin.skin_velocities(v);
    std::vector<Eigen::Vector2d> u(x.size());
    for (std::size_t i = 0; i < x.size(); ++i)
      u[i] = x[i] - reference_skins_[b][i];
    skins.push_back({wall.surface().name,
                     x,
                     wall.surface().faces,
                     {{"displacement", "m", u},
                      {"velocity", "m/s", v},
                      {"fluid_force", "N/m", wall.delivered()},
                      {"contact_force", "N/m", wall.delivered_contact()}}});
  }
  skins_.write(time(), skins);
  return fluid_.frame();
}

std::vector<std::string> CoupledSimulation::probe_columns() const
{
  auto columns = fluid_.probe_columns();
  for (const auto& d : case_.bodies)
  {
    columns.push_back(d.name + "_dx_m");
    columns.push_back(d.name + "_dy_m");
  }
  return columns;
}

std::vector<double> CoupledSimulation::probe_values() const
{
  auto values = fluid_.probe_values();
  for (std::size_t b = 0; b < bodies_.size(); ++b)
  {
    const Eigen::Vector2d u = bodies_[b]->probe_position() - probe_start_[b];
    values.push_back(u.x());
    values.push_back(u.y());
  }
  return values;
}

void CoupledSimulation::save(Hdf5File& file) const
{
  fluid_.save(file);
  cosim_->save_bodies(file, "/bodies");
  file.ensure_group("/probes");
  for (std::size_t b = 0; b < bodies_.size(); ++b)
  {
    const auto& h = histories_[b];
    std::vector<double> rows;
    for (std::size_t i = 0; i < h.size(); ++i)
      rows.insert(rows.end(), {h.time()[i], h.dx()[i], h.dy()[i]});
    file.write("/probes/" + case_.bodies[b].name, rows, {h.size(), 3});
  }
  const double wall =
      restored_wall_seconds_ +
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  file.write_attribute("/probes", "wall_seconds", wall);
}

void CoupledSimulation::load(const Hdf5File& file)
{
  fluid_.load(file);
  cosim_->load_bodies(file, "/bodies");
  for (std::size_t b = 0; b < bodies_.size(); ++b)
  {
    std::vector<std::size_t> shape;
    const auto rows = file.read_doubles("/probes/" + case_.bodies[b].name, &shape);
    coupling::DisplacementHistory h;
    for (std::size_t i = 0; i < shape.at(0); ++i)
      h.append(rows[3 * i], rows[3 * i + 1], rows[3 * i + 2]);
    histories_[b] = h;
  }
  skins_.resume(time());
  restored_wall_seconds_ = file.read_double_attribute("/probes", "wall_seconds");
  started_ = std::chrono::steady_clock::now();
}

std::string CoupledSimulation::summary() const
{
  std::ostringstream s;
  s << fluid_.summary();
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    s << "\nbody '" << case_.bodies[b].name << "': " << bodies_[b]->kind() << ", "
      << bodies_[b]->skin().n_skin_nodes() << " skin nodes, "
      << (case_.bodies[b].wall_model == sph::WallModel::lennard_jones ? "Lennard-Jones"
                                                                      : "dummy-particle")
      << " wall";
  if (const auto* contact = cosim_->contact())
    s << "\ncontact: restitution " << contact->parameters().restitution << ", friction "
      << contact->parameters().friction << ", " << contact->n_obstacles() << " walls";
  return s.str();
}

std::string CoupledSimulation::finish(const std::string& output_directory) const
{
  const double wall =
      restored_wall_seconds_ +
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  std::ostringstream line;
  line << std::fixed << std::setprecision(2);
  for (std::size_t b = 0; b < bodies_.size(); ++b)
  {
    const auto& name = case_.bodies[b].name;
    histories_[b].write_csv(output_directory + "/" + name + "_displacement.csv");
    line << "summary: body=" << name << " kind=" << bodies_[b]->kind();
    if (b == 0 && !case_.reference_file.empty())
    {
      const auto reference = coupling::DisplacementHistory::read_csv(case_.reference_file);
      if (time() + 1e-9 >= case_.error_window_end)
      {
        const auto e =
            histories_[b].rms_error(reference, case_.error_window_begin, case_.error_window_end);
        line << " rms_dx_mm=" << e.rms_dx * 1e3 << " rms_dy_mm=" << e.rms_dy * 1e3
             << " frames=" << e.frames;
      }
      else
        line << " rms=n/a(run ends before " << case_.error_window_end << " s)";
    }
    const auto& h = histories_[b];
    double dx_max = 0, dy_max = 0;
    for (std::size_t i = 0; i < h.size(); ++i)
    {
      dx_max = std::max(dx_max, h.dx()[i]);
      dy_max = std::max(dy_max, h.dy()[i]);
    }
    line << " max_dx_mm=" << dx_max * 1e3 << " max_dy_mm=" << dy_max * 1e3;
    line << " dp_mm=" << fluid_.description().fluid.particle_spacing * 1e3
         << " particles=" << cosim_->fluid().n_particles()
         << " lost_particles=" << n_lost_particles()
         << " peak_fluid_speed_m_s=" << peak_fluid_speed() << " steps=" << step_count()
         << " wall_s=" << wall << (b + 1 < bodies_.size() ? "\n" : "");
  }
  return line.str();
}
} // namespace chipflex::apps
