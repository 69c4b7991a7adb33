#pragma once
// One agent's part of a record line, cut from its text: `canopy record --agent I`. The line keeps
// every key, byte for byte, except that its lists of one entry per agent (the fields marked so in
// record_fields.cpp: "agents" and "scans") hold only entry I (agent I's belief and UAV I's scan),
// so what a reader of the whole line does with agents[0] it does here with agent I.
#include <optional>
#include <string>
#include <string_view>

namespace canopy::sim {

/// `line` (one record line, as the recorder writes it) with "agents" and "scans" cut to their
/// entry `agent`; nothing when either list has no such entry or the line is not such an object.
std::optional<std::string> agentSlice(std::string_view line, std::size_t agent);

}  // namespace canopy::sim
