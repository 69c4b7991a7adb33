#include "spec/internal/referenced_file.h"

#include "core/printable.h"
#include "core/text_file.h"
#include "spec/loader.h"

namespace canopy::spec::internal {
namespace fs = std::filesystem;
namespace {

fs::path canonicalOrEmpty(const fs::path& path) {
  std::error_code error;
  fs::path canonical = fs::weakly_canonical(fs::absolute(path, error), error);
  return error ? fs::path() : canonical;
}

// True when `path` is `root` or lies below it (both canonical), compared by whole components.
bool isInside(const fs::path& path, const fs::path& root) {
  auto p = path.begin();
  for (auto r = root.begin(); r != root.end(); ++r, ++p) {
    if (r->empty()) continue;  // a trailing separator
    if (p == path.end() || *p != *r) return false;
  }
  return true;
}

}  // namespace

LoadContext loadContextFor(const fs::path& scenario_file, const std::vector<fs::path>& allowed) {
  LoadContext context;
  fs::path folder = fs::path(scenario_file).parent_path();
  if (folder.empty()) folder = ".";
  for (const fs::path& root : {folder, libraryDir()}) {
    if (fs::path canonical = canonicalOrEmpty(root); !canonical.empty())
      context.roots.push_back(canonical);
  }
  for (const fs::path& root : allowed) {
    if (fs::path canonical = canonicalOrEmpty(root); !canonical.empty())
      context.roots.push_back(canonical);
  }
  return context;
}

ReferencedFile readReferencedFile(const Field& field, const std::string& what,
                                  const fs::path& fallback_dir) {
  const std::string name = field.string();
  if (name.empty()) field.fail("expected the name of a " + what + ", got an empty string");
  fs::path path = name;
  if (path.is_relative()) {
    path = fs::path(field.file()).parent_path() / name;
    std::error_code error;
    if (!fallback_dir.empty() && !fs::exists(path, error) && fs::exists(fallback_dir / name, error))
      path = fallback_dir / name;
  }
  ReferencedFile file{canonicalOrEmpty(path), printable(path.string(), 200), {}, {}};
  file.quoted = "'" + file.shown + "'";
  if (file.path.empty()) field.fail("cannot resolve the " + what + " " + file.quoted);
  std::error_code error;
  if (file.path != fs::absolute(path, error).lexically_normal())  // through a link
    file.quoted += " (a link to '" + printable(file.path.string(), 200) + "')";
  const LoadContext* context = field.context();
  bool allowed = false;
  for (const fs::path& root : context ? context->roots : std::vector<fs::path>{})
    allowed = allowed || isInside(file.path, root);
  if (!allowed) {
    field.fail("the " + what + " " + file.quoted +
               " lies outside the scenario's folder and the scenario library "
               "(--allow-path DIR allows another folder)");
  }
  std::string why;
  std::optional<std::string> text = readRegularFile(file.path, kMaxReferencedBytes, why);
  if (!text) field.fail("cannot read the " + what + " " + file.quoted + ": " + why);
  file.text = std::move(*text);
  return file;
}

}  // namespace canopy::spec::internal
