// The RMS error definition of data/antoci2007/README.md: frames 0.04 ... 0.36 s of
// experiment_merged.csv, model curve interpolated linearly. Reference: the errors the
// README quotes for the published curves (Antoci SPH 4.3 / 2.3 mm, Khayyer 8.1 / 4.6,
// Yang 10.6 / 5.8), reproduced from the digitised curves to the quoted 0.1 mm.

#include "common/input_error.h"
#include "coupling/displacement_history.h"

#include <catch2/catch.hpp>
#include <filesystem>

using chipflex::coupling::DisplacementHistory;

namespace
{
const std::string data = std::string(CHIPFLEX_SOURCE_DIR) + "/data/antoci2007/";

void check_published(const std::string& stem, double rms_dx_mm, double rms_dy_mm)
{
  const auto experiment = DisplacementHistory::read_csv(data + "experiment_merged.csv");
  const auto dx = DisplacementHistory::read_csv(data + stem + "_dx.csv", 0);
  const auto dy = DisplacementHistory::read_csv(data + stem + "_dy.csv", 1);
  CHECK(dx.rms_error(experiment, 0.04, 0.36, true).rms_dx * 1e3 == Approx(rms_dx_mm).margin(0.051));
  CHECK(dy.rms_error(experiment, 0.04, 0.36, true).rms_dy * 1e3 == Approx(rms_dy_mm).margin(0.051));
  // Without skipping, a curve that ends early is refused rather than extrapolated.
  if (dx.time().back() < 0.36)
    CHECK_THROWS_AS(dx.rms_error(experiment, 0.04, 0.36), chipflex::InputError);
  else
    CHECK(dx.rms_error(experiment, 0.04, 0.36).frames == 9);
}
} // namespace

TEST_CASE("published gate curves give the published RMS errors", "[coupling]")
{
  check_published("antoci2007_sph", 4.3, 2.3);
  check_published("khayyer2018_isph_sph", 8.1, 4.6);
  check_published("yang2012_sph_fem", 10.6, 5.8);
}

TEST_CASE("displacement history interpolates, round-trips and refuses extrapolation", "[coupling]")
{
  DisplacementHistory h;
  h.append(0.0, 0.0, 0.0);
  h.append(0.1, 1.0, -2.0);
  h.append(0.3, 3.0, 2.0);
  CHECK(h.interpolate(0.05, 0) == Approx(0.5));
  CHECK(h.interpolate(0.2, 1) == Approx(0.0).margin(1e-12));
  CHECK_THROWS_AS(h.interpolate(0.31, 0), chipflex::InputError);

  // In the system temporary folder: tests never write into the working tree.
  const std::string path =
      (std::filesystem::temp_directory_path() / "chipflex_history_roundtrip.csv").string();
  h.write_csv(path);
  const auto back = DisplacementHistory::read_csv(path);
  REQUIRE(back.size() == 3);
  CHECK(back.dy()[1] == -2.0);
  // A model identical to the reference has zero error; a shifted one its shift.
  DisplacementHistory ref;
  ref.append(0.1, 1.0, -2.0);
  ref.append(0.2, 2.0, 0.0);
  CHECK(h.rms_error(ref, 0, 1).rms_dx == Approx(0.0).margin(1e-15));
  DisplacementHistory shifted;
  for (std::size_t i = 0; i < h.size(); ++i)
    shifted.append(h.time()[i], h.dx()[i] + 0.003, h.dy()[i]);
  CHECK(shifted.rms_error(ref, 0, 1).rms_dx == Approx(0.003));

  h.truncate_after(0.1);
  CHECK(h.size() == 2);
}
