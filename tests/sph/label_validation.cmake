# Included by CTest after the discovered Catch tests: the long validation runs.
set_tests_properties(
  "hydrostatic tank: pressure within 2 % of rho g (H - y) and walls hold"
  "dam break surge front follows Martin and Moyce 1952"
  "open-boundary channel reaches the Poiseuille profile and inflow equals outflow"
  PROPERTIES LABELS "sph;validation" PROCESSORS 2)
