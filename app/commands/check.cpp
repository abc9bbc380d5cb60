#include "commands/check.h"

#include <iostream>

#include "core/check.h"
#include "core/project.h"

namespace rm::cli {

CheckCommand::CheckCommand(CLI::App& app)
    : command_(app.add_subcommand("check", "Preprocess and validate SCENE (with every pass it reads) with glslang; print diagnostics")) {
  command_->add_option("scene", scene_, "Shader to check")->required()->type_name("SCENE");
  CLI::Option* expand =
      command_->add_flag("-E,--expand", expand_, "Print what the compiler sees: the source after the preprocessor");
  command_->add_flag("-P,--no-line-markers", no_line_markers_,
                     "With -E: no '# LINE \"FILE\"' lines, as cpp -P: text any GLSL compiler takes as it is")
      ->needs(expand);
  source_.add_to(*command_);
}

int CheckCommand::run() const {
  require_readable_file(scene_);
  check_project_file(scene_, {});  // malformed JSON: exit 2 with its line and column
  Diagnostics diags;
  // Every pass of a project (or a Shadertoy .json); -E prints the image pass.
  const Source source = check_project(project_files(scene_), source_.source(), &diags);
  std::cerr << join(diags);
  if (count_errors(diags)) return build_failure_status(diags);
  if (expand_) {
    auto text = expand_preprocessor(source, &diags, no_line_markers_ ? LineMarkers::Off : LineMarkers::On);
    std::cerr << join(diags);
    if (!text) return kExitShaderError;
    std::cout << *text;
  }
  return kExitOk;
}

}  // namespace rm::cli
