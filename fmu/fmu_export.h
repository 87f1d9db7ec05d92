#pragma once
// `chipflex export fmu`: packs a body file into an FMI 2.0 co-simulation FMU,
//   modelDescription.xml
//   binaries/linux64/<modelIdentifier>.so   (the chipflex body runtime, libchipflex_fmi.so)
//   resources/body.h5                       (the body file, byte for byte)
// stored uncompressed in a zip archive with fixed time stamps: the same body file and
// runtime always give the same FMU bytes, and the GUID depends on the body file alone.

#include <string>

namespace chipflex::fmu
{
struct FmuExportOptions
{
  std::string runtime_library;                    ///< path of libchipflex_fmi.so
  std::string model_identifier = "chipflex_body"; ///< a C identifier
  double default_step = 1e-4;                     ///< DefaultExperiment stepSize, s
  double default_stop = 0.1;                      ///< DefaultExperiment stopTime, s
};

struct FmuExportSummary
{
  std::string guid;
  std::size_t n_variables = 0, n_inputs = 0, n_outputs = 0, n_parameters = 0;
};

/// Reads and checks the body file (InputError naming it if it is not one), then writes
/// the FMU atomically (nothing is left at fmu_path on failure).
FmuExportSummary export_fmu(const std::string& body_path, const std::string& fmu_path,
                            const FmuExportOptions& options);
} // namespace chipflex::fmu
