// The tracking bench anyone can feed (docs/output-formats.md, "Scan files"):
//
//   build/release/bench/tracking_accuracy SCANS.txt [--confirmation existence|m_of_n]
//   build/release/bench/tracking_accuracy --generate N --seed S [--out FILE]
//
// The first runs one agent's tracker over the file's scans with the file's parameters and prints,
// per scan, OSPA and GOSPA (c = 50 m, p = 2, α = 2; GOSPA's localisation, missed and false parts)
// between the true positions and the confirmed tracks, then one line
// "mean OSPA X m, mean GOSPA Y m, confirmed Z" (means over scans; Z confirmed tracks per scan).
// The second writes a file of N targets drawn from seed S (bench/scan_file.h). Bad input: a
// message naming the file and line, exit 2.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#include "agents/tracking/tracker.h"
#include "bench/scan_file.h"
#include "metrics/ospa.h"

namespace canopy::bench {
namespace {

constexpr double kCutoff = 50.0;  // m, OSPA and GOSPA cut-off c
constexpr double kOrder = 2.0;    // p

[[noreturn]] void usage(const std::string& message) {
  std::cerr << "tracking_accuracy: " << message << "\n"
            << "usage: tracking_accuracy SCANS.txt [--confirmation existence|m_of_n]\n"
            << "       tracking_accuracy --generate N --seed S [--out FILE]\n";
  std::exit(2);
}

int run(const ScanFile& file, agents::TrackConfirmation rule) {
  const agents::TrackingConfig config = trackerConfigFor(file, rule);
  agents::tracking::Tracker tracker(0, config);
  sensing::FootprintDef everywhere;  // the sensor sees every target wherever it goes
  everywhere.shape = sensing::FootprintShape::disc;
  everywhere.radius = 1e12;
  const sensing::Footprint footprint = sensing::Footprint::place(everywhere, Vec2::Zero(), 0.0);
  const agents::OcclusionMap no_map;
  const Mat2 R = file.sigma * file.sigma * Mat2::Identity();  // m²

  metrics::CutoffAssignment assignment(kCutoff, kOrder);
  std::vector<Vec2> truth, estimates;
  sensing::Scan scan;
  double ospa_sum = 0.0, gospa_sum = 0.0, confirmed_sum = 0.0;
  std::printf("# scan ospa_m gospa_m localisation_m2 missed false confirmed\n");
  for (const ScanFileScan& s : file.scans) {
    scan.clear();
    for (const Vec2& z : s.detections) {
      sensing::Observation o;
      o.label = 1;
      o.z = z;
      o.R = R;
      scan.observations.push_back(o);
    }
    if (s.index > 0) tracker.predict(file.dt);
    tracker.update(scan, footprint, no_map);
    tracker.mergeDuplicates();
    tracker.deleteStale();

    truth.clear();
    for (const ScanFileTruth& t : s.truth) truth.push_back(t.position);
    estimates.clear();
    for (const agents::tracking::TargetTrack& track : tracker.targets()) {
      if (track.status == agents::tracking::TrackStatus::confirmed)
        estimates.push_back(track.posterior.x.head<2>());
    }
    assignment.solve(truth, estimates);
    const auto parts = assignment.parts();
    const double ospa = assignment.ospa(), gospa = assignment.gospa();
    std::printf("%d %.4f %.4f %.4f %d %d %zu\n", s.index, ospa, gospa, parts.localisation,
                parts.missed, parts.false_estimates, estimates.size());
    ospa_sum += ospa;
    gospa_sum += gospa;
    confirmed_sum += static_cast<double>(estimates.size());
  }
  const double n = static_cast<double>(file.scans.size());
  std::printf("mean OSPA %.3f m, mean GOSPA %.3f m, confirmed %.3f\n", ospa_sum / n, gospa_sum / n,
              confirmed_sum / n);
  return 0;
}

int main(int argc, char** argv) {
  std::vector<std::string_view> args(argv + 1, argv + argc);
  if (args.empty()) usage("expected a scan file or --generate N --seed S");
  if (args[0] == "--generate") {
    if (args.size() != 4 && args.size() != 6) usage("expected --generate N --seed S [--out FILE]");
    if (args[2] != "--seed") usage("expected --seed S after --generate N");
    char* end = nullptr;
    const long targets = std::strtol(std::string(args[1]).c_str(), &end, 10);
    if (*end != '\0' || targets < 1 || targets > 100000) usage("N must be an integer in 1..100000");
    const unsigned long long seed = std::strtoull(std::string(args[3]).c_str(), &end, 10);
    if (*end != '\0' || args[3].empty()) usage("S must be a non-negative integer");
    const ScanFile file = generateScanFile(static_cast<int>(targets), seed);
    if (args.size() == 6) {
      if (args[4] != "--out") usage("expected --out FILE");
      std::ofstream out{std::string(args[5])};
      if (!out) usage("cannot write " + std::string(args[5]));
      writeScanFile(out, file);
      return out ? 0 : 2;
    }
    writeScanFile(std::cout, file);
    return 0;
  }
  agents::TrackConfirmation rule = agents::TrackConfirmation::existence;
  if (args.size() == 3 && args[1] == "--confirmation") {
    if (args[2] == "m_of_n") {
      rule = agents::TrackConfirmation::m_of_n;
    } else if (args[2] != "existence") {
      usage("--confirmation is existence or m_of_n");
    }
  } else if (args.size() != 1) {
    usage("expected SCANS.txt [--confirmation existence|m_of_n]");
  }
  const std::string name(args[0]);
  std::ifstream in(name);
  if (!in) {
    std::cerr << "tracking_accuracy: " << name << ": cannot open the file\n";
    return 2;
  }
  try {
    const ScanFile file = readScanFile(in, name);
    return run(file, rule);
  } catch (const ScanFileError& error) {
    std::cerr << "tracking_accuracy: " << error.what() << "\n";
    return 2;
  }
}

}  // namespace
}  // namespace canopy::bench

int main(int argc, char** argv) {
  return canopy::bench::main(argc, argv);
}
