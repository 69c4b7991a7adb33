#pragma once
// The replay's data that changes over time, written as changes (replay_data.cpp writes the rest):
// each agent's occlusion map (typed columns) and its planned paths and planning epochs (JSON).
#include "replay/columns.h"
#include "replay/packed_json.h"
#include "replay/run_folder.h"

namespace canopy::replay {

/// Occlusion maps as changes per agent and step, in the map_* columns of `c` (kMapResend,
/// replay_data.h; the layout in replay_changes.cpp).
void writeMaps(const RunFolder& run, Table& keys, Columns& c);

/// ",\"paths\":[…],\"epochs\":[…]": planned paths per agent and step (0: unchanged), then the
/// planning epochs.
void writePlans(const RunFolder& run, Writer& w);

}  // namespace canopy::replay
