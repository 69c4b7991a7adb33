#pragma once
// Where each value of a JSON text starts: the line of every field path, in the loader's spelling
// ("clock.dt", "uavs[0].v_max", "occluders[3]"), so that an error names the line as well as the
// field, and several errors can be listed in file order. The JSON library keeps no positions;
// this is a second, small scan of the text (comments allowed, as in the parse).
#include <map>
#include <set>
#include <string>

namespace canopy::spec {

/// Line (1-based) of every value and of every object key (the key's own line: where an unknown
/// field is written) in `text`. A text that is not valid JSON gives the lines found up to the
/// fault; the parse reports the fault itself.
std::map<std::string, int> jsonValueLines(const std::string& text);
/// The same for the paths in `wanted` only (those of a few errors): one linear pass that builds
/// no path outside them, however many values the text holds (10⁶ targets: no 10⁷-entry map).
std::map<std::string, int> jsonValueLines(const std::string& text,
                                          const std::set<std::string>& wanted);

}  // namespace canopy::spec
