#pragma once
// The replay's data that changes over time, written as changes (replay_data.cpp writes the rest):
// each agent's occlusion map and its planned paths and planning epochs, as typed columns.
#include "replay/columns.h"
#include "replay/packed_json.h"  // Table
#include "replay/run_folder.h"

namespace canopy::replay {

/// Occlusion maps as changes per agent and step, in the map_* columns of `c` (kMapResend,
/// replay_data.h; the layout in replay_changes.cpp).
void writeMaps(const RunFolder& run, Table& keys, Columns& c);

/// Planned paths per agent and step (only where they change), then the planning epochs (each
/// agent's plan, cost and the epochs it planned against; the messages sent), in the plan_*,
/// epoch_*, part_* and message_* columns of `c` (the layout in replay_changes.cpp).
void writePlans(const RunFolder& run, Columns& c);

}  // namespace canopy::replay
