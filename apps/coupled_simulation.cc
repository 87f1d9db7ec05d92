#include "apps/coupled_simulation.h"

#include "common/atomic_output.h"
#include "common/hdf5_file.h"
#include "common/input_error.h"
#include "coupling/fluid_overlap.h"
#include "sph/thin_skins.h"

#include <Eigen/Geometry>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace chipflex::apps
{
namespace
{
/// The probe histories are sampled at the multiples of this interval, interpolated
/// linearly between the two fluid steps around each: the CSV has the same times
/// whatever the particle spacing and time step (4000 rows for a 0.4 s run), so runs can
/// be compared row by row.
constexpr double sample_interval = 1e-4; // s
constexpr const char* axis_name[3] = {"x", "y", "z"};

/// 2D: the angle; 3D: the rotation vector (axis times angle).
template <int dim>
std::vector<double> rotation_probe(const Eigen::Matrix<double, dim, dim>& r)
{
  if constexpr (dim == 2)
    return {std::atan2(r(1, 0), r(0, 0))};
  else
  {
    const Eigen::AngleAxisd a(r);
    const Eigen::Vector3d v = a.angle() * a.axis();
    return {v[0], v[1], v[2]};
  }
}

/// `wall model = automatic`: a thin skin where the fluid on the skin's two sides would
/// interact through it. The fluid stands about dp/2 off each face, so pairs across a
/// skin of thickness t reach each other when t + dp < 2h; a skin thicker than that keeps
/// the former default (Lennard-Jones), so thick bodies' results do not move.
template <int dim>
void choose_wall_model(CaseBody<dim>& b, const sph::FluidParameters<dim>& fluid)
{
  sph::WallSurface<dim> skin;
  b.body->skin().skin_positions(skin.vertices);
  skin.faces = b.body->skin().skin_faces();
  const double t = sph::skin_thickness(skin);
  const double limit = 2 * fluid.smoothing_length() - fluid.particle_spacing;
  std::ostringstream note;
  note.precision(3);
  if (t < limit)
  {
    b.wall_model = sph::WallModel::thin_skin;
    note << "automatic: ";
    if (t > 0)
      note << "thickness " << 1e3 * t << " mm";
    else
      note << "an open skin";
    note << " < 2h - dp = " << 1e3 * limit << " mm";
  }
  else
  {
    b.wall_model = sph::WallModel::lennard_jones;
    note << "automatic: thickness " << 1e3 * t << " mm >= 2h - dp = " << 1e3 * limit << " mm";
  }
  b.wall_model_note = note.str();
}
} // namespace

template <int dim>
CoupledSimulation<dim>::CoupledSimulation(const sph::CaseDescription<dim>& fluid_case,
                                          BodyCase<dim> bodies, const std::string& output_directory,
                                          const ContactCase& contact, bool distributed)
    : fluid_(fluid_case, output_directory, distributed), case_(std::move(bodies)),
      skins_(output_directory, "skins"), started_(std::chrono::steady_clock::now())
{
  // Coupled momentum exchange is exact only with the symplectic fluid schemes (the
  // Verlet step's velocity update spans two steps): refuse the other rather than
  // silently losing momentum.
  if (!sph::is_symplectic(fluid_.description().fluid.scheme))
    throw InputError("time, scheme",
                     "a case with bodies needs the symplectic or position verlet scheme");
  // Fluid blocks ignore the bodies: drop the particles that start inside a body or
  // on its skin (closer than 0.4 dp; the lattice's half-spacing gap to a body face
  // placed on a lattice plane stays).
  const double dp = fluid_.description().fluid.particle_spacing;
  for (auto& b : case_.bodies)
  {
    std::vector<Vector> x;
    b.body->skin().skin_positions(x);
    const coupling::SkinOverlap<dim> overlap(x, b.body->skin().skin_faces(), 0.4 * dp);
    b.displaced_fluid = fluid_.fluid().remove_fluid_where(overlap);
  }
  cosim_ = std::make_unique<coupling::CoSimulation<dim>>(fluid_.fluid());
  for (auto& b : case_.bodies)
  {
    if (b.automatic_wall_model)
      choose_wall_model(b, fluid_.description().fluid);
    cosim_->add_body(*b.body, b.name, b.wall_model, b.lennard_jones);
    fluid_.exclude_from_wall_output(cosim_->fluid_wall_id(cosim_->n_bodies() - 1));
    probe_start_.push_back(b.probe_position());
    reference_skins_.emplace_back();
    b.body->skin().skin_positions(reference_skins_.back());
    histories_.emplace_back();
    last_step_.emplace_back();
  }
  if (contact.enabled)
    cosim_->enable_contact(contact.parameters);
  if (const auto& source = case_.chip_source; !source.bodies.empty())
  {
    coupling::ChipSourceSettings<dim> s;
    for (const std::string& name : source.bodies)
    {
      int found = -1;
      for (std::size_t b = 0; b < case_.bodies.size(); ++b)
        if (case_.bodies[b].name == name)
          found = int(b);
      if (found < 0)
        throw InputError("bodies/chip source, bodies", "no body named '" + name + "'");
      s.pool.push_back(found);
    }
    s.first_release = source.first_release;
    s.interval = source.interval;
    s.position = source.position;
    s.rotation = source.rotation;
    s.velocity = source.velocity;
    s.angular_velocity = source.angular_velocity;
    s.exit_point = source.exit_point;
    s.exit_normal = source.exit_normal;
    chip_source_ = std::make_unique<coupling::ChipSource<dim>>(*cosim_, s);
  }
  const auto& a = contact.torque_axis;
  if (!a.empty())
  {
    const std::size_t expected = dim == 3 ? 6 : 2;
    if (a.size() != expected)
      throw InputError("contact/torque axis",
                       dim == 3 ? "needs a point and a direction, x, y, z, ax, ay, az"
                                : "needs a point, x, y (2D torques are about z)");
    for (int d = 0; d < dim; ++d)
      torque_point_[d] = a[d];
    if constexpr (dim == 3)
    {
      torque_direction_ = Eigen::Vector3d(a[3], a[4], a[5]);
      if (!(torque_direction_.norm() > 0))
        throw InputError("contact/torque axis", "the direction must not be zero");
      torque_direction_.normalize();
    }
  }
  record();
}

template <int dim>
void CoupledSimulation<dim>::record()
{
  const double t = time();
  for (std::size_t b = 0; b < case_.bodies.size(); ++b)
  {
    auto& h = histories_[b];
    const Vector u = case_.bodies[b].probe_position() - probe_start_[b];
    Sample now;
    now[0] = t;
    for (int d = 0; d < dim; ++d)
      now[1 + d] = u[d];
    auto& last = last_step_[b];
    if (h.empty())
      h.push_back(now); // t = 0
    else
    {
      // Every sample time passed in this step, from the one after the last row on.
      for (long long k = std::llround(h.back()[0] / sample_interval) + 1;
           k * sample_interval <= t * (1 + 1e-12); ++k)
      {
        const double tk = k * sample_interval, w = (tk - last[0]) / (t - last[0]);
        Sample s;
        s[0] = tk;
        for (int d = 0; d < dim; ++d)
          s[1 + d] = last[1 + d] + w * (now[1 + d] - last[1 + d]);
        h.push_back(s);
      }
    }
    last = now;
  }
}

template <int dim>
void CoupledSimulation<dim>::advance()
{
  cosim_->step();
  record();
}

template <int dim>
ParticleFrame CoupledSimulation<dim>::frame() const
{
  std::vector<typename SurfaceOutput<dim>::Surface> skins;
  for (int b = 0; b < cosim_->n_bodies(); ++b)
  {
    const auto& wall = cosim_->skin_wall(b);
    const auto& skin = cosim_->body(b).skin();
    std::vector<Vector> x, v;
    skin.skin_positions(x);
    skin.skin_velocities(v);
    std::vector<Vector> u(x.size());
    for (std::size_t i = 0; i < x.size(); ++i)
      u[i] = x[i] - reference_skins_[b][i];
    skins.push_back({wall.surface().name,
                     x,
                     wall.surface().faces,
                     {{"displacement", "m", u},
                      {"velocity", "m/s", v},
                      {"fluid_force", dim == 2 ? "N/m" : "N", wall.delivered()},
                      {"contact_force", dim == 2 ? "N/m" : "N", wall.delivered_contact()}}});
  }
  if (fluid_.writes_outputs())
    skins_.write(time(), skins);
  return fluid_.frame();
}

namespace
{
/// A wall's name as a column name: spaces become underscores.
std::string column_name(std::string name)
{
  for (char& c : name)
    if (c == ' ' || c == ',')
      c = '_';
  return name;
}
} // namespace

template <int dim>
std::vector<std::string> CoupledSimulation<dim>::probe_columns() const
{
  auto columns = fluid_.probe_columns();
  // Contact reactions on every wall (tank, case walls, barriers, moving walls): the sum
  // of the forces the bodies' contacts put on it and their torque about the torque axis.
  if (const auto* contact = cosim_->contact())
    for (int o = 0; o < contact->n_obstacles(); ++o)
    {
      const std::string prefix = "contact_" + column_name(contact->obstacle(o).name);
      for (int d = 0; d < dim; ++d)
        columns.push_back(prefix + "_force_" + axis_name[d] + "_N");
      columns.push_back(prefix + "_torque_Nm");
    }
  for (const auto& b : case_.bodies)
  {
    for (int d = 0; d < dim; ++d)
      columns.push_back(b.name + "_d" + axis_name[d] + "_m");
    for (int d = 0; d < dim; ++d)
      columns.push_back(b.name + "_" + axis_name[d] + "_m");
    if (dim == 2)
      columns.push_back(b.name + "_angle_rad");
    else
      for (int d = 0; d < 3; ++d)
        columns.push_back(b.name + "_r" + axis_name[d] + "_rad");
    columns.push_back(b.name + "_deflection_m");
    columns.push_back(b.name + "_strain_energy_J");
    for (const auto& [name, value] : b.body->extra_probes())
      columns.push_back(b.name + "_" + name);
  }
  if (chip_source_)
  {
    for (int b : chip_source_->settings().pool)
      columns.push_back(case_.bodies[b].name + "_chip"); // the chip it carries, 0: parked
    for (const char* c : {"chips_released", "chips_removed", "chips_skipped", "chips_delayed"})
      columns.push_back(c);
  }
  return columns;
}

template <int dim>
std::vector<double> CoupledSimulation<dim>::probe_values() const
{
  auto values = fluid_.probe_values();
  if (const auto* contact = cosim_->contact())
    for (int o = 0; o < contact->n_obstacles(); ++o)
    {
      const auto& x = contact->obstacle(o).vertices;
      const auto& f = contact->obstacle_forces(o);
      Vector force = Vector::Zero();
      double torque = 0;
      for (std::size_t k = 0; k < f.size() && k < x.size(); ++k)
      {
        force += f[k];
        const Vector r = x[k] - torque_point_;
        if constexpr (dim == 2)
          torque += r[0] * f[k][1] - r[1] * f[k][0];
        else
          torque += torque_direction_.dot(r.cross(f[k]));
      }
      values.insert(values.end(), force.data(), force.data() + dim);
      values.push_back(torque);
    }
  for (std::size_t b = 0; b < case_.bodies.size(); ++b)
  {
    const auto& body = *case_.bodies[b].body;
    const Vector x = case_.bodies[b].probe_position();
    const Vector u = x - probe_start_[b];
    values.insert(values.end(), u.data(), u.data() + dim);
    values.insert(values.end(), x.data(), x.data() + dim);
    for (double r : rotation_probe<dim>(body.frame_rotation()))
      values.push_back(r);
    values.push_back(body.max_deflection());
    values.push_back(body.strain_energy());
    for (const auto& [name, value] : body.extra_probes())
      values.push_back(value);
  }
  if (chip_source_)
  {
    for (std::size_t k = 0; k < chip_source_->settings().pool.size(); ++k)
      values.push_back(double(chip_source_->chip_number(int(k))));
    values.push_back(double(chip_source_->released()));
    values.push_back(double(chip_source_->removed()));
    values.push_back(double(chip_source_->skipped()));
    values.push_back(double(chip_source_->delayed()));
  }
  return values;
}

template <int dim>
void CoupledSimulation<dim>::save(Hdf5File* file_pointer) const
{
  fluid_.save(file_pointer); // over MPI, the ranks' part of the gather
  if (!file_pointer)
    return;
  Hdf5File& file = *file_pointer;
  cosim_->save_bodies(file, "/bodies");
  if (chip_source_)
  {
    const auto state = chip_source_->state();
    file.write("/chip_source", state, {state.size()});
  }
  file.ensure_group("/probes");
  for (std::size_t b = 0; b < case_.bodies.size(); ++b)
  {
    const auto& h = histories_[b];
    std::vector<double> rows;
    for (const auto& s : h)
      rows.insert(rows.end(), s.begin(), s.end());
    file.write("/probes/" + case_.bodies[b].name, rows, {h.size(), std::size_t(1 + dim)});
  }
  const double wall =
      restored_wall_seconds_ +
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  file.write_attribute("/probes", "wall_seconds", wall);
}

template <int dim>
void CoupledSimulation<dim>::load(const Hdf5File& file)
{
  fluid_.load(file);
  cosim_->load_bodies(file, "/bodies");
  if (chip_source_)
  {
    if (!file.exists("/chip_source"))
      throw InputError(file.path(), "checkpoint has no chip source state (written without one)");
    chip_source_->restore(file.read_doubles("/chip_source"));
  }
  for (std::size_t b = 0; b < case_.bodies.size(); ++b)
  {
    std::vector<std::size_t> shape;
    const auto rows = file.read_doubles("/probes/" + case_.bodies[b].name, &shape);
    if (shape.size() != 2 || shape[1] != std::size_t(1 + dim))
      throw InputError("/probes/" + case_.bodies[b].name, "not a probe history of this case");
    histories_[b].clear();
    for (std::size_t i = 0; i < shape[0]; ++i)
    {
      Sample s;
      std::copy_n(&rows[(1 + dim) * i], 1 + dim, s.begin());
      histories_[b].push_back(s);
    }
  }
  // The step before the checkpoint's time is not needed: the next sample lies after it,
  // between the checkpoint's state (the one just loaded) and the next step.
  for (std::size_t b = 0; b < case_.bodies.size(); ++b)
  {
    const Vector u = case_.bodies[b].probe_position() - probe_start_[b];
    last_step_[b][0] = time();
    for (int d = 0; d < dim; ++d)
      last_step_[b][1 + d] = u[d];
  }
  skins_.resume(time());
  restored_wall_seconds_ = file.read_double_attribute("/probes", "wall_seconds");
  started_ = std::chrono::steady_clock::now();
}

template <int dim>
std::string CoupledSimulation<dim>::summary() const
{
  std::ostringstream s;
  s << fluid_.summary();
  for (const auto& b : case_.bodies)
    s << "\nbody '" << b.name << "': " << b.body->kind() << ", " << b.body->skin().n_skin_nodes()
      << " skin nodes, " << sph::wall_model_name(b.wall_model) << " wall"
      << (b.wall_model_note.empty() ? std::string() : " (" + b.wall_model_note + ")")
      << (b.displaced_fluid
              ? ", " + std::to_string(b.displaced_fluid) + " fluid particles inside it removed"
              : std::string());
  if (chip_source_)
  {
    const auto& c = chip_source_->settings();
    s << "\nchip source: " << c.pool.size() << " bodies in its pool, a chip every " << c.interval
      << " s from " << c.first_release << " s";
  }
  if (const auto* contact = cosim_->contact())
    s << "\ncontact: restitution " << contact->parameters().restitution << ", friction "
      << contact->parameters().friction << ", " << contact->n_obstacles() << " walls";
  return s.str();
}

template <int dim>
std::string CoupledSimulation<dim>::finish(const std::string& output_directory) const
{
  const double wall =
      restored_wall_seconds_ +
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  std::ostringstream line;
  line << std::fixed << std::setprecision(2);
  for (std::size_t b = 0; b < case_.bodies.size(); ++b)
  {
    const auto& body = case_.bodies[b];
    const auto& h = histories_[b];
    if (fluid_.writes_outputs())
    {
      const std::string path = output_directory + "/" + body.name + "_displacement.csv";
      AtomicOutput output(path);
      {
        std::ofstream out(output.temporary_path());
        out << "time_s";
        for (int d = 0; d < dim; ++d)
          out << ",d" << axis_name[d] << "_m";
        out << '\n' << std::setprecision(10);
        for (const auto& s : h)
        {
          out << s[0];
          for (int d = 0; d < dim; ++d)
            out << ',' << s[1 + d];
          out << '\n';
        }
        if (!out)
          throw InputError(path, "write failed");
      }
      output.commit();
    }
    line << "summary: body=" << body.name << " kind=" << body.body->kind();
    // Magnitudes, not signed values: a body that moved only towards -y (a sinking
    // sphere) must not report 0.
    Vector largest = Vector::Zero();
    double largest_norm = 0;
    for (const auto& s : h)
    {
      double norm2 = 0;
      for (int d = 0; d < dim; ++d)
      {
        largest[d] = std::max(largest[d], std::abs(s[1 + d]));
        norm2 += s[1 + d] * s[1 + d];
      }
      largest_norm = std::max(largest_norm, std::sqrt(norm2));
    }
    line << " max_displacement_mm=" << largest_norm * 1e3;
    for (int d = 0; d < dim; ++d)
      line << " max_abs_d" << axis_name[d] << "_mm=" << largest[d] * 1e3;
    line << " dp_mm=" << fluid_.description().fluid.particle_spacing * 1e3
         << " particles=" << fluid_.n_fluid_particles() + cosim_->fluid().n_boundary()
         << " lost_particles=" << n_lost_particles()
         << " peak_fluid_speed_m_s=" << peak_fluid_speed() << " steps=" << step_count()
         << " wall_s=" << wall << (b + 1 < case_.bodies.size() ? "\n" : "");
  }
  if (chip_source_)
    line << "\nsummary: chip_source released=" << chip_source_->released()
         << " removed=" << chip_source_->removed() << " skipped=" << chip_source_->skipped()
         << " in_segment=" << chip_source_->released() - chip_source_->removed()
         << " delayed=" << chip_source_->delayed();
  return line.str();
}

template <int dim>
std::vector<std::pair<std::string, double>> CoupledSimulation<dim>::natural_frequencies() const
{
  std::vector<std::pair<std::string, double>> f;
  for (const auto& b : case_.bodies)
    if (b.body->natural_frequency_hz() > 0)
      f.emplace_back("body " + b.name + "'s first natural frequency",
                     b.body->natural_frequency_hz());
  return f;
}

template class CoupledSimulation<2>;
template class CoupledSimulation<3>;
} // namespace chipflex::apps
