#pragma once
// What the frames of `canopy run` show (`--view aoi|action|x0,y0,x1,y1`): one region for the
// whole run, so that the projection never changes between frames.
#include <string>

#include "core/types.h"
#include "spec/scenario_spec.h"

namespace canopy::render {

/// The padded box of everything that moves over the run as the scenario scripts it: every
/// target's path and every scripted UAV's path sampled at each step (a planned UAV: its start),
/// grown by the largest footprint's half-diagonal and then by 10 % of the larger side (at least
/// 2 m) on every side, and kept within the AOI. A planned UAV may leave it.
Aabb actionBox(const spec::ScenarioSpec& spec);

/// Whether `text` is in --view's grammar: "aoi", "action" or "x0,y0,x1,y1" (four numbers in JSON's
/// grammar, x1 > x0, y1 > y0; no blanks). Checked as the command line is read.
bool isViewText(const std::string& text);

/// The region for `--view TEXT`: "aoi", "action" or "x0,y0,x1,y1" (m, x1 > x0, y1 > y0); a usage
/// error naming --view otherwise.
Aabb viewFor(const std::string& text, const spec::ScenarioSpec& spec);

}  // namespace canopy::render
