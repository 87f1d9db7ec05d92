// A minimal FMI 2.0 co-simulation master for the shell test export_fmu.sh: runs an FMU
// under a step load (a total force on a node set from t = 0) with communication steps of
// DT, and writes time, |q|, kinetic and strain energy as CSV (17 digits), the columns of
// `chipflex simulate`'s output it is compared with.
//   usage: fmu_step_response FMU UNPACK_DIR SET FX FY DT END CLAMPED(0|1) OUT.csv

#include "fmu_loader.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>

int main(int argc, char** argv)
{
  if (argc != 10)
  {
    std::cerr << "usage: fmu_step_response FMU UNPACK_DIR SET FX FY DT END CLAMPED OUT.csv\n";
    return 2;
  }
  try
  {
    const chipflex::test::LoadedFmu f(argv[1], argv[2]);
    const std::string set = argv[3];
    const double fx = std::stod(argv[4]), fy = std::stod(argv[5]), dt = std::stod(argv[6]),
                 end = std::stod(argv[7]);
    const fmi2Boolean clamped = std::stoi(argv[8]) ? fmi2True : fmi2False;
    const auto& fmi = f.fmi();
    fmi2Component c =
        fmi.Instantiate("step", fmi2CoSimulation, f.guid().c_str(), f.resource_uri().c_str(),
                        &chipflex::test::test_callbacks(), fmi2False, fmi2False);
    const auto check = [&](fmi2Status s, const char* what)
    {
      if (s != fmi2OK)
        throw std::runtime_error(
            std::string(what) + " failed: " +
            (chipflex::test::logged().empty() ? "" : chipflex::test::logged().back().message));
    };
    if (!c)
      check(fmi2Error, "fmi2Instantiate");
    check(fmi.SetupExperiment(c, fmi2False, 0, 0, fmi2True, end), "fmi2SetupExperiment");
    const fmi2ValueReference clamp_vr = f.vr("clamped"), step_vr = f.vr("step_size");
    check(fmi.SetBoolean(c, &clamp_vr, 1, &clamped), "fmi2SetBoolean");
    check(fmi.SetReal(c, &step_vr, 1, &dt), "fmi2SetReal");
    check(fmi.EnterInitializationMode(c), "fmi2EnterInitializationMode");
    const fmi2ValueReference load[2] = {f.vr("set." + set + ".force.x"),
                                        f.vr("set." + set + ".force.y")};
    const double value[2] = {fx, fy};
    check(fmi.SetReal(c, load, 2, value), "fmi2SetReal");
    check(fmi.ExitInitializationMode(c), "fmi2ExitInitializationMode");
    std::vector<fmi2ValueReference> q;
    while (f.has("q[" + std::to_string(q.size()) + "]"))
      q.push_back(f.vr("q[" + std::to_string(q.size()) + "]"));
    const fmi2ValueReference energies[2] = {f.vr("kinetic_energy"), f.vr("strain_energy")};
    std::ofstream out(argv[9]);
    out << "time_s,q_norm,kinetic_J,strain_J\n" << std::setprecision(17);
    const long n = std::lround(end / dt);
    for (long s = 0; s <= n; ++s)
    {
      if (s > 0)
        check(fmi.DoStep(c, (s - 1) * dt, dt, fmi2True), "fmi2DoStep");
      std::vector<double> qv(q.size());
      double e[2];
      check(fmi.GetReal(c, q.data(), q.size(), qv.data()), "fmi2GetReal");
      check(fmi.GetReal(c, energies, 2, e), "fmi2GetReal");
      double norm = 0;
      for (double x : qv)
        norm += x * x;
      out << s * dt << "," << std::sqrt(norm) << "," << e[0] << "," << e[1] << "\n";
    }
    check(fmi.Terminate(c), "fmi2Terminate");
    fmi.FreeInstance(c);
  }
  catch (const std::exception& e)
  {
    std::cerr << "fmu_step_response: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
