// `canopy reproduce` end to end with two trials per configuration: the paper's table and the
// sensitivity studies, some 400 trials (LABEL monte_carlo: Release only).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/app/cli.h"

namespace {
namespace fs = std::filesystem;
using canopy::cli_test::fresh;
using canopy::cli_test::slurp;

TEST(ReproduceCommand, TwoTrialsWriteTheReportWithItsTablesAndFigures) {
  const fs::path dir = fresh("reproduce");
  const canopy::cli_test::Outcome outcome =
      canopy::cli_test::runIn(dir.parent_path(), "reproduce --out " + dir.string() +
                                                      " --trials 2 --jobs 2 --timing-trials 1");
  ASSERT_EQ(outcome.code, 0) << outcome.err;
  // The sweeps' bars only: no trial's stage line ("canopy: running steps: …") breaks into them.
  EXPECT_EQ(outcome.err.find("canopy: running steps"), std::string::npos) << outcome.err;
  const std::string report = slurp(dir / "report.md");
  EXPECT_NE(report.find("| trajectory_handover | SMA-NBO | 5 |"), std::string::npos);
  EXPECT_NE(report.find("| occlusion_sharing | SMA-NBO | III |"), std::string::npos);
  // The learned planner (issue 54): Occlusion_Aware and Occlusion_Share beside SMA-NBO's, its
  // held-out variants, and every timed planner's decision time per agent.
  EXPECT_NE(report.find("| occlusion_sharing | learned | III |"), std::string::npos);
  EXPECT_NE(report.find("| Occlusion_Aware (P[OA]) | joint_effect | I "), std::string::npos);
  EXPECT_NE(report.find("| Ownership_Change (M* at L) | resource_allocation | H = 5 |"),
            std::string::npos);
  EXPECT_NE(report.find("| team_6 | 6 | learned (imitates SMA-NBO) | 2 |"), std::string::npos);
  EXPECT_NE(report.find("| rotated_90 | 2 | SMA-NBO | 2 |"), std::string::npos);
  EXPECT_NE(report.find("## Decision time per agent"), std::string::npos);
  // One trial timed per configuration (--timing-trials 1): 13 epochs × 2 agents.
  EXPECT_NE(report.find("| trajectory_handover | H = 5 | learned (imitates SMA-NBO) | 1 | 26 |"),
            std::string::npos);
  // Dec-POMDP with each joint search (README): the default block search, the paper's one swarm
  // and the ring swarm, in Resource Allocation at H = 5.
  for (const char* planner :
       {"Dec-POMDP", "Dec-POMDP, the paper's one swarm", "Dec-POMDP, local-best swarm"}) {
    EXPECT_NE(report.find("| resource_allocation | " + std::string(planner) + " | 5 |"),
              std::string::npos)
        << planner;
  }
  // The learned planner's rows (issue 54) beside the paper's planners.
  EXPECT_NE(report.find("| trajectory_handover | learned (imitates SMA-NBO) | 5 |"),
            std::string::npos);
  EXPECT_NE(report.find("| resource_allocation | learned (imitates SMA-NBO) | 1 |"),
            std::string::npos);
  EXPECT_NE(report.find("H = 5 is more cooperative than H = 1"), std::string::npos);
  for (const char* scenario :
       {"trajectory_handover", "resource_allocation", "joint_effect", "occlusion_sharing",
        "joint_effect_learned", "occlusion_sharing_learned", "learned_heldout"}) {
    EXPECT_TRUE(fs::exists(dir / scenario / "summary.json")) << scenario;
    EXPECT_TRUE(fs::exists(dir / scenario / "analysis" / "ownership_states.csv")) << scenario;
  }
  // Every figure the report links exists.
  std::size_t at = 0;
  int figures = 0;
  while ((at = report.find("](", at)) != std::string::npos) {
    const std::size_t end = report.find(')', at);
    const std::string link = report.substr(at + 2, end - at - 2);
    EXPECT_TRUE(fs::exists(dir / link)) << link;
    ++figures;
    at = end;
  }
  // 20 Sankey diagrams (5 planners — SMA-NBO, Dec-POMDP with the block, the paper's and the
  // local-best joint search, learned — × 2 horizons × 2), 4 coverage figures (SMA-NBO's and the
  // learned planner's in JE and OS), 6 sensitivity maps (Resource Allocation; Joint Effect's
  // occlusion × spacing per occlusion map, and its decision period × footprint per map with a map)
  // and the altitude study's team figure (issue 53).
  EXPECT_EQ(figures, 31);
  EXPECT_NE(report.find("Should the team fly higher over this forest?"), std::string::npos);
  EXPECT_NE(report.find("| free, forest = dense | "), std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "altitude_tradeoff" / "analysis" / "team.csv"));
  EXPECT_NE(report.find("| decisions every 0.2 s step | a_priori |"), std::string::npos);
}

}  // namespace
