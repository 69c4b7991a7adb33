#pragma once
// Policy files (issue 54; the format is docs/imitation.md): the weights of the learned planner's
// network as JSON. Every refusal is a ScenarioError naming the file and the field.
#include <memory>
#include <string>

#include "agents/planning/policy_network.h"

namespace canopy::spec {

constexpr int kMaxPolicyLayers = 16;          // per part (track, mate, head)
constexpr int kMaxPolicyWidth = 1024;         // inputs or outputs of one layer
constexpr long kMaxPolicyWeights = 4000000;   // numbers in the whole file

/// Parses a policy file's text; `file` names it in errors.
std::shared_ptr<const agents::planning::PolicyNetwork> parsePolicy(const std::string& text,
                                                                   const std::string& file);
/// Reads and parses a policy file (a regular file of at most 64 MiB).
std::shared_ptr<const agents::planning::PolicyNetwork> readPolicyFile(const std::string& path);

}  // namespace canopy::spec
