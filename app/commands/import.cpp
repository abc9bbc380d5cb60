#include "commands/import.h"

#include <iostream>

#include "commands/cli_options.h"
#include "core/capture.h"
#include "core/diagnostics.h"
#include "core/files.h"
#include "core/shadertoy_json.h"

namespace rm::cli {

ImportCommand::ImportCommand(CLI::App& app)
    : command_(app.add_subcommand("import", "Write a Shadertoy .json export out as project files, for editing")) {
  CLI::App& c = *command_;
  c.add_option("json", json_, "Shadertoy JSON export")->required()->type_name("PROJECT.json");
  c.add_option("dir", dir_, "Directory to write image.frag, buffer_a.frag ..., common.glsl into")->required()->type_name("DIR");
  c.add_option("--media", media_, "Where the shadertoy.com media are, by file name")->type_name("DIR");
  c.add_flag("-f,--force", force_, "Replace files that exist");
}

int ImportCommand::run() const {
  require_readable_file(json_);
  std::string error;
  auto project = read_shadertoy_file(json_, media_, &error);
  if (!project) throw UsageError{error};
  // At the JSON, as a build of it says them.
  for (const Diagnostic& warning : project->warnings_at(json_)) std::cerr << warning.str() << '\n';
  const std::filesystem::path dir = dir_;
  // The folders this import makes, deepest first: taken away again if it fails.
  std::vector<std::filesystem::path> made_dirs;
  for (std::filesystem::path at = std::filesystem::absolute(dir).lexically_normal();
       !at.empty() && at != at.parent_path() && !exists_on_disk(at); at = at.parent_path())
    made_dirs.push_back(at);
  std::error_code made, probed;
  std::filesystem::create_directories(dir, made);
  if (!std::filesystem::is_directory(dir, probed)) {
    const std::string why = exists_on_disk(dir) ? "a file of that name is there" : made ? after_colon(made.message()) : "";
    throw UsageError{"'" + dir_ + "': cannot create the directory" + (why.empty() ? "" : ": " + why)};
  }
  // Nothing is written unless everything can be: no half-imported project.
  const auto files = project->files_to_import();
  for (const auto& [name, text] : files)
    if (!force_ && exists_on_disk(dir / name))
      throw UsageError{"'" + (dir / name).string() + "' exists (--force replaces it)"};
  std::vector<std::pair<std::filesystem::path, std::string_view>> writes;
  for (const auto& [name, text] : files) writes.emplace_back(dir / name, text);
  if (!write_whole_files(writes, &error)) {  // a full disk: all of them or none
    for (const std::filesystem::path& made_dir : made_dirs) {
      std::error_code ec;
      std::filesystem::remove(made_dir, ec);  // only if empty
    }
    throw UsageError{error};
  }
  std::cout << (dir / ShadertoyProject::kImage).string() << '\n';
  return kExitOk;
}

}  // namespace rm::cli
