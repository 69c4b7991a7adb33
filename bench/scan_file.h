#pragma once
// Scans for the tracking bench, as text anyone can write or read (docs/output-formats.md, "Scan
// files"): a header with the scene's parameters, then per scan the true target positions and the
// detections (target-originated and clutter, unlabelled).
#include <cstdint>
#include <iosfwd>
#include <stdexcept>
#include <string>
#include <vector>

#include "agents/config.h"
#include "core/types.h"

namespace canopy::bench {

struct ScanFileTruth {
  int id = 0;     // target identity, constant over scans
  Vec2 position;  // m
};

struct ScanFileScan {
  int index = 0;                     // 0, 1, 2, … in file order
  std::vector<ScanFileTruth> truth;  // targets present in this scan
  std::vector<Vec2> detections;      // m, in no particular order
};

/// The scene: what a tracker is told (the generator's parameters).
struct ScanFile {
  Vec2 area_min = Vec2::Zero(), area_max = Vec2::Zero();  // m, the surveillance area
  double dt = 0.2;                                        // s between scans
  double process_noise = 0.2;  // m²/s³, q of the NCV truth (continuous white acceleration)
  double p_detect = 0.9;       // probability that a target is detected in a scan
  double clutter_mean = 5.0;   // false detections per scan (Poisson), uniform over the area
  double sigma = 1.0;          // m, σ of the Cartesian position noise on each axis
  std::vector<ScanFileScan> scans;

  double area() const {  // m²
    const Vec2 size = area_max - area_min;
    return size.x() * size.y();
  }
};

/// Bad input: the message names the file and the line ("scans.txt:12: …").
class ScanFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Reads a scan file; `name` is used in error messages only.
ScanFile readScanFile(std::istream& in, const std::string& name);
/// Writes it back in the same format (doubles in their shortest exact form).
void writeScanFile(std::ostream& out, const ScanFile& file);

/// N targets in a square area of N · 2 500 m² centred on the origin, 100 scans of dt = 0.2 s:
/// initial positions uniform over the area, initial velocities N(0, 1 m²/s²) per axis, NCV
/// motion with continuous white acceleration q = 0.2 m²/s³ (per axis, exact discretisation
/// Q = q [[dt³/3, dt²/2], [dt²/2, dt]]), each target detected with P_D = 0.9 as its position plus
/// N(0, σ² I), σ = 1 m, and Poisson(5) clutter per scan uniform over the area. Every draw comes
/// from RandomStream(seed, "tracking_accuracy", …), so a seed gives the same file on any machine.
ScanFile generateScanFile(int targets, std::uint64_t seed);

/// The tracker told what the file says: P_D, λ = clutter_mean / area (at least 10⁻³ / area),
/// R = σ² I, σ_a² = q / dt (the piecewise-constant acceleration whose velocity variance per scan,
/// σ_a² dt², equals the truth's q dt), no pre-seeded tracks. m_of_n is the JPDAF of the issue's
/// reference table: 2 of 3, deleted after 5 misses or tr(P_pos) > 400 m².
agents::TrackingConfig trackerConfigFor(const ScanFile& file, agents::TrackConfirmation rule);

}  // namespace canopy::bench
