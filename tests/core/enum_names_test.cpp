#include "core/enum_names.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "agents/config.h"
#include "sensing/visibility.h"

namespace canopy {
namespace {

// Every table names each of its enum's values 0..N−1 exactly once, each with its own spelling.
template <class Enum, std::size_t N>
void expectCoversEveryValueOnce(const EnumNames<Enum, N>& names) {
  std::set<int> values;
  std::set<std::string> spellings;
  for (const EnumName<Enum>& entry : names) {
    values.insert(static_cast<int>(entry.value));
    spellings.insert(std::string(entry.name));
    EXPECT_FALSE(entry.name.empty());
  }
  EXPECT_EQ(values.size(), N);
  EXPECT_EQ(spellings.size(), N);
  EXPECT_EQ(*values.begin(), 0);
  EXPECT_EQ(*values.rbegin(), static_cast<int>(N) - 1);
}

TEST(EnumNames, EveryTableCoversItsEnum) {
  expectCoversEveryValueOnce(agents::kFusionMethodNames);
  expectCoversEveryValueOnce(agents::kPlannerAlgorithmNames);
  expectCoversEveryValueOnce(agents::kOcclusionMapModeNames);
  expectCoversEveryValueOnce(agents::kJointSearchNames);
  expectCoversEveryValueOnce(sensing::kOcclusionModelNames);
}

TEST(EnumNames, NameOfFindsTheSpelling) {
  EXPECT_EQ(nameOf(agents::kOcclusionMapModeNames, agents::OcclusionMapMode::a_priori), "a_priori");
  EXPECT_EQ(nameOf(agents::kPlannerAlgorithmNames, agents::PlannerAlgorithm::dec_pomdp),
            "dec_pomdp");
  static_assert(nameOf(agents::kJointSearchNames, agents::JointSearch::block_coordinate) ==
                "block_coordinate");
}

}  // namespace
}  // namespace canopy
