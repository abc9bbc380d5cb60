#include "core/project.h"

#include <algorithm>
#include <chrono>
#include <tuple>
#include <utility>

#include "core/channel_spec.h"
#include "core/files.h"
#include "core/glslviewer_passes.h"
#include "core/shadertoy_json.h"

namespace rm {

ProjectFiles project_files(const fs::path& path, const fs::path& media_dir) {
  if (!is_shadertoy_json(path)) return {path, disk_file_system(), {}};
  // Common comes in ahead of each pass's first line, so that the lines of
  // the JSON's code keep the numbers shadertoy.com's editor shows.
  return {fs::absolute(path).lexically_normal() / ShadertoyProject::kImage, shadertoy_file_system(path, media_dir),
          {ShadertoyProject::kCommon}};
}

namespace {

SourceOptions with_forced(SourceOptions options, const std::vector<std::string>& forced) {
  options.forced_includes.insert(options.forced_includes.begin(), forced.begin(), forced.end());
  return options;
}

// A pass's name as the draw order sorts it: its file's, where a glslViewer
// pass's number has two digits (BUFFER_2 before BUFFER_10, as glslViewer draws them).
std::string sorted_name(const fs::path& pass) {
  std::string name = pass.filename().string();
  const size_t digits = name.find_last_not_of("0123456789") + 1;
  if (glslviewer_pass_of(pass) && name.size() - digits == 1) name.insert(digits, "0");
  return name;
}

// The passes a walk reached (the image first) in the order they are drawn:
// the stand-ins for missing media first, then buffers in the order of their
// file names, then cube passes, then the image: Shadertoy's A, B, C, D,
// Cube A, Image.
std::vector<fs::path> draw_order(const std::vector<fs::path>& reached, const std::map<fs::path, int>& cube_size) {
  std::vector<fs::path> passes(reached.begin() + 1, reached.end());
  auto order = [&](const fs::path& p) {
    return std::make_tuple(!is_media_stand_in(p), cube_size.count(p), sorted_name(p), p);
  };
  std::sort(passes.begin(), passes.end(), [&](const fs::path& a, const fs::path& b) { return order(a) < order(b); });
  passes.push_back(reached.front());
  return passes;
}

}  // namespace

Project::Project(fs::path image, SourceOptions options, FileSystem files, std::array<fs::path, 4> channels)
    : image_path_(fs::absolute(image).lexically_normal()),
      options_(options),
      image_options_(std::move(options)),
      files_(std::move(files)),
      channel_overrides_(std::move(channels)) {}

Project::Project(const ProjectFiles& from, SourceOptions options, std::array<fs::path, 4> channels)
    : Project(from.image, with_forced(std::move(options), from.forced_includes), from.files, std::move(channels)) {
  forced_includes_ = from.forced_includes;
}

void Project::set_options(SourceOptions all, SourceOptions image_only) {
  options_ = with_forced(std::move(all), forced_includes_);
  image_options_ = with_forced(std::move(image_only), forced_includes_);
  for (auto& [file, scene] : scenes_) scene->set_options(file == image_path_ ? image_options_ : options_);
}

Scene& Project::scene_for(const fs::path& file) {
  auto& scene = scenes_[file];
  if (!scene) scene = std::make_unique<Scene>(file, file == image_path_ ? image_options_ : options_, files_);
  return *scene;
}

const Source& Project::image_source() const {
  static const Source none;
  return ready() ? image().scene->source() : none;
}

PassWalk walk_passes(const fs::path& image, const std::function<VisitedPass(const fs::path&)>& visit,
                     Diagnostics* diags, const std::array<bool, 4>& image_channels_given) {
  PassWalk walk;
  walk.reached = {image};
  auto graph_error = [&](const fs::path& file, std::string message) {
    Diagnostic d;
    d.path = file.string();
    d.message = std::move(message);
    diags->push_back(std::move(d));
    walk.ok = false;
  };
  std::map<fs::path, const Source*> sources;
  std::vector<std::pair<fs::path, ChannelSpec>> reads;  // reader, and a buffer it reads
  for (size_t i = 0; i < walk.reached.size(); ++i) {
    const fs::path file = walk.reached[i];
    const VisitedPass visited = visit(file);
    const Source* source = visited.source;
    if (!source) {
      walk.ok = false;
      continue;
    }
    sources[file] = source;
    std::array<bool, 4> bound{};
    for (size_t c = 0; c < 4; ++c)
      bound[c] = source->channels[c].kind != ChannelSpec::Kind::None || (i == 0 && image_channels_given[c]);
    const Diagnostics unbound = unbound_channel_reads(*source, bound, visited.active);
    append_new(diags, unbound);
    if (i == 0 && source->cubemap)
      graph_error(image, "the image pass defines mainCubemap: open the pass that reads the cube map");
    for (const ChannelSpec& channel : source->channels) {
      if (channel.kind == ChannelSpec::Kind::Self && channel.buffer_size.given()) {  // a size for itself
        if (i == 0) graph_error(file, "the image pass is the picture's size: size=WxH and scale=F are for buffers");
        ChannelSpec itself = channel;
        itself.path = file;
        reads.push_back({file, itself});
      }
      if (channel.kind != ChannelSpec::Kind::Pass) continue;
      reads.push_back({file, channel});
      if (channel.path == image)
        graph_error(file, "'" + image.filename().string() + "' is the image pass: no pass can read it");
      else if (std::find(walk.reached.begin(), walk.reached.end(), channel.path) == walk.reached.end())
        walk.reached.push_back(channel.path);
    }
  }
  if (walk.reached.size() > Project::kMaxBuffers + 1)
    graph_error(image, "a project may have at most " + std::to_string(Project::kMaxBuffers) +
                           " buffer passes; this one reaches " + std::to_string(walk.reached.size() - 1));
  if (!walk.ok) return walk;
  // A Cube A pass is one that defines mainCubemap; every reader must read it as a cube.
  for (const auto& [reader, channel] : reads) {
    const bool cube_pass = sources.at(channel.path)->cubemap;
    if (cube_pass != (channel.shape == ChannelSpec::Shape::Cube))
      graph_error(reader, "'" + channel.path.filename().string() +
                              (cube_pass ? "' defines mainCubemap: read it with `cube` after its name"
                                         : "' is read with `cube` but defines no mainCubemap(out vec4, in vec2, in vec3, in vec3)"));
    if (cube_pass) {
      int& size = walk.cube_size[channel.path];
      size = std::max(size, channel.cube_size);
    }
    if (!channel.buffer_size.given()) continue;
    // A buffer's own size: every reader that gives one gives the same.
    const auto [given, first] = walk.buffer_size.emplace(channel.path, channel.buffer_size);
    if (!first && given->second != channel.buffer_size)
      graph_error(reader, "'" + channel.path.filename().string() + "' is read here with " +
                              to_string(channel.buffer_size) + " and elsewhere with " + to_string(given->second) +
                              ": a buffer has one size");
  }
  return walk;
}

Source check_project(const ProjectFiles& from, const SourceOptions& options, Diagnostics* diags) {
  const SourceOptions with_common = with_forced(options, from.forced_includes);
  if (from.files.warnings) {
    const Diagnostics warnings = from.files.warnings();
    diags->insert(diags->end(), warnings.begin(), warnings.end());
  }
  std::map<fs::path, Source> sources;
  std::map<fs::path, std::string> active;
  const fs::path image = fs::absolute(from.image).lexically_normal();  // as the passes name each other
  walk_passes(
      image,
      [&](const fs::path& file) -> VisitedPass {
        Diagnostics found;
        Source source = check_scene(file, with_common, &found, from.files, &active[file]);
        append_new(diags, found);
        if (count_errors(found) > 0) return {};
        return {&(sources[file] = std::move(source)), active[file]};
      },
      diags);
  auto found = sources.find(image);
  return found == sources.end() ? Source{} : found->second;
}

ReloadStatus Project::reload() {
  const ReloadStatus status = prepare();
  if (status == ReloadStatus::Swapped) commit();
  return status;
}

ReloadStatus Project::prepare(const OnBuilt& on_built, const Cancelled& cancelled, const RunJobs& run) {
  return prepare(on_built, cancelled, run, true);
}

ReloadStatus Project::prepare_without_compiling() { return prepare({}, {}, {}, false); }

ReloadStatus Project::prepare(const OnBuilt& on_built, const Cancelled& cancelled, const RunJobs& run, bool compile) {
  const auto begun = std::chrono::steady_clock::now();
  pending_.reset();
  Diagnostics shown = std::exchange(diagnostics_, files_.warnings ? files_.warnings() : Diagnostics{});
  bool needs_compile = false;
  times_ = {};
  std::array<bool, 4> channels_given{};
  for (size_t c = 0; c < 4; ++c) channels_given[c] = !channel_overrides_[c].empty();
  bool changed = false;
  std::vector<fs::path> swapped;  // passes with a new program
  // Every pass reachable from the image pass, the image first.
  const PassWalk walk = walk_passes(
      image_path_,
      [&](const fs::path& file) -> VisitedPass {
        Scene& scene = scene_for(file);
        // The driver's stage waits for the walk's end: glslang's stage
        // names the passes the graph reaches, and their links run at once.
        const ReloadStatus status =
            compile ? scene.prepare(cancelled, Scene::Link::Later) : scene.prepare_without_compiling();
        times_.preprocess += scene.times().preprocess;
        times_.validate += scene.times().validate;
        if (status == ReloadStatus::NeedsCompile) {
          needs_compile = true;
          return {};
        }
        if (status == ReloadStatus::Swapped) swapped.push_back(file);
        const Diagnostics& diags = scene.latest_diagnostics();
        append_new(&diagnostics_, diags);
        changed = changed || status == ReloadStatus::Swapped;
        // Unchanged since a failed attempt is still failed.
        if (status == ReloadStatus::Failed || (status == ReloadStatus::Unchanged && count_errors(diags) > 0) ||
            (!scene.program() && status != ReloadStatus::Swapped))
          return {};
        return {&scene.latest_source(), scene.latest_active()};
      },
      &diagnostics_, channels_given);
  const std::vector<fs::path>& reached = walk.reached;
  auto same_passes = [&] {
    if (reached.size() != passes_.size()) return false;
    for (const Pass& pass : passes_)
      if (std::find(reached.begin(), reached.end(), pass.file) == reached.end()) return false;
    return true;
  };
  if (!walk.ok) {
    for (const fs::path& file : reached) scene_for(file).discard();
    if (!needs_compile) return ReloadStatus::Failed;
    diagnostics_ = std::move(shown);
    return ReloadStatus::NeedsCompile;
  }
  if (!changed && same_passes()) return ReloadStatus::Unchanged;
  // Each pass's link and warm-up, as a job of its own, the largest first:
  // the runner's threads take them in turn, and a long job taken last would
  // leave one thread building it alone. The size of the active code stands
  // for the compile's cost. (Each warm-up also draws in a probe context,
  // which waits for Mesa's cache to hold its code, so the window finds every
  // pass's code whatever the order.)
  std::vector<Scene*> scenes;
  for (const fs::path& file : draw_order(reached, walk.cube_size))
    if (Scene& scene = scene_for(file); scene.built_anew()) scenes.push_back(&scene);
  std::stable_sort(scenes.begin(), scenes.end(),
                   [](const Scene* a, const Scene* b) { return a->latest_active().size() > b->latest_active().size(); });
  std::vector<char> linked(scenes.size(), 1);  // not vector<bool>: its jobs write on several threads
  std::vector<std::function<void()>> jobs;
  for (size_t i = 0; i < scenes.size(); ++i)
    jobs.push_back([&, i] {
      if (!scenes[i]->link()) linked[i] = 0;
      else scenes[i]->warm_up(on_built);
    });
  try {
    if (run) run(jobs);
    else for (const auto& job : jobs) job();
  } catch (...) {  // no room for the driver (core/address_space.h): nothing half-built stays
    for (const fs::path& file : reached) scene_for(file).discard();
    throw;
  }
  for (Scene* scene : scenes) {
    times_.driver += scene->times().driver;
    times_.warm += scene->times().warm;
  }
  if (std::find(linked.begin(), linked.end(), 0) != linked.end()) {  // the driver rejected what glslang passed
    for (size_t i = 0; i < scenes.size(); ++i)
      if (!linked[i]) append_new(&diagnostics_, scenes[i]->latest_diagnostics());
    for (const fs::path& file : reached) scene_for(file).discard();
    return ReloadStatus::Failed;
  }
  pending_ = PendingSwap{walk.reached, walk.cube_size, walk.buffer_size, std::move(swapped)};
  times_.wall = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begun).count();
  return ReloadStatus::Swapped;
}

bool Project::tweaked() const {
  return std::any_of(passes_.begin(), passes_.end(), [](const Pass& p) { return p.scene->tweaked(); });
}

bool Project::wants_twins() const {
  return std::any_of(passes_.begin(), passes_.end(), [](const Pass& p) { return p.scene->wants_twin(); });
}

bool Project::prepare_twins(const OnBuilt& on_built, const Cancelled& cancelled) {
  return take_twins(build_twins(twin_jobs(), on_built, cancelled));
}

void Project::commit_twins() {
  for (const Pass& pass : passes_) pass.scene->commit_twin();
}

Diagnostics Project::latest_diagnostics() const {
  Diagnostics out = files_.warnings ? files_.warnings() : Diagnostics{};
  for (const Pass& pass : passes_) {
    const Diagnostics& diags = pass.scene->latest_diagnostics();
    append_new(&out, diags);
  }
  return out;
}

std::vector<Scene::ExactJob> Project::exact_jobs() const {
  std::vector<Scene::ExactJob> jobs;
  for (const Pass& pass : passes_)
    if (std::optional<Scene::ExactJob> job = pass.scene->exact_job()) jobs.push_back(std::move(*job));
  return jobs;
}

std::vector<Scene::ExactResult> Project::build_exact(const std::vector<Scene::ExactJob>& jobs,
                                                     const OnBuilt& on_built, const Cancelled& cancelled) {
  std::vector<Scene::ExactResult> results;
  for (const Scene::ExactJob& job : jobs) results.push_back(Scene::build_exact(job, on_built, cancelled));
  return results;
}

ReloadStatus Project::take_exact(std::vector<Scene::ExactResult> results) {
  pending_.reset();
  times_ = {};
  std::vector<fs::path> swapped;
  bool failed = false;
  for (Scene::ExactResult& result : results) {
    const auto scene = scenes_.find(result.path);
    if (scene == scenes_.end()) continue;
    const ReloadStatus status = scene->second->take_exact(std::move(result));
    times_ += scene->second->times();
    if (status == ReloadStatus::Swapped) swapped.push_back(scene->first);
    failed = failed || status == ReloadStatus::Failed;
  }
  // A project swaps all its passes or none: a failed one keeps every tweak.
  if (failed)
    for (const fs::path& file : swapped) scenes_.at(file)->discard();
  if (failed || !swapped.empty()) diagnostics_ = latest_diagnostics();
  if (failed) return ReloadStatus::Failed;
  if (swapped.empty()) return ReloadStatus::Unchanged;
  pending_ = PendingSwap{shown_.reached, shown_.cube_size, shown_.buffer_size, std::move(swapped)};
  return ReloadStatus::Swapped;
}

std::vector<Scene::TwinJob> Project::twin_jobs() {
  std::vector<Scene::TwinJob> jobs;
  for (const Pass& pass : passes_)
    if (std::optional<Scene::TwinJob> job = pass.scene->twin_job()) jobs.push_back(std::move(*job));
  return jobs;
}

std::vector<Scene::TwinResult> Project::build_twins(const std::vector<Scene::TwinJob>& jobs, const OnBuilt& on_built,
                                                    const Cancelled& cancelled) {
  std::vector<Scene::TwinResult> results;
  for (const Scene::TwinJob& job : jobs) results.push_back(Scene::build_twin(job, on_built, cancelled));
  return results;
}

bool Project::take_twins(std::vector<Scene::TwinResult> results) {
  bool any = false;
  for (Scene::TwinResult& result : results)
    if (const auto scene = scenes_.find(result.path); scene != scenes_.end())
      any = scene->second->take_twin(std::move(result)) || any;
  return any;
}

void Project::commit() {
  if (!pending_) return;
  const PendingSwap swap = std::move(*pending_);
  pending_.reset();
  shown_ = swap;
  const std::vector<fs::path>& reached = swap.reached;
  const std::map<fs::path, int>& cube_size = swap.cube_size;
  for (const fs::path& file : reached) scene_for(file).commit();
  for (auto it = scenes_.begin(); it != scenes_.end();)
    it = std::find(reached.begin(), reached.end(), it->first) == reached.end() ? scenes_.erase(it) : std::next(it);
  passes_.clear();
  for (const fs::path& file : draw_order(reached, cube_size)) {
    Pass pass;
    pass.file = file;
    pass.scene = scenes_.at(file).get();
    pass.is_image = file == image_path_;
    if (auto cube = cube_size.find(file); cube != cube_size.end()) {
      pass.cube = true;
      pass.cube_size = cube->second > 0 ? cube->second : ChannelSpec::kDefaultCubeSize;
    }
    if (auto size = swap.buffer_size.find(file); size != swap.buffer_size.end()) pass.size = size->second;
    pass.channels = channels_of(file, pass.scene->source());
    passes_.push_back(std::move(pass));
  }
  rebuilt_ = swap.rebuilt;
  ++generation_;
}

std::array<ChannelSpec, 4> Project::channels_of(const fs::path& file, const Source& source) const {
  std::array<ChannelSpec, 4> channels = source.channels;
  for (size_t c = 0; c < 4; ++c) {
    ChannelSpec& spec = channels[c];
    if (spec.kind == ChannelSpec::Kind::Self) {
      spec.kind = ChannelSpec::Kind::Pass;
      spec.path = file;
    }
    // A --channelN file takes the place of what the image pass names, read
    // as the same shape (a cube map stays a cube map: the shader samples one),
    // but not of a glslViewer buffer, which the code reads by its own name:
    // it took a channel the code does not read as u_texN.
    if (file == image_path_ && !channel_overrides_[c].empty() && spec.sampler_name.empty()) {
      const ChannelSpec::Shape shape = spec.kind == ChannelSpec::Kind::Keyboard ? ChannelSpec::Shape::Flat : spec.shape;
      spec = ChannelSpec{};
      spec.kind = ChannelSpec::Kind::Image;
      spec.shape = shape;
      spec.path = channel_overrides_[c];
      spec.sampler = default_sampler(ChannelSpec::Kind::Image, shape);
    }
  }
  return channels;
}

std::vector<ChannelSpec> Project::images_read() const {
  std::vector<ChannelSpec> out;
  auto add = [&](const std::array<ChannelSpec, 4>& channels) {
    for (const ChannelSpec& spec : channels)
      if (spec.kind == ChannelSpec::Kind::Image) out.push_back(spec);
  };
  if (pending_)
    for (const fs::path& file : pending_->reached) add(channels_of(file, scenes_.at(file)->latest_source()));
  else
    for (const Pass& pass : passes_) add(pass.channels);
  return out;
}

std::vector<fs::path> Project::watch_list() const {
  std::vector<fs::path> out;
  auto add = [&](fs::path watched) {
    // A pass served from a .json is watched as the .json.
    if (is_shadertoy_json(watched.parent_path())) watched = watched.parent_path();
    if (std::find(out.begin(), out.end(), watched) == out.end()) out.push_back(watched);
  };
  for (const auto& [file, scene] : scenes_)
    for (const fs::path& watched : scene->watch_list()) add(watched);
  // The --channelN files, which no pass's text names, and a cube map's faces.
  for (const fs::path& given : channel_overrides_) {
    if (given.empty()) continue;
    const fs::path image = fs::absolute(given).lexically_normal();
    add(image);
    for (const fs::path& face : cube_face_files(image, exists_on_disk)) add(face);
  }
  return out;
}

bool Project::reads_current(const std::vector<Pass>& passes, size_t reader, const fs::path& buffer) {
  for (size_t i = 0; i < reader && i < passes.size(); ++i)
    if (passes[i].file == buffer) return true;
  return false;
}

bool Project::has_feedback() const {
  for (size_t i = 0; i < passes_.size(); ++i)
    for (const ChannelSpec& c : passes_[i].channels)
      if (c.kind == ChannelSpec::Kind::Pass && !reads_current(passes_, i, c.path)) return true;
  return false;
}

bool Project::reads_keyboard() const {
  for (const Pass& pass : passes_)
    for (const ChannelSpec& c : pass.channels)
      if (c.kind == ChannelSpec::Kind::Keyboard) return true;
  return false;
}

UserUniforms Project::user_uniforms() const {
  UserUniforms all;
  for (const Pass& pass : passes_)
    merge_user_uniforms(&all, find_user_uniforms(pass.scene->source(), &pass.scene->active_code()));
  return all;
}

InputUse Project::inputs_read() const {
  InputUse use;
  for (const Pass& pass : passes_) {
    const InputUse one = rm::inputs_read(*pass.scene->program());
    use.time = use.time || one.time;
    use.drag = use.drag || one.drag;
    use.pointer = use.pointer || one.pointer;
  }
  use.time = use.time || has_feedback();
  return use;
}

}  // namespace rm
