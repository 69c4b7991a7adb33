#pragma once
// The program's version (CMake's project version) and the git commit it was built from
// ("unknown" when git or the checkout was missing at build time; "-dirty" with uncommitted
// changes). Written into every manifest.json and printed by `canopy --version`.

namespace canopy {

extern const char* const kVersion;
extern const char* const kGitCommit;

}  // namespace canopy
