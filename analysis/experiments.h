#pragma once
// The paper's experiment table (scenarios.md, "Experiments the paper ran") as sweeps, and the
// numbers the paper reports for them.
#include <optional>
#include <string>
#include <vector>

#include "scenarios/sweep.h"

namespace canopy::analysis {

/// One row group of the paper's table.
struct Experiment {
  std::string scenario;  // library name; also the sweep's name and directory
  scenarios::SweepSpec sweep;
  bool ownership = false;  // analysed by ownership (TH, RA) or by occlusion (JE, OS)
};

/// TH and RA: SMA-NBO and Dec-POMDP × H ∈ {1, 5}; JE and OS: SMA-NBO, H = 5, × occlusion map
/// ∈ {a-priori, dynamic, none}; `trials` per configuration (the paper: 40, 560 trials in all).
std::vector<Experiment> paperExperiments(int trials, std::uint64_t seed);

/// The sensitivity studies of scenarios/sweeps/ (ra_distance_horizon, je_occlusion_spacing), with
/// `trials` per configuration and the given seed; `ownership` as above.
std::vector<Experiment> sensitivityStudies(int trials, std::uint64_t seed);

/// What the paper reports for the frequency of the cooperative state M*_L (Sankey figures).
struct PaperOwnership {
  std::string scenario, algorithm;  // "sma" / "dec_pomdp"
  int horizon = 0;
  std::optional<double> at_half;  // fraction of trials in M* at k = L/2
  std::optional<double> at_end;   // … at k = L
  std::string note;
};
const std::vector<PaperOwnership>& paperOwnership();

}  // namespace canopy::analysis
