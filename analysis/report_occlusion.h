#pragma once
// report.md's occlusion sections: the wasted-coverage table of Joint Effect and Occlusion
// Sharing per map and decision period, Joint Effect's reaction times beside the paper's, and the
// occlusion findings (2–5) checked per decision period.
#include <ostream>
#include <vector>

#include "analysis/findings.h"
#include "analysis/report.h"

namespace canopy::analysis {

void writeOcclusion(std::ostream& md, const std::vector<ExperimentResult>& results);
void writeReaction(std::ostream& md, const Findings& findings);

void writeWastedCoverageFinding(std::ostream& md, const Findings& findings);
void writeCatchUpFinding(std::ostream& md, const Findings& findings);
void writeReactionOrderFinding(std::ostream& md, const Findings& findings);
void writeFirstRankingFinding(std::ostream& md, const Findings& findings);

}  // namespace canopy::analysis
