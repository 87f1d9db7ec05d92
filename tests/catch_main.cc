// Catch2's main for the test executables that need no MPI.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
