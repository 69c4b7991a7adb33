#include "bench/scan_file.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <istream>
#include <ostream>
#include <sstream>

#include "core/random.h"

namespace canopy::bench {
namespace {

constexpr int kFormatVersion = 1;

class LineError {
 public:
  LineError(const std::string& name, int line) : name_(name), line_(line) {}
  [[noreturn]] void fail(const std::string& what) const {
    throw ScanFileError(name_ + ":" + std::to_string(line_) + ": " + what);
  }

 private:
  const std::string& name_;
  int line_;
};

// The whitespace-separated words of a line, without a trailing "# comment".
std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line.substr(0, line.find('#')));
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

double number(const std::string& word, const LineError& error, const char* what) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (ec != std::errc() || end != word.data() + word.size() || !std::isfinite(value)) {
    error.fail(std::string("expected a finite number for ") + what + ", got \"" + word + "\"");
  }
  return value;
}

int integer(const std::string& word, const LineError& error, const char* what) {
  int value = 0;
  const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (ec != std::errc() || end != word.data() + word.size()) {
    error.fail(std::string("expected an integer for ") + what + ", got \"" + word + "\"");
  }
  return value;
}

void expectWords(const std::vector<std::string>& w, std::size_t count, const LineError& error,
                 const char* form) {
  if (w.size() != count) error.fail(std::string("expected \"") + form + "\"");
}

std::string shortest(double value) {
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, end);
}

}  // namespace

ScanFile readScanFile(std::istream& in, const std::string& name) {
  ScanFile file;
  bool header_seen = false, area_seen = false;
  std::string line;
  int number_of_line = 0;
  while (std::getline(in, line)) {
    ++number_of_line;
    const LineError error(name, number_of_line);
    const std::vector<std::string> w = words(line);
    if (w.empty()) continue;
    const std::string& key = w[0];
    if (!header_seen) {
      if (key != "canopy-scans") error.fail("expected the first line \"canopy-scans 1\"");
      expectWords(w, 2, error, "canopy-scans 1");
      if (integer(w[1], error, "the format version") != kFormatVersion)
        error.fail("unsupported format version " + w[1] + " (this reader knows 1)");
      header_seen = true;
    } else if (key == "area") {
      expectWords(w, 5, error, "area XMIN YMIN XMAX YMAX");
      file.area_min = Vec2(number(w[1], error, "XMIN"), number(w[2], error, "YMIN"));
      file.area_max = Vec2(number(w[3], error, "XMAX"), number(w[4], error, "YMAX"));
      if (!(file.area_max.x() > file.area_min.x() && file.area_max.y() > file.area_min.y()))
        error.fail("expected XMAX > XMIN and YMAX > YMIN");
      area_seen = true;
    } else if (key == "dt" || key == "process_noise" || key == "p_detect" ||
               key == "clutter_mean" || key == "sigma") {
      expectWords(w, 2, error, (key + " VALUE").c_str());
      const double v = number(w[1], error, key.c_str());
      const bool probability = key == "p_detect";
      if (probability ? !(v > 0.0 && v <= 1.0) : key == "clutter_mean" ? !(v >= 0.0) : !(v > 0.0))
        error.fail(key + (probability             ? " must lie in (0, 1]"
                          : key == "clutter_mean" ? " must be at least 0"
                                                  : " must be positive"));
      (key == "dt"              ? file.dt
       : key == "process_noise" ? file.process_noise
       : key == "p_detect"      ? file.p_detect
       : key == "clutter_mean"  ? file.clutter_mean
                                : file.sigma) = v;
    } else if (key == "scan") {
      expectWords(w, 2, error, "scan INDEX");
      const int index = integer(w[1], error, "the scan index");
      if (index != static_cast<int>(file.scans.size()))
        error.fail("expected scan " + std::to_string(file.scans.size()) + ", got " + w[1]);
      file.scans.push_back({index, {}, {}});
    } else if (key == "truth" || key == "detection") {
      if (file.scans.empty()) error.fail("\"" + key + "\" before the first \"scan\" line");
      ScanFileScan& scan = file.scans.back();
      if (key == "truth") {
        expectWords(w, 4, error, "truth ID X Y");
        scan.truth.push_back(
            {integer(w[1], error, "ID"), Vec2(number(w[2], error, "X"), number(w[3], error, "Y"))});
      } else {
        expectWords(w, 3, error, "detection X Y");
        scan.detections.emplace_back(number(w[1], error, "X"), number(w[2], error, "Y"));
      }
    } else {
      error.fail("unknown line \"" + key +
                 "\" (expected area, dt, process_noise, p_detect, "
                 "clutter_mean, sigma, scan, truth or detection)");
    }
  }
  const LineError end(name, number_of_line);
  if (!header_seen) end.fail("empty file: expected the first line \"canopy-scans 1\"");
  if (!area_seen) end.fail("no \"area XMIN YMIN XMAX YMAX\" line");
  if (file.scans.empty()) end.fail("no \"scan\" line");
  return file;
}

void writeScanFile(std::ostream& out, const ScanFile& file) {
  out << "canopy-scans " << kFormatVersion << "\n";
  out << "area " << shortest(file.area_min.x()) << ' ' << shortest(file.area_min.y()) << ' '
      << shortest(file.area_max.x()) << ' ' << shortest(file.area_max.y()) << "\n";
  out << "dt " << shortest(file.dt) << "\nprocess_noise " << shortest(file.process_noise)
      << "\np_detect " << shortest(file.p_detect) << "\nclutter_mean "
      << shortest(file.clutter_mean) << "\nsigma " << shortest(file.sigma) << "\n";
  for (const ScanFileScan& scan : file.scans) {
    out << "scan " << scan.index << "\n";
    for (const ScanFileTruth& t : scan.truth) {
      out << "truth " << t.id << ' ' << shortest(t.position.x()) << ' ' << shortest(t.position.y())
          << "\n";
    }
    for (const Vec2& z : scan.detections) {
      out << "detection " << shortest(z.x()) << ' ' << shortest(z.y()) << "\n";
    }
  }
}

ScanFile generateScanFile(int targets, std::uint64_t seed) {
  constexpr int kScans = 100;
  ScanFile file;
  const double half = 0.5 * std::sqrt(2500.0 * targets);  // m: N · 2 500 m² as a square
  file.area_min = Vec2(-half, -half);
  file.area_max = Vec2(half, half);
  RandomStream start(seed, "tracking_accuracy.start");
  RandomStream motion(seed, "tracking_accuracy.motion");
  RandomStream detection(seed, "tracking_accuracy.detection");
  RandomStream clutter(seed, "tracking_accuracy.clutter");
  std::vector<Vec4> state(static_cast<std::size_t>(targets));
  for (Vec4& x : state) {
    x << start.uniform(-half, half), start.uniform(-half, half), start.normal(), start.normal();
  }
  // Per axis, the exact discretisation of white acceleration of intensity q over dt:
  // Q = q [[dt³/3, dt²/2], [dt²/2, dt]], drawn through its Cholesky factor (2×2, by hand).
  const double dt = file.dt, q = file.process_noise;
  const double q11 = q * dt * dt * dt / 3.0, q12 = q * dt * dt / 2.0, q22 = q * dt;
  const double l11 = std::sqrt(q11), l21 = q12 / l11, l22 = std::sqrt(q22 - l21 * l21);
  for (int k = 0; k < kScans; ++k) {
    ScanFileScan scan;
    scan.index = k;
    for (int t = 0; t < targets; ++t) {
      Vec4& x = state[static_cast<std::size_t>(t)];
      if (k > 0) {
        for (int axis = 0; axis < 2; ++axis) {
          const double u = motion.normal(), v = motion.normal();
          x(axis) += dt * x(axis + 2) + l11 * u;  // p += dt v + w_p
          x(axis + 2) += l21 * u + l22 * v;       // v += w_v, (w_p, w_v) ~ N(0, Q)
        }
      }
      scan.truth.push_back({t, x.head<2>()});
      if (detection.bernoulli(file.p_detect)) {
        scan.detections.push_back(x.head<2>() +
                                  file.sigma * Vec2(detection.normal(), detection.normal()));
      }
    }
    const int false_alarms = clutter.poisson(file.clutter_mean);
    for (int c = 0; c < false_alarms; ++c) {
      scan.detections.emplace_back(clutter.uniform(-half, half), clutter.uniform(-half, half));
    }
    file.scans.push_back(std::move(scan));
  }
  return file;
}

agents::TrackingConfig trackerConfigFor(const ScanFile& file, agents::TrackConfirmation rule) {
  agents::TrackingConfig config;
  config.p_detect = file.p_detect;
  config.clutter_density = std::max(file.clutter_mean, 1e-3) / file.area();  // λ (1/m²)
  config.sigma_a = std::sqrt(file.process_noise / file.dt);                  // σ_a² = q / dt
  config.preseed = false;
  config.confirmation = rule;
  if (rule == agents::TrackConfirmation::m_of_n) {
    config.confirm_hits = 2;
    config.confirm_window = 3;
    config.delete_misses = 5;
    config.delete_trace = 400.0;
  }
  return config;
}

}  // namespace canopy::bench
