// SlabDecomposition: owners and ghost ranks at slab bounds, thin and empty slabs, and the
// balanced cuts (the MPI exchange itself is checked by mpi_fluid_check under mpirun).

#include "sph/slab_decomposition.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <vector>

using chipflex::sph::SlabDecomposition;

namespace
{
std::vector<int> ghost_ranks(const SlabDecomposition& s, double x, double y = 0)
{
  const double point[2] = {x, y};
  std::vector<int> out;
  s.for_each_ghost_rank(point, s.owner(point), [&](int r) { out.push_back(r); });
  return out;
}

int owner(const SlabDecomposition& s, double x, double y = 0)
{
  const double point[2] = {x, y};
  return s.owner(point);
}
} // namespace

TEST_CASE("slabs: every point has one owner, the bounds belong to the upper slab")
{
  const SlabDecomposition s(0, {1.0, 2.0}, 0.25);
  CHECK(owner(s, -1e300) == 0);
  CHECK(owner(s, 0.999) == 0);
  CHECK(owner(s, 1.0) == 1);
  CHECK(owner(s, 1.999) == 1);
  CHECK(owner(s, 2.0) == 2);
  CHECK(owner(s, 1e300) == 2);
  CHECK(owner(s, std::numeric_limits<double>::quiet_NaN()) == -1);
  // The other axis does not matter.
  const SlabDecomposition along_y(1, {1.0}, 0.25);
  CHECK(owner(along_y, 5.0, 0.5) == 0);
  CHECK(owner(along_y, -5.0, 1.5) == 1);
}

TEST_CASE("slabs: a point is a ghost on the neighbours within the halo width")
{
  const SlabDecomposition s(0, {1.0, 2.0}, 0.25);
  CHECK(ghost_ranks(s, 0.5).empty());
  CHECK(ghost_ranks(s, 0.76) == std::vector<int>{1});
  CHECK(ghost_ranks(s, 0.75) == std::vector<int>{1}); // the halo's lower end is inside
  CHECK(ghost_ranks(s, 0.74).empty());
  CHECK(ghost_ranks(s, 1.2) == std::vector<int>{0}); // 1.2 < 1 + 0.25
  CHECK(ghost_ranks(s, 1.25).empty());               // the upper end is outside
  CHECK(ghost_ranks(s, 1.8) == std::vector<int>{2});
  CHECK(ghost_ranks(s, 1e9).empty());
}

TEST_CASE("slabs: a slab thinner than the halo sends its particles two ranks on")
{
  // Slab 1 is [1, 1.1): a particle in slab 0 near 1 is a ghost on 1 and on 2.
  const SlabDecomposition s(0, {1.0, 1.1}, 0.25);
  CHECK(ghost_ranks(s, 0.9) == std::vector<int>{1, 2});
  CHECK(ghost_ranks(s, 1.05) == std::vector<int>{0, 2});
  CHECK(ghost_ranks(s, 1.2) == std::vector<int>{0, 1});
  CHECK(ghost_ranks(s, 1.3) == std::vector<int>{1});
}

TEST_CASE("slabs: the ranks beside a wide stretch (a buffer) get its halo, the others not")
{
  // An inlet buffer at [-0.1, 0] in slab 0, an outlet buffer at [3, 3.1] in slab 2; slab
  // 1 [1, 2) touches neither and keeps 0.25.
  const SlabDecomposition s(0, {1.0, 2.0}, 0.25, {{-0.1, 0.0, 0.6}, {3.0, 3.1, 0.5}});
  CHECK(s.halo_width() == 0.25);
  CHECK(s.halo_width(0) == 0.6);
  CHECK(s.halo_width(1) == 0.25);
  CHECK(s.halo_width(2) == 0.5);
  // Slab 1's particles: a ghost on slab 0 below 1 + 0.6, on slab 2 from 2 - 0.5.
  CHECK(ghost_ranks(s, 1.45) == std::vector<int>{0});
  CHECK(ghost_ranks(s, 1.5) == std::vector<int>{0, 2});
  CHECK(ghost_ranks(s, 1.6) == std::vector<int>{2}); // slab 0's upper end is outside
  // Slab 0's particles reach slab 1 within its own 0.25 only.
  CHECK(ghost_ranks(s, 0.8) == std::vector<int>{1});
  CHECK(ghost_ranks(s, 0.7).empty());
  // A stretch across a cut widens both slabs beside it.
  const SlabDecomposition across(0, {1.0, 2.0}, 0.25, {{0.9, 1.1, 0.4}});
  CHECK(across.halo_width(0) == 0.4);
  CHECK(across.halo_width(1) == 0.4);
  CHECK(across.halo_width(2) == 0.25);
  CHECK(across.wide_halos().size() == 1);
}

TEST_CASE("slabs: empty slabs own nothing and receive no ghosts")
{
  // Ranks 1 and 2 have empty slabs [1, 1).
  const SlabDecomposition s(0, {1.0, 1.0, 1.0}, 0.25);
  CHECK(s.empty(1));
  CHECK(s.empty(2));
  CHECK_FALSE(s.empty(3));
  for (const double x : {0.5, 0.99, 1.0, 1.01, 3.0})
  {
    CHECK(owner(s, x) != 1);
    CHECK(owner(s, x) != 2);
  }
  CHECK(owner(s, 1.0) == 3);
  CHECK(ghost_ranks(s, 0.9) == std::vector<int>{3});
  CHECK(ghost_ranks(s, 1.1) == std::vector<int>{0});
}

TEST_CASE("slabs: balanced cuts split the particle count evenly on layer bounds")
{
  // 10 layers of width 0.5 from x = 2, 100 particles each: four ranks cut at 25 %, 50 %,
  // 75 %, i.e. after 3 (300 >= 250), 5 and 8 layers.
  const std::vector<double> even(10, 100);
  const auto cuts = SlabDecomposition::balanced_cuts(even, 2.0, 0.5, 4);
  REQUIRE(cuts.size() == 3);
  CHECK(cuts[0] == 2.0 + 3 * 0.5);
  CHECK(cuts[1] == 2.0 + 5 * 0.5);
  CHECK(cuts[2] == 2.0 + 8 * 0.5);
  const SlabDecomposition s(0, cuts, 1.0);
  CHECK(s.loads(even, 2.0, 0.5) == std::vector<double>{300, 200, 300, 200});

  // All particles in one layer: the other ranks get empty slabs, one rank holds them all.
  std::vector<double> lump(10, 0);
  lump[4] = 1000;
  const SlabDecomposition lumped(0, SlabDecomposition::balanced_cuts(lump, 0.0, 1.0, 3), 1.0);
  const auto loads = lumped.loads(lump, 0.0, 1.0);
  CHECK(loads[0] + loads[1] + loads[2] == 1000);
  CHECK((loads[0] == 1000 || loads[1] == 1000 || loads[2] == 1000));

  // One rank: no cuts.
  CHECK(SlabDecomposition::balanced_cuts(even, 0.0, 1.0, 1).empty());
}
