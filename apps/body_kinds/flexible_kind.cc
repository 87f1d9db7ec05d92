// Body kind `flexible`: a reduced floating-frame body from a body file (`chipflex
// reduce`), 2D or 3D, free or with its frame clamped to the ground, linear or
// geometrically nonlinear (`reduce --nonlinear`, docs/nonlinear_bodies.md); its skin
// moves by Psi q.

#include "apps/body_kinds/body_kind.h"
#include "common/input_error.h"
#include "common/reduced_body_file.h"
#include "coupling/multibody_coupled_body.h"

namespace chipflex::apps
{
namespace
{
class FlexibleKind : public AnyDimensionKind<FlexibleKind>
{
public:
  std::string name() const override { return "flexible"; }
  std::string description() const override { return "flexible (reduced body file)"; }

  void declare(BodyKeyDeclarations& keys) const override
  {
    keys.declare("body file", "", "text", "HDF5 body file from `chipflex reduce`.");
    keys.declare("modes", "-1", "integer >= -1", "First n modes of the file; -1: all.");
    keys.declare("modal damping", "0", "double >= 0", "Damping ratio of every mode, -.");
    keys.declare("rayleigh mass", "0", "double >= 0", "Rayleigh alpha, 1/s.");
    keys.declare("rayleigh stiffness", "0", "double >= 0", "Rayleigh beta, s.");
    keys.declare("probe set", "tip", "text",
                 "Node set whose mean is the body's probe point (displacement output).");
  }

  template <int dim>
  static std::unique_ptr<coupling::CoupledBody<dim>> make(const BodyKeys& keys,
                                                          const BodyContext<dim>& context)
  {
    using Vector = Eigen::Matrix<double, dim, 1>;
    const std::string file = keys.file("body file");
    const ReducedBodyData data = read_reduced_body(file);
    if (data.dim != dim)
      throw InputError(file, "a " + std::to_string(data.dim) + "D body file in a " +
                                 std::to_string(dim) + "D case");
    const int modes = keys.integer("modes");
    if (modes == 0 || modes > data.n_modes())
      throw InputError(keys.at("modes"), "the file has " + std::to_string(data.n_modes()) +
                                             " modes, asked for " + std::to_string(modes));
    mbs::FloatingFrameOptions options;
    options.n_modes = modes;
    const double zeta = keys.number("modal damping"), alpha = keys.number("rayleigh mass"),
                 beta = keys.number("rayleigh stiffness");
    if (zeta > 0 && (alpha > 0 || beta > 0))
      throw InputError(keys.where() + ", damping",
                       "give either a modal damping ratio or Rayleigh coefficients, not both");
    if (zeta > 0)
    {
      options.damping = mbs::DampingKind::modal;
      options.modal_damping_ratio = zeta;
    }
    else if (alpha > 0 || beta > 0)
    {
      options.damping = mbs::DampingKind::rayleigh;
      options.rayleigh_mass = alpha;
      options.rayleigh_stiffness = beta;
    }
    auto system = make_body_system(context);
    auto body = std::make_unique<mbs::FloatingFrameBody<dim>>(data, options);
    const std::string probe_set = keys.text("probe set");
    std::vector<int> probe;
    if (data.node_sets.count(probe_set))
      probe = body->node_set(probe_set);
    else if (probe_set != "tip") // the default may be missing: the frame origin then
      body->node_set(probe_set); // InputError naming the missing set
    place_body(*body, context.placement);
    auto* skin = body.get();
    system->add_body(std::move(body));
    // The lowest normal mode kept (static correction modes and modal derivatives are
    // not natural modes).
    double first_frequency = 0;
    const int kept = modes < 0 ? data.n_modes() : modes;
    for (int k = 0; k < kept && k < int(data.mode_kinds.size()); ++k)
      if (data.mode_kinds[k] == "normal" && data.frequencies_hz[k] > 0 &&
          (first_frequency == 0 || data.frequencies_hz[k] < first_frequency))
        first_frequency = data.frequencies_hz[k];
    auto coupled = std::make_unique<coupling::MultibodyCoupledBody<dim>>(
        "flexible", std::move(system), *skin, context.max_step,
        [probe](const mbs::MultibodySystem<dim>& s)
        {
          if (probe.empty())
            return Vector(s.body(0).position());
          Vector sum = Vector::Zero();
          for (int n : probe)
            sum += s.body(0).node_position(n);
          return Vector(sum / double(probe.size()));
        });
    coupled->set_natural_frequency_hz(first_frequency);
    return coupled;
  }
};

const BodyKindRegistration registration(std::make_unique<FlexibleKind>());
} // namespace
} // namespace chipflex::apps
