#include "spec/policy_file.h"

#include <cmath>

#include "spec/error.h"
#include "spec/json_text.h"

namespace canopy::spec {
namespace {

using agents::planning::DenseLayer;
using agents::planning::PolicyNetwork;

struct Reader {
  std::string file;
  [[noreturn]] void fail(const std::string& field, const std::string& message) const {
    throw ScenarioError(file, field, message);
  }
  const Json& member(const Json& object, const std::string& key, const std::string& field) const {
    const auto it = object.find(key);
    if (it == object.end()) fail(field, "missing; expected a " + key + " field");
    return *it;
  }
  double number(const Json& value, const std::string& field) const {
    if (!value.is_number()) fail(field, "expected a number, got " + std::string(value.type_name()));
    const double x = value.get<double>();
    if (!std::isfinite(x)) fail(field, "expected a finite number");
    return x;
  }
  int count(const Json& value, const std::string& field) const {
    if (!value.is_number_integer()) fail(field, "expected an integer");
    return value.get<int>();
  }
};

DenseLayer readLayer(const Reader& r, const Json& value, const std::string& field, long& total) {
  if (!value.is_object())
    r.fail(field, "expected an object {\"weight\": [[…]], \"bias\": […]}");
  for (const auto& [key, unused] : value.items()) {
    if (key != "weight" && key != "bias") r.fail(field + "." + key, "unknown field");
  }
  const Json& weight = r.member(value, "weight", field + ".weight");
  const Json& bias = r.member(value, "bias", field + ".bias");
  if (!weight.is_array() || weight.empty())
    r.fail(field + ".weight", "expected a non-empty array of rows");
  if (!bias.is_array()) r.fail(field + ".bias", "expected an array of numbers");
  const std::size_t rows = weight.size();
  const std::size_t cols = weight[0].is_array() ? weight[0].size() : 0;
  if (rows > kMaxPolicyWidth || cols > kMaxPolicyWidth || cols == 0) {
    r.fail(field + ".weight", "expected 1 to " + std::to_string(kMaxPolicyWidth) +
                                  " rows of 1 to " + std::to_string(kMaxPolicyWidth) + " numbers");
  }
  total += static_cast<long>(rows * cols + bias.size());
  if (total > kMaxPolicyWeights)
    r.fail(field, "more than " + std::to_string(kMaxPolicyWeights) + " numbers in the file");
  DenseLayer layer;
  layer.weight.resize(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(cols));
  for (std::size_t i = 0; i < rows; ++i) {
    const std::string row_field = field + ".weight[" + std::to_string(i) + "]";
    const Json& row = weight[i];
    if (!row.is_array() || row.size() != cols)
      r.fail(row_field, "expected an array of " + std::to_string(cols) + " numbers (as row 0)");
    for (std::size_t j = 0; j < cols; ++j) {
      layer.weight(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
          r.number(row[j], row_field + "[" + std::to_string(j) + "]");
    }
  }
  if (bias.size() > kMaxPolicyWidth) r.fail(field + ".bias", "too long");
  layer.bias.resize(static_cast<Eigen::Index>(bias.size()));
  for (std::size_t i = 0; i < bias.size(); ++i)
    layer.bias(static_cast<Eigen::Index>(i)) =
        r.number(bias[i], field + ".bias[" + std::to_string(i) + "]");
  return layer;
}

std::vector<DenseLayer> readPart(const Reader& r, const Json& layers, const std::string& name,
                                 long& total) {
  const std::string field = "layers." + name;
  const Json& part = r.member(layers, name, field);
  if (!part.is_array() || part.empty() || part.size() > kMaxPolicyLayers) {
    r.fail(field, "expected an array of 1 to " + std::to_string(kMaxPolicyLayers) + " layers");
  }
  std::vector<DenseLayer> out;
  for (std::size_t k = 0; k < part.size(); ++k)
    out.push_back(readLayer(r, part[k], field + "[" + std::to_string(k) + "]", total));
  return out;
}

}  // namespace

std::shared_ptr<const PolicyNetwork> parsePolicy(const std::string& text, const std::string& file) {
  const Reader r{file};
  const Json doc = parseJson(text, file);
  if (!doc.is_object()) r.fail("", "expected a policy file: a JSON object");
  for (const auto& [key, unused] : doc.items()) {
    if (key != "format" && key != "version" && key != "features" && key != "layers" &&
        key != "training")
      r.fail(key, "unknown field (expected format, version, features, layers, training)");
  }
  const Json& format = r.member(doc, "format", "format");
  if (!format.is_string() || format.get<std::string>() != "canopy-policy")
    r.fail("format", "expected \"canopy-policy\"");
  const Json& version = r.member(doc, "version", "version");
  if (!version.is_number_integer() || version.get<long long>() != 1)
    r.fail("version", "expected 1 (the only version this canopy reads)");
  // The feature counts the network was trained on must be those of this build's observation.
  const Json& features = r.member(doc, "features", "features");
  if (!features.is_object()) r.fail("features", "expected {\"self\": …, \"track\": …, \"mate\": …}");
  const std::pair<const char*, int> expected[] = {{"self", agents::planning::kSelfFeatures},
                                                  {"track", agents::planning::kTrackFeatures},
                                                  {"mate", agents::planning::kMateFeatures}};
  for (const auto& [key, want] : expected) {
    const std::string field = std::string("features.") + key;
    if (r.count(r.member(features, key, field), field) != want) {
      r.fail(field, "expected " + std::to_string(want) +
                        " (this canopy's observation; retrain the policy)");
    }
  }
  if (features.size() != 3) r.fail("features", "expected exactly self, track and mate");
  const Json& layers = r.member(doc, "layers", "layers");
  if (!layers.is_object() || layers.size() != 3)
    r.fail("layers", "expected {\"track\": […], \"mate\": […], \"head\": […]}");
  auto net = std::make_shared<PolicyNetwork>();
  long total = 0;
  net->track = readPart(r, layers, "track", total);
  net->mate = readPart(r, layers, "mate", total);
  net->head = readPart(r, layers, "head", total);
  net->file = file;
  if (const std::string error = net->shapeError(); !error.empty()) {
    const std::size_t colon = error.find(": ");
    r.fail(error.substr(0, colon), error.substr(colon + 2));
  }
  return net;
}

std::shared_ptr<const PolicyNetwork> readPolicyFile(const std::string& path) {
  return parsePolicy(readJsonText(path), path);
}

}  // namespace canopy::spec
