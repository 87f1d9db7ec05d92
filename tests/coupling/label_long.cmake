# Included by CTest after the discovered Catch tests. The 3D plates under a water column
# (about 3.5 minutes each on 2 cores here, over 11 minutes on a slower 2-core machine) carry
# the label `long`: scripts/test.sh leaves it out unless CHIPFLEX_LONG_TESTS=1, and
# `ctest -L long` runs it.
set_tests_properties(
  "a clamped 3D plate under a water column deflects as the FE static solution"
  PROPERTIES LABELS "validation;long" PROCESSORS 2)
set_tests_properties(
  "a thin 3D steel flap under a water column deflects as the FE static solution"
  PROPERTIES LABELS "validation;long" PROCESSORS 2)
