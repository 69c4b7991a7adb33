#pragma once
// The replay's data that changes over time, written as changes (replay_data.cpp writes the rest):
// each agent's occlusion map and its planned paths and planning epochs.
#include "replay/packed_json.h"
#include "replay/run_folder.h"

namespace canopy::replay {

/// ",\"maps\":[…]": occlusion maps as changes per agent and step (kMapResend, replay_data.h).
void writeMaps(const RunFolder& run, Table& keys, Writer& w);

/// ",\"paths\":[…],\"epochs\":[…]": planned paths per agent and step (0: unchanged), then the
/// planning epochs.
void writePlans(const RunFolder& run, Writer& w);

}  // namespace canopy::replay
