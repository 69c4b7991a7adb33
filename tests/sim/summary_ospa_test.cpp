// summary.json's per-agent OSPA, GOSPA and false tracks: the summary solves an agent's assignment
// through the people's grid, and reuses the last solve's figures when an agent holds the same
// positions, bit for bit. Checked against a fresh assignment per agent and step (no grid, no
// reuse) on a run where agents agree at some steps and not at others.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "metrics/ospa.h"
#include "sim/run.h"
#include "sim/simulation.h"
#include "sim/summary.h"
#include "spec/loader.h"

namespace canopy::sim {
namespace {

// Keeps a copy of every record it is handed.
struct RecordKeeper final : StepObserver {
  std::vector<StepRecord> records;
  void onStep(const StepRecord& record) override { records.push_back(record); }
};

std::vector<Vec2> positionsOf(const agents::AgentBelief& belief) {
  std::vector<Vec2> positions;
  for (const agents::TrackEstimate& track : belief.tracks) positions.push_back(track.belief.x.head<2>());
  return positions;
}

bool sameBits(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec2)) == 0);
}

TEST(SummaryOspa, EveryAgentsFiguresAreThoseOfItsOwnSolve) {
  spec::LoadOptions load;
  load.overrides = {"clock.duration=6", "fusion.comm_drop=0.5"};  // lost messages: some disagree
  const spec::ScenarioSpec spec = spec::loadScenario("trajectory_handover", load);
  Simulation sim(spec);
  RecordKeeper keeper;
  SummaryBuilder summary(spec);
  StepObserver* const observers[] = {&keeper, &summary};
  runToEnd(sim, observers);

  int agreeing = 0, differing = 0;  // agent-steps like the agent before, and not
  for (std::size_t k = 0; k < keeper.records.size(); ++k) {
    const StepRecord& record = keeper.records[k];
    std::vector<Vec2> truth;
    for (const TargetRecord& target : record.targets) truth.push_back(target.position);
    for (std::size_t i = 0; i < record.beliefs.size(); ++i) {
      const std::vector<Vec2> estimates = positionsOf(record.beliefs[i]);
      if (i > 0 && !estimates.empty()) {
        (sameBits(estimates, positionsOf(record.beliefs[i - 1])) ? agreeing : differing) += 1;
      }
      metrics::CutoffAssignment fresh(50.0, 2.0);
      fresh.solve(truth, estimates);
      EXPECT_EQ(summary.ospa()[i][k], fresh.ospa()) << "agent " << i << " step " << k;
    }
  }
  // Both cases occur, so both were checked.
  EXPECT_GT(agreeing, 0);
  EXPECT_GT(differing, 0);
}

}  // namespace
}  // namespace canopy::sim
