// raymarching: a live shader playground for ray-marched SDF scenes.
//   raymarching [SCENE]            open a window (default scene without SCENE)
//   raymarching render SCENE -o F  render headless through EGL
//   raymarching check SCENE [-E]   preprocess and validate only (-E: print the result)
//   raymarching accuracy SCENE     what each accuracy knob costs and buys
//   raymarching import P.json DIR  a Shadertoy JSON export as project files
// Each command lives in app/commands/ with its options and its run; this
// file only wires them.

#include <CLI/CLI.hpp>
#include <iostream>
#include <new>
#include <regex>
#include <string>
#include <system_error>
#include <vector>

#include "commands/accuracy.h"
#include "commands/check.h"
#include "commands/import.h"
#include "commands/render.h"
#include "commands/window.h"
#include "core/address_space.h"
#include "core/deep_stack.h"
#include "core/diagnostics.h"
#include "core/stop_signals.h"
#include "window/window_app.h"

namespace {

// CLI11 checks the required options before it looks for unknown ones: a
// mistyped option would be reported as the missing one it was meant to be.
// (And CLI11 2.1 lists the unexpected arguments last first.)
std::string usage_error(const CLI::App& app, const CLI::ParseError& e) {
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&e) != nullptr) {
    // An option of one value given twice: CLI11 says "--size: At Most 1 required but received 2";
    // and one given last with no value: "--size: 1 required WxH missing".
    static const std::regex given_twice(R"(^(\S+): At Most 1 required but received (\d+)$)");
    static const std::regex no_value(R"(^(\S+): 1 required (.+) missing$)");
    std::cmatch m;
    if (std::regex_match(e.what(), m, given_twice))
      return m[1].str() + " was given " + m[2].str() + " times; it takes one value";
    if (std::regex_match(e.what(), m, no_value)) return m[1].str() + " needs a value: " + m[2].str();
  }
  if (dynamic_cast<const CLI::RequiredError*>(&e) == nullptr && dynamic_cast<const CLI::ExtrasError*>(&e) == nullptr)
    return e.what();
  const std::vector<std::string> unexpected = app.remaining(true);  // with the subcommand's, in order
  if (unexpected.empty()) return e.what();
  std::string message = unexpected.size() == 1 ? "The following argument was not expected:"
                                               : "The following arguments were not expected:";
  for (const std::string& arg : unexpected) message += " " + arg;
  return message;
}

int run(int argc, char** argv) {
  CLI::App app{"raymarching: a live shader playground for ray-marched SDF scenes.\n"
               "Opens SCENE (a .frag file) in a window and reloads it on every save.",
               "raymarching"};
  app.set_version_flag("--version", std::string("raymarching ") + RM_VERSION);
  app.require_subcommand(0, 1);

  const rm::cli::WindowCommand window(app);  // the default: no subcommand
  const rm::cli::RenderCommand render(app);
  const rm::cli::CheckCommand check(app);
  const rm::cli::AccuracyCommand accuracy(app);
  const rm::cli::ImportCommand import(app);
  // Each help shows what its command takes: the window's keys only in the
  // window's (set after the subcommands, which would inherit them).
  const std::string exit_status =
      "\nexit status: 0 ok, 1 shader error, 2 usage or I/O error, 124 render --timeout passed,\n"
      "128+N stopped by signal N";
  app.footer(std::string("\n") + rm::window_keys_help() + exit_status);
  for (CLI::App* command : app.get_subcommands([](CLI::App*) { return true; })) command->footer(exit_status);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    const std::vector<CLI::App*> command = app.get_subcommands();  // the one given, if any
    std::cerr << "raymarching: error: " << usage_error(app, e) << " (see raymarching "
              << (command.empty() ? "" : command[0]->get_name() + " ") << "--help)\n";
    return rm::kExitUsage;
  }

  try {
    if (accuracy.chosen()) return accuracy.run();
    if (check.chosen()) return check.run();
    if (import.chosen()) return import.run();
    if (render.chosen()) return render.run();
    return window.run();
  } catch (const rm::cli::UsageError& e) {
    std::cerr << "raymarching: error: " << e.message << '\n';
    return rm::kExitUsage;
  } catch (const rm::NoRoomForDriver& e) {
    std::cerr << "raymarching: error: " << e.what() << '\n';
    return rm::kExitUsage;
  } catch (const std::bad_alloc&) {  // what the system refuses ends in one line, as a bad path does
    std::cerr << "raymarching: error: out of memory\n";
    return rm::kExitUsage;
  } catch (const std::system_error& e) {  // a thread that cannot start says only strerror
    const bool thread = e.code() == std::errc::resource_unavailable_try_again;
    std::cerr << "raymarching: error: " << (thread ? "a thread could not be started: " : "") << e.what()
              << (thread ? " (out of memory or of threads)" : "") << '\n';
    return rm::kExitUsage;
  }
}

}  // namespace

int main(int argc, char** argv) {
  rm::fit_malloc_to_address_space_limit();
  rm::StopSignals::prepare();  // before anything else takes file descriptors
  // Every command may build a program in the GL driver, whose compiler
  // recurses on a shader's trees, on this thread: give it a deep stack.
  int status = 0;
  rm::run_with_deep_stack([&] { status = run(argc, argv); });
  return status;
}
