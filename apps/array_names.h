#pragma once
// The names ParaView shows for the arrays of the XDMF outputs carry their unit, so that a
// user sees "pressure_Pa" in the array list, the colour legend and the spreadsheet
// (readers show no XDMF Information). The HDF5 datasets keep the bare names ("pressure"),
// which scripts read. docs/output.md lists both.

#include <string>

namespace chipflex::apps
{
/// `name` + "_" + `unit` with the unit spelt with letters, digits and '_' only
/// ("m/s" -> "velocity_m_s", "kg/m^3" -> "density_kg_m3"); `name` alone for a unit
/// "-" or "" (dimensionless numbers and labels).
std::string name_with_unit(const std::string& name, const std::string& unit);
} // namespace chipflex::apps
