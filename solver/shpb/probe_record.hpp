// Probe records: each SHPB assembly declares what it records at every output step as a list of
// {name, unit, description, sampler}, the value's function next to its name. Nothing lines up a
// list of values with a list of names by position: run() makes its RunResult probes from these
// records, entry for entry, and each sample is the record's own sampler.
//   Lifetime: a sampler reads the assembly (or specimen) it was made from by reference, so a
//   record list is valid while that object stays where it is. SimulatedShpb::run() asks for the
//   list at its start and drops it at its end; declared_probes() keeps the text only.
//   Cost: one std::function call per probe per output step; nothing per step or per grain.
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace kolsky::shpb {

struct ProbeRecord {
  std::string name;         ///< unique within a run; the HDF5 group /probes/<name>
  std::string unit;         ///< SI ("Pa", "J", "m/s"; "1" for a pure number)
  std::string description;  ///< one line, for people
  /// The value at the output time t^n, after step n and the assembly's observe(t^n).
  std::function<double(double t)> sample;
};
using ProbeRecords = std::vector<ProbeRecord>;

/// Gauge probe names: the first gauge of a bar is "<bar>_gauge_strain", gauge k + 1 (k >= 1)
/// "<bar>_gauge_strain_<k+1>"; bar is "incident" or "transmission". kolsky analyze, the
/// --gauges-csv output and waves_from_gauges read the first ones.
inline std::string gauge_probe_name(const std::string& bar, std::size_t k) {
  return k == 0 ? bar + "_gauge_strain" : bar + "_gauge_strain_" + std::to_string(k + 1);
}

}  // namespace kolsky::shpb
