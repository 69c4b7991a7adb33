#pragma once
// What the fusion step did and what went wrong, counted rather than aborting (MuJoCo's habit).
// Totals since the TeamFusion was made; targets and trees together.

namespace canopy::agents::fusion {

struct FusionDiagnostics {
  long steps = 0;               // fuse() calls
  long messages = 0;            // consensus messages sent (exchanges × directed links)
  long lost_messages = 0;       // of which lost (comm_drop)
  long late_messages = 0;       // of those that arrived, read comm_latency steps after sent
  long remembered_matches = 0;  // neighbour pairs kept together because they share a key
  long new_matches = 0;         // neighbour pairs joined by the gated Hungarian assignment
  long refused_matches = 0;     // assigned pairs refused: one agent would hold two of a cluster
  long adoptions = 0;           // tracks copied to a neighbour that lacked them
  long rekeys = 0;              // clusters given a fresh key because another one kept theirs
  long numerical_failures = 0;  // covariances or fused information not positive definite

  FusionDiagnostics& operator+=(const FusionDiagnostics& o) {
    steps += o.steps;
    messages += o.messages;
    lost_messages += o.lost_messages;
    late_messages += o.late_messages;
    remembered_matches += o.remembered_matches;
    new_matches += o.new_matches;
    refused_matches += o.refused_matches;
    adoptions += o.adoptions;
    rekeys += o.rekeys;
    numerical_failures += o.numerical_failures;
    return *this;
  }
};

}  // namespace canopy::agents::fusion
