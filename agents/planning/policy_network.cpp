#include "agents/planning/policy_network.h"

#include <cmath>
#include <limits>

namespace canopy::agents::planning {
namespace {

using Eigen::VectorXd;

// ReLU(W x + b) through every layer of an encoder.
VectorXd encode(const std::vector<DenseLayer>& layers, const double* row, int size) {
  VectorXd h = Eigen::Map<const VectorXd>(row, size);
  for (const DenseLayer& layer : layers) h = (layer.weight * h + layer.bias).cwiseMax(0.0);
  return h;
}

// [mean, max] over the rows' encodings; zeros for no rows.
VectorXd pool(const std::vector<DenseLayer>& layers, const std::vector<double>& rows, int size) {
  const Eigen::Index width = layers.back().bias.size();
  VectorXd out = VectorXd::Zero(2 * width);
  const int count = static_cast<int>(rows.size()) / size;
  if (count == 0) return out;
  VectorXd sum = VectorXd::Zero(width);
  VectorXd max = VectorXd::Constant(width, -std::numeric_limits<double>::infinity());
  for (int r = 0; r < count; ++r) {
    const VectorXd h = encode(layers, rows.data() + static_cast<std::ptrdiff_t>(r) * size, size);
    sum += h;
    max = max.cwiseMax(h);
  }
  out.head(width) = sum / count;
  out.tail(width) = max;
  return out;
}

std::string checkChain(const std::vector<DenseLayer>& layers, const std::string& name,
                       Eigen::Index input, Eigen::Index output) {
  if (layers.empty()) return "layers." + name + ": expected at least one layer";
  Eigen::Index in = input;
  for (std::size_t k = 0; k < layers.size(); ++k) {
    const std::string where = "layers." + name + "[" + std::to_string(k) + "]";
    const DenseLayer& layer = layers[k];
    if (layer.weight.cols() != in) {
      return where + ".weight: expected rows of " + std::to_string(in) + " numbers, got " +
             std::to_string(layer.weight.cols());
    }
    if (layer.weight.rows() < 1) return where + ".weight: expected at least one row";
    if (layer.bias.size() != layer.weight.rows()) {
      return where + ".bias: expected " + std::to_string(layer.weight.rows()) + " numbers, got " +
             std::to_string(layer.bias.size());
    }
    in = layer.weight.rows();
  }
  if (output > 0 && in != output) {
    return "layers." + name + "[" + std::to_string(layers.size() - 1) + "].weight: expected " +
           std::to_string(output) + " rows (the last layer's outputs), got " + std::to_string(in);
  }
  return "";
}

}  // namespace

std::string PolicyNetwork::shapeError() const {
  if (std::string e = checkChain(track, "track", kTrackFeatures, 0); !e.empty()) return e;
  if (std::string e = checkChain(mate, "mate", kMateFeatures, 0); !e.empty()) return e;
  const Eigen::Index input =
      kSelfFeatures + 2 * track.back().bias.size() + 2 * mate.back().bias.size();
  return checkChain(head, "head", input, 2);
}

Vec2 PolicyNetwork::output(const Observation& o) const {
  const Eigen::Index width_t = track.back().bias.size();
  const Eigen::Index width_m = mate.back().bias.size();
  VectorXd z(kSelfFeatures + 2 * width_t + 2 * width_m);
  z << Eigen::Map<const VectorXd>(o.self.data(), kSelfFeatures),
      pool(track, o.tracks, kTrackFeatures), pool(mate, o.mates, kMateFeatures);
  for (std::size_t k = 0; k < head.size(); ++k) {
    z = head[k].weight * z + head[k].bias;
    if (k + 1 < head.size()) z = z.cwiseMax(0.0);
  }
  return Vec2(std::tanh(z(0)), std::tanh(z(1)));
}

Vec2 PolicyNetwork::command(const Observation& o, double v_max) const {
  Vec2 a = v_max * output(o);
  const double speed = a.norm();
  if (speed > v_max) a *= v_max / speed;
  return a;
}

}  // namespace canopy::agents::planning
