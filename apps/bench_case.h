#pragma once
// `chipflex bench case CASE.prm`: the wall time per step of any case file.

#include "apps/commands.h"

namespace chipflex::apps
{
int bench_case(const Arguments& args);
} // namespace chipflex::apps
