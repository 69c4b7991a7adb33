// Learned planning in a whole run (issue 54): the same seed gives the same bits, and labelling the
// decisions with SMA-NBO (DAgger) does not change what is flown.
#include <gtest/gtest.h>

#include <vector>

#include "agents/planning/policy_network.h"
#include "sim/simulation.h"
#include "spec/loader.h"

namespace canopy::sim {
namespace {

spec::ScenarioSpec learnedHandover() {
  spec::LoadOptions options;
  options.overrides = {"planner.algorithm=learned"};
  return spec::loadScenario("trajectory_handover", options);
}

// Every step's UAV positions and commands, as flown.
std::vector<double> flight(Simulation& sim) {
  std::vector<double> out;
  while (!sim.done()) {
    const StepRecord& r = sim.tick();
    for (const UavRecord& u : r.uavs)
      out.insert(out.end(), {u.position.x(), u.position.y(), u.command.x(), u.command.y()});
  }
  return out;
}

TEST(LearnedRun, TheShippedPolicyIsTheDefaultAndRunsAreBitIdentical) {
  const spec::ScenarioSpec spec = learnedHandover();
  ASSERT_TRUE(spec.planner.policy);
  EXPECT_NE(spec.planner.policy->file.find("policies/trajectory_handover.json"), std::string::npos);
  Simulation a(spec), b(spec);
  const std::vector<double> fa = flight(a), fb = flight(b);
  ASSERT_FALSE(fa.empty());
  EXPECT_EQ(fa, fb);  // bit for bit
  // The UAVs moved under the policy's commands.
  double moved = 0.0;
  for (std::size_t k = 2; k < fa.size(); k += 4) moved += std::abs(fa[k]) + std::abs(fa[k + 1]);
  EXPECT_GT(moved, 0.0);
}

TEST(LearnedRun, LabellingWithTheExpertChangesNothingFlown) {
  const spec::ScenarioSpec spec = learnedHandover();
  Simulation plain(spec), labelled(spec);
  int decisions = 0, differing = 0;
  labelled.observeDecisions(
      [&](const agents::planning::Decision& d) {
        ++decisions;
        if ((d.expert - d.flown).norm() > 1e-9) ++differing;
        EXPECT_LE(d.expert.norm(), d.v_max + 1e-9);
      },
      true);
  EXPECT_EQ(flight(plain), flight(labelled));
  // 2 agents × 13 epochs (12 s, one every 1 s, k = 0 included); SMA-NBO's search is no copy of
  // the policy.
  EXPECT_EQ(decisions, 26);
  EXPECT_GT(differing, 0);
}

}  // namespace
}  // namespace canopy::sim
