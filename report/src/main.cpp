// contact-report: measures what the scenes ask for and writes the report.
//
//   contact-report --out DIR                      every scene of the default set (scenes/*.toml)
//   contact-report --scene FILE [--scene FILE] --out DIR
//   contact-report --check [--scene FILE]         parse and check scenes only
//
// Exit status: 0 done; 1 a scene file is bad (message "FILE:LINE: reason" on
// stderr); 2 bad options; 3 the report was written but gnuplot failed.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "candidates.hpp"
#include "contact/batch.hpp"
#include "contact/harness/candidate.hpp"
#include "measure.hpp"
#include "output.hpp"
#include "scene.hpp"

namespace fs = std::filesystem;

namespace {

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) return line.substr(line.find_first_not_of(' ', colon + 1));
    }
  return "unknown";
}

std::string now_utc() {
  const std::time_t t = std::time(nullptr);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return buffer;
}

// The default scene set: scenes/ of the source tree, or ../scenes, ../../scenes
// or ../share/contact/scenes beside the executable.
std::string default_scenes_dir(const char* argv0) {
  if (fs::is_directory(CONTACT_SCENES_DIR)) return CONTACT_SCENES_DIR;
  std::error_code error;
  const fs::path exe = fs::canonical("/proc/self/exe", error);
  const fs::path base = error ? fs::path(argv0).parent_path() : exe.parent_path();
  for (const char* relative : {"../scenes", "../../scenes", "../share/contact/scenes"})
    if (fs::is_directory(base / relative)) return (base / relative).lexically_normal().string();
  return CONTACT_SCENES_DIR;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"contact-report: precision and speed report of the closed-form contact step (A.2)"};
  std::vector<std::string> scene_files;
  std::string out_dir, scenes_dir;
  bool raw = false, check_only = false;
  std::vector<std::string> candidate_specs;
  app.add_option("--scene", scene_files, "scene file (TOML); repeatable; default: every *.toml of --scenes-dir");
  app.add_option("--scenes-dir", scenes_dir, "directory of the default scene set")->check(CLI::ExistingDirectory);
  app.add_option("--out", out_dir, "directory to write report.md, results.csv, results.json and plots/ into");
  app.add_flag("--raw", raw, "also write every sample's measurement into DIR/raw/");
  app.add_flag("--check", check_only, "only parse and check the scene files");
  app.add_option("--candidate", candidate_specs,
                 "NAME=SPEC: also measure an outside implementation in double (SPEC as contact-check's: "
                 "lib:PATH[:SYMBOL] or cmd:COMMAND); repeatable");
  try {
    app.parse(argc, argv);
    if (!check_only && out_dir.empty()) throw CLI::RequiredError("--out");
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  try {
    for (const auto& spec : candidate_specs) report::add_candidate(spec);
  } catch (const contact::harness::candidate_error& e) {
    std::fprintf(stderr, "contact-report: --candidate %s\n", e.what());
    return 2;
  }

  if (scene_files.empty()) {
    if (scenes_dir.empty()) scenes_dir = default_scenes_dir(argv[0]);
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(scenes_dir, error))
      if (entry.is_regular_file() && entry.path().extension() == ".toml") scene_files.push_back(entry.path().string());
    std::sort(scene_files.begin(), scene_files.end());
    if (scene_files.empty()) {
      std::fprintf(stderr, "contact-report: no scene files (*.toml) in %s\n", scenes_dir.c_str());
      return 2;
    }
  }

  std::vector<report::scene> scenes;
  bool bad = false;
  for (const auto& file : scene_files) {
    try {
      scenes.push_back(report::parse_scene(file));
    } catch (const report::scene_error& e) {
      std::fprintf(stderr, "%s\n", e.what());
      bad = true;
    }
  }
  for (std::size_t i = 0; i < scenes.size(); ++i)
    for (std::size_t k = 0; k < i; ++k)
      if (scenes[i].name == scenes[k].name) {
        std::fprintf(stderr, "%s:1: scene name '%s' is already used by %s\n", scenes[i].file.c_str(),
                     scenes[i].name.c_str(), scenes[k].file.c_str());
        bad = true;
      }
  const report::scene* reference = nullptr;
  for (const auto& s : scenes) {
    if (!s.batch_reference) continue;
    if (reference) {
      std::fprintf(stderr, "%s:%ld: batch_reference is already set by scene '%s' (%s): at most one scene sets it\n",
                   s.file.c_str(), s.batch_reference_line, reference->name.c_str(), reference->file.c_str());
      bad = true;
    } else {
      reference = &s;
    }
  }
  const report::scene* headline = nullptr;
  for (const auto& s : scenes) {
    if (!report::asks_for(s, report::plot::headline)) continue;
    if (headline) {
      std::fprintf(stderr, "%s:%ld: plots: the headline figure is already asked for by scene '%s' (%s): at most one scene asks for it\n",
                   s.file.c_str(), s.plots_line, headline->name.c_str(), headline->file.c_str());
      bad = true;
    } else {
      headline = &s;
    }
  }
  if (bad) return 1;
  if (check_only) {
    for (const auto& s : scenes) std::printf("%s: scene %s is well-formed\n", s.file.c_str(), s.name.c_str());
    return 0;
  }

  report::run_info info;
  for (int i = 0; i < argc; ++i) info.command += (i ? " " : "") + std::string(argv[i]);
  info.started = now_utc();
  info.cpu = cpu_model();
  info.compiler = CONTACT_COMPILER;
  info.flags = CONTACT_REPORT_FLAGS;
  for (const contact::batch_target& t : contact::batch_targets()) info.batch_targets.emplace_back(t.name, t.supported);
  info.batch_chosen = contact::chosen_batch_target().name;
  const auto start = std::chrono::steady_clock::now();
  std::vector<report::scene_result> results;
  report::measure_options options;
  options.raw = raw;
  for (const auto& s : scenes) results.push_back(report::measure(s, options));
  report::measure_batch_across_scenes(results);
  info.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const bool plotted = report::write_report(out_dir, results, info, raw) && report::write_candidate_maps(out_dir, scenes);
  std::fprintf(stderr, "contact-report: wrote %s/report.md, results.csv, results.json%s in %.1f s\n", out_dir.c_str(),
               plotted ? " and plots/" : "", info.seconds);
  return plotted ? 0 : 3;
}
